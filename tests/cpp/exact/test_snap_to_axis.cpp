// snap_to_axis: the Voronoi vertices moved onto the exact medial axis, with exact radii. Judged
// against the exact axis of convex polytopes (polytope_medial_axis.h) and a cylinder's.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/exact/snap_to_axis.h"
#include "support/convex_polytope.h"
#include "support/engine_run.h"
#include "support/polytope_medial_axis.h"
#include "support/random.h"
#include "support/solids.h"

namespace cadmedial::test {
namespace {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

void expect_snapped_onto_the_axis(const ConvexPolytope& poly, const TopoDS_Solid& solid, const std::string& key,
                                  double spacing) {
  const ComputeResult& r = medial_axis_of(key, [&] { return solid; }, spacing);
  const PolytopeMedialAxis exact(poly);
  const double diag = poly.bbox_diagonal();
  MedialMesh mesh = r.mesh;
  const SnapStats st = snap_to_axis(solid, 0, diag, 0.5 * spacing, mesh);
  EXPECT_GE(st.snapped, st.vertices * 8 / 10) << key;
  EXPECT_LE(st.max_move, 0.5 * spacing);
  std::vector<double> before, after;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    before.push_back(exact.distance(r.mesh.vertices[v]));
    after.push_back(exact.distance(mesh.vertices[v]));
    // Whether moved or not, the radius is the distance to the boundary.
    EXPECT_NEAR(mesh.radius[v], poly.boundary_distance(mesh.vertices[v]), 1e-7 * diag) << key << " vertex " << v;
  }
  // The vertices that moved are on the axis; those that stayed (near edges) as before.
  EXPECT_LE(quantile(after, 0.9), 1e-7 * diag) << key << ": before, p90 " << quantile(before, 0.9);
  EXPECT_LE(quantile(after, 0.99), quantile(before, 0.99)) << key;
  EXPECT_GT(quantile(before, 0.9), 1e-4 * diag) << key << ": the Voronoi vertices were already on it";
}

TEST(SnapToAxis, BoxVerticesLandOnTheExactAxis) {
  expect_snapped_onto_the_axis(box_polytope(40, 25, 15), make_box(40, 25, 15), "box40", 1.0);
}

TEST(SnapToAxis, RandomPolytopesVerticesLandOnTheExactAxis) {
  for (std::uint32_t seed : {3u, 8u}) {
    const ConvexPolytope poly = random_polytope(seed, 10, 5.0, 50.0, 0.5);
    expect_snapped_onto_the_axis(poly, make_polytope_solid(poly), "snap_poly" + std::to_string(seed),
                                 poly.bbox_diagonal() / 60);
  }
}

TEST(SnapToAxis, CylinderVerticesLandOnItsAxisOrCones) {
  // R 5, H 40: its axis is the z axis between z = 5 and 35 and two cones to the rims. A vertex
  // with radius rho at distance s from the z axis and h from the nearer end lies on the axis
  // when rho = 5 - s = h, the two touching at once (or on the segment: s = 0, rho = 5).
  const TopoDS_Solid cyl = make_cylinder(5, 40);
  const ComputeResult& r = medial_axis_of("cyl5", [&] { return cyl; }, 0.5);
  MedialMesh mesh = r.mesh;
  const SnapStats st = snap_to_axis(cyl, 0, std::sqrt(10.0 * 10 + 10 * 10 + 40 * 40), 0.25, mesh);
  EXPECT_GE(st.snapped, st.vertices / 2);
  std::vector<double> off_before, off_after;
  const auto off = [](const Point3& p) {
    const double s = std::hypot(p[0], p[1]), h = std::min(p[2], 40 - p[2]);
    return std::abs((5 - s) - h) / std::sqrt(2.0);  // distance to the cone 5 - s = h
  };
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const double h = std::min(mesh.vertices[v][2], 40 - mesh.vertices[v][2]);
    if (h > 4.5 || h < 0.5) continue;  // the cones' vertices only (the z axis is at h >= 5)
    off_before.push_back(off(r.mesh.vertices[v]));
    off_after.push_back(off(mesh.vertices[v]));
  }
  ASSERT_GT(off_after.size(), 100u);
  EXPECT_LE(quantile(off_after, 0.9), 1e-6);
  EXPECT_GT(quantile(off_before, 0.9), 1e-3);
}

}  // namespace
}  // namespace cadmedial::test
