// The exact boundary distance the radii come from, against OpenCASCADE's BRepExtrema, and the
// radii and welded vertices of the output against the B-rep.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <BRepPrimAPI_MakeBox.hxx>
#include <Bnd_Box.hxx>
#include <BRepBndLib.hxx>

#include "core/exact/boundary_distance.h"
#include "core/features/solid_euler.h"
#include "core/medial/weld_vertices.h"
#include "support/engine_run.h"
#include "support/hard_solids.h"
#include "support/mesh_measures.h"
#include "support/shape_measures.h"
#include "support/solids.h"

namespace cadmedial::test {
namespace {

std::array<double, 6> box_of(const TopoDS_Shape& s) {
  Bnd_Box b;
  BRepBndLib::Add(s, b, false);
  std::array<double, 6> out;
  b.Get(out[0], out[1], out[2], out[3], out[4], out[5]);
  return out;
}

// Random points in the box around the solid (inside and outside): the exact distance must be
// BRepExtrema's wherever a bound above it is given.
void expect_distances_agree(const TopoDS_Solid& solid, const char* name) {
  cadmedial::BoundaryDistance exact(solid);
  const test::BoundaryDistance reference(solid);
  const auto b = box_of(solid);
  const double diag = shape_bbox_diagonal(solid);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    const Point3 p{b[0] + (b[3] - b[0]) * u(rng), b[1] + (b[4] - b[1]) * u(rng), b[2] + (b[5] - b[2]) * u(rng)};
    const double want = reference.distance({p[0], p[1], p[2]});
    const auto got = exact.nearest(p, 2 * diag);
    EXPECT_NEAR(got.distance, want, 1e-7 * diag) << name << " at " << p[0] << " " << p[1] << " " << p[2];
    // The nearest point is on the boundary, at that distance.
    EXPECT_NEAR(reference.distance({got.point[0], got.point[1], got.point[2]}), 0.0, 1e-7 * diag) << name;
  }
}

TEST(ExactBoundaryDistance, AgreesWithBRepExtremaOnPlanesCylindersAndFillets) {
  expect_distances_agree(make_filleted_box(10, 8, 6, 1.5), "filleted box");
  expect_distances_agree(make_block_with_filleted_hole(20, 14, 6, 3, 1), "block with filleted hole");
}

TEST(ExactBoundaryDistance, AgreesWithBRepExtremaOnABSplineFace) {
  expect_distances_agree(make_box_with_bspline_top(10, 8, 4, 1.5), "box with B-spline top");
}

TEST(ExactBoundaryDistance, TellsInsideFromOutsideAtAFace) {
  const TopoDS_Solid box = make_box(10, 8, 6);
  cadmedial::BoundaryDistance d(box);
  EXPECT_EQ(d.nearest({5, 4, 7}, 100).side, 1);   // above the top face
  EXPECT_EQ(d.nearest({5, 4, 5}, 100).side, -1);  // under it
  EXPECT_NEAR(d.nearest({5, 4, 5}, 100).distance, 1.0, 1e-12);
  // No face or edge within the bound: the bound comes back.
  EXPECT_DOUBLE_EQ(d.nearest({5, 4, 3}, 0.5).distance, 0.5);
}

// Every output radius is the vertex's distance to the B-rep: no ball sticks out, on solids where
// the distance to the samples overstated it most (thin walls, wedges, fillets).
void expect_exact_radii(const std::string& key, const TopoDS_Solid& solid, double spacing) {
  const ComputeResult& r = medial_axis_of(key, [solid] { return TopoDS_Shape(solid); }, spacing);
  const test::BoundaryDistance reference(solid);
  const double diag = shape_bbox_diagonal(solid);
  ASSERT_GT(r.mesh.num_vertices(), 0u);
  double worst = 0;
  const std::size_t step = std::max<std::size_t>(1, r.mesh.num_vertices() / 400);
  for (std::size_t v = 0; v < r.mesh.num_vertices(); v += step) {
    const Point3& p = r.mesh.vertices[v];
    const double D = reference.distance({p[0], p[1], p[2]});
    worst = std::max(worst, std::abs(r.mesh.radius[v] - D));
  }
  EXPECT_LE(worst, 1e-6 * diag) << key << ": |radius - distance to the B-rep| up to " << worst;
  // The stats say how far the samples' distance was off.
  ASSERT_EQ(r.stats.solids.size(), 1u);
  EXPECT_GT(r.stats.solids[0].radius_max_excess, 0.0) << key;
  EXPECT_LE(r.stats.solids[0].radius_max_excess, 2 * spacing) << key;
}

TEST(ExactRadii, EveryRadiusIsTheDistanceToTheBRepOnAThinRibAndAWedge) {
  expect_exact_radii("exact-rib", make_block_with_rib(20, 10, 4, 0.6, 3), 0.5);
  expect_exact_radii("exact-wedge", make_sharp_wedge(25, 10, 4), 0.3);
}

TEST(ExactRadii, EveryRadiusIsTheDistanceToTheBRepOnFilletsAndBSplines) {
  expect_exact_radii("exact-fillets", make_filleted_box(10, 8, 6, 1.5), 0.4);
  expect_exact_radii("exact-bspline", make_box_with_bspline_top(10, 8, 4, 1.5), 0.4);
}

// A plate's sheet lies at its mid-plane with radius half its thickness, exactly.
TEST(ExactRadii, APlatesSheetHasRadiusHalfItsThickness) {
  const double t = 0.8;
  const ComputeResult& r = medial_axis_of("exact-plate", [t] { return TopoDS_Shape(make_box(20, 12, t)); }, 0.5);
  std::size_t on_sheet = 0;
  for (std::size_t v = 0; v < r.mesh.num_vertices(); ++v) {
    const Point3& p = r.mesh.vertices[v];
    // Away from the rim (one thickness), the axis is the mid-plane sheet.
    if (p[0] < 2 * t || p[0] > 20 - 2 * t || p[1] < 2 * t || p[1] > 12 - 2 * t) continue;
    ++on_sheet;
    EXPECT_NEAR(p[2], t / 2, 1e-6) << "vertex " << v;
    EXPECT_NEAR(r.mesh.radius[v], t / 2, 1e-9) << "vertex " << v;
  }
  EXPECT_GT(on_sheet, 50u);
}

// Sides shorter than 1e-9 of the diagonal are collapsed before the topology is counted (the
// clusters of a degenerate Voronoi vertex), and the topology holds on what is left.
TEST(WeldedVertices, FiveTouchingCubesKeepTheirTopologyAndHaveNoSideShorterThanTheWeld) {
  const ComputeResult& r = medial_axis_of("five-cubes", [] {
    std::vector<TopoDS_Solid> cubes;
    for (int i = 0; i < 5; ++i) cubes.push_back(BRepPrimAPI_MakeBox(gp_Pnt(10.0 * i, 0, 0), 10, 10, 10).Solid());
    return make_compound(cubes);
  }, ComputeParams{});
  const MedialMesh& m = r.mesh;
  // (Welded also where no side joins two vertices, at 1e-12 of the diagonal, the middle cubes
  // still come out with Euler characteristic 3 to 5: copies of one Voronoi vertex, 1e-16 apart,
  // that coincident_cells leaves apart, carry a doubled patch of sheet. Not solved yet.)
  for (int s = 0; s < 5; ++s) {
    EXPECT_EQ(r.stats.solids[s].euler_characteristic, 1) << "cube " << s;
    EXPECT_EQ(r.stats.solids[s].components, 1u) << "cube " << s;
  }
  const double weld = 1e-9 * 10.0 * std::sqrt(3.0);  // of each cube's diagonal
  std::size_t short_sides = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < m.face_size(f); ++k) {
      const Point3 &a = m.vertices[m.face(f)[k]], &b = m.vertices[m.face(f)[(k + 1) % m.face_size(f)]];
      short_sides += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) < weld;
    }
  EXPECT_EQ(short_sides, 0u);
}

TEST(WeldVertices, MergesNearDuplicatesAndDropsWhatDegenerates) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1e-12, 0}, {2, 0, 0}, {0, 1, 1e-12}};
  m.radius = {0.5, 0.4, 0.3, 0.2, 0.1, 0.6};
  m.add_face({0, 1, 2}, FaceKind::Voronoi, 0);
  m.add_face({1, 3, 4}, FaceKind::Voronoi, 0);  // a sliver: 1 and 3 are one vertex
  m.add_face({5, 4, 0}, FaceKind::Voronoi, 0);  // 5 is as close to 2, but no side joins them
  m.add_face({3, 4, 2}, FaceKind::Edge, 0);
  m.edges = {{1, 3}};  // becomes a point
  m.edge_solid = {0};
  const WeldStats st = cadmedial::weld_vertices(m, 1e-9);
  EXPECT_EQ(st.merged_vertices, 1u);
  EXPECT_EQ(st.dropped_faces, 1u);
  EXPECT_EQ(st.dropped_edges, 1u);
  ASSERT_EQ(m.num_vertices(), 5u);
  ASSERT_EQ(m.num_faces(), 3u);
  EXPECT_EQ(m.num_edges(), 0u);
  EXPECT_DOUBLE_EQ(m.radius[1], 0.2);  // the smaller radius of the two
  EXPECT_EQ(m.kind[2], FaceKind::Edge);
  EXPECT_EQ(m.face(2)[0], 1);  // 3 became 1
}

// A face whose two ends weld together stays as the segment it became, one that welds into a point
// as that point: the axis keeps its pieces (a sphere's axis, its centre, is such a cluster).
TEST(WeldVertices, AFaceCollapsedToASegmentOrAPointKeepsItsPlace) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1e-12, 0}, {5, 5, 5}, {5, 5, 5 + 1e-12}, {5, 5 + 1e-12, 5}};
  m.radius = {0.5, 0.4, 0.3, 0.2, 0.1, 0.6};
  m.add_face({0, 1, 2}, FaceKind::Voronoi, 0);  // a segment from 0 to 1
  m.add_face({3, 4, 5}, FaceKind::Voronoi, 1);  // a point
  const WeldStats st = cadmedial::weld_vertices(m, 1e-9);
  EXPECT_EQ(st.merged_vertices, 3u);
  EXPECT_EQ(st.dropped_faces, 2u);
  EXPECT_EQ(m.num_faces(), 0u);
  ASSERT_EQ(m.num_vertices(), 3u);
  ASSERT_EQ(m.num_edges(), 1u);
  EXPECT_EQ(m.edge_solid[0], 0);
  const Point3 &a = m.vertices[m.edges[0][0]], &b = m.vertices[m.edges[0][1]];
  EXPECT_NEAR(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]), 1.0, 1e-9);
  const int point = 3 - m.edges[0][0] - m.edges[0][1];  // the vertex the edge does not use
  EXPECT_NEAR(m.vertices[point][0], 5.0, 1e-9);
  EXPECT_DOUBLE_EQ(m.radius[point], 0.1);  // the smallest radius of the three
}

}  // namespace
}  // namespace cadmedial::test
