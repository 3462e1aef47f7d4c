// Checks of the test references themselves (no engine): the exact medial axes, the solids built
// from them, and the mesh measures. A reference that is wrong would make every engine test moot.
#include <cmath>

#include <gtest/gtest.h>

#include "support/convex_polytope.h"
#include "support/mesh_measures.h"
#include "support/polytope_medial_axis.h"
#include "support/random.h"
#include "support/revolved_medial_axis.h"
#include "support/shape_measures.h"
#include "support/solids.h"

namespace cadmedial::test {
namespace {

TEST(PolytopeReference, BoxAxisDistanceMatchesHandDerivation) {
  const ConvexPolytope box = box_polytope(10, 8, 6);
  const PolytopeMedialAxis axis(box);
  // The centre ties the two z planes (3 = 3 < 4 < 5).
  EXPECT_NEAR(axis.distance({5, 4, 3}), 0.0, 1e-12);
  // Below the centre: the nearest sheet is the z = 3 mid sheet (1.5 away); the sheet z = y of the
  // bottom and front planes is |y - z| / sqrt 2 = 2.5 / sqrt 2 = 1.77 away.
  EXPECT_NEAR(axis.distance({5, 4, 1.5}), 1.5, 1e-12);
  // A corner and a point on an edge are on the axis's closure.
  EXPECT_NEAR(axis.distance({0, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(axis.distance({10, 3, 6}), 0.0, 1e-12);
  // Near the bottom face's centre the sheet z = y of the bottom and front planes is nearer than the
  // mid sheet (2.9): |y - z| / sqrt 2 = 3.9 / sqrt 2, foot (5, 2.05, 2.05) where 2.05 < 3.95, 5, 5.95.
  EXPECT_NEAR(axis.distance({5, 4, 0.1}), 3.9 / std::sqrt(2.0), 1e-12);
}

TEST(PolytopeReference, ProjectedPointsAreOnTheAxis) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const ConvexPolytope poly = random_polytope(seed, 10, 5.0, 50.0, 0.5);
    const PolytopeMedialAxis axis(poly);
    const double eps = 1e-9 * poly.bbox_diagonal();
    for (const Vec3& m : axis.sample(300, seed)) {
      ASSERT_LE(axis.gap(m), eps) << "seed " << seed;
      ASSERT_LE(axis.distance(m), eps) << "seed " << seed;
    }
  }
}

TEST(PolytopeReference, DistanceIsWithinTheGapBounds) {
  // gap / 2 <= distance <= t* <= gap / (1 - max n_i.n_j), for interior points.
  const ConvexPolytope poly = random_polytope(7, 9, 5.0, 50.0, 0.5);
  const PolytopeMedialAxis axis(poly);
  const double c = poly.max_normal_cosine(), eps = 1e-9 * poly.bbox_diagonal();
  Random rng(11);
  const Vec3 lo = poly.bbox_min(), hi = poly.bbox_max();
  int tested = 0;
  while (tested < 500) {
    const Vec3 x{rng.uniform(lo[0], hi[0]), rng.uniform(lo[1], hi[1]), rng.uniform(lo[2], hi[2])};
    if (poly.boundary_distance(x) <= 0) continue;
    ++tested;
    double t = 0;
    axis.project(x, &t);
    const double d = axis.distance(x), g = axis.gap(x);
    ASSERT_GE(d, g / 2 - eps);
    ASSERT_LE(d, t + eps);
    ASSERT_LE(t, g / (1 - c) + eps);
  }
}

TEST(PolytopeReference, OpenCascadeSolidMatchesThePlanes) {
  // The solid built from the facets classifies points as the planes do (away from the boundary).
  const std::vector<ConvexPolytope> polys{box_polytope(10, 8, 6),
                                          prism_polytope({{0, 0}, {6, 0}, {2, 5}}, 4),
                                          random_polytope(1, 10, 5.0, 50.0, 0.5)};
  for (const auto& poly : polys) {
    const SolidClassifier inside(make_polytope_solid(poly));
    Random rng(5);
    const Vec3 lo = poly.bbox_min() - Vec3{1, 1, 1}, hi = poly.bbox_max() + Vec3{1, 1, 1};
    for (int k = 0; k < 300; ++k) {
      const Vec3 x{rng.uniform(lo[0], hi[0]), rng.uniform(lo[1], hi[1]), rng.uniform(lo[2], hi[2])};
      const double d = poly.boundary_distance(x);
      if (std::abs(d) < 1e-3) continue;
      ASSERT_EQ(inside.inside_or_on(x, 1e-7), d > 0) << x[0] << " " << x[1] << " " << x[2];
    }
  }
}

TEST(RevolvedReference, SampledPointsTieTwoBoundaryDistances) {
  // On the cylinder's axis two of (R - rho, z, H - z) tie, or rho = 0 (the wall's nearest points form
  // a circle).
  for (double H : {8.0, 2.0}) {
    const double R = H > 4 ? 2.0 : 5.0;
    for (const Vec3& m : RevolvedMedialAxis::cylinder(R, H).sample(500, 3)) {
      const double rho = std::hypot(m[0], m[1]);
      double d[3] = {R - rho, m[2], H - m[2]};
      std::sort(d, d + 3);
      ASSERT_TRUE(d[1] - d[0] < 1e-12 || (rho < 1e-12 && d[0] == R - rho)) << rho << " " << m[2];
      ASSERT_GE(d[0], -1e-12);
    }
  }
}

TEST(RevolvedReference, CylinderAxisDistanceMatchesHandDerivation) {
  const RevolvedMedialAxis axis = RevolvedMedialAxis::cylinder(2, 8);
  EXPECT_NEAR(axis.distance({1, 0, 4}), 1.0, 1e-12);          // to the axis segment
  EXPECT_NEAR(axis.distance({0, 1.5, 0.2}), 0.3 / std::sqrt(2.0), 1e-12);  // to the bottom cone
  EXPECT_NEAR(axis.distance({0, 0, 1}), 1 / std::sqrt(2.0), 1e-12);  // to the cone rho + z = 2
  const RevolvedMedialAxis disc = RevolvedMedialAxis::cylinder(5, 2);
  EXPECT_NEAR(disc.distance({2, 0, 0.5}), 0.5, 1e-12);        // to the mid disc
  EXPECT_NEAR(RevolvedMedialAxis::torus(5, 1.5).distance({0, 4, 1}), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(RevolvedMedialAxis::sphere(3).distance({1, 2, 2}), 3.0, 1e-12);
}

TEST(RevolvedReference, OpenCascadeSolidsMatchTheAnalyticBoundaryDistance) {
  struct Case {
    TopoDS_Solid solid;
    RevolvedMedialAxis axis;
  };
  const std::vector<Case> cases{{make_cylinder(2, 8), RevolvedMedialAxis::cylinder(2, 8)},
                                {make_cylinder(5, 2), RevolvedMedialAxis::cylinder(5, 2)},
                                {make_sphere(3), RevolvedMedialAxis::sphere(3)},
                                {make_torus(5, 1.5), RevolvedMedialAxis::torus(5, 1.5)}};
  Random rng(9);
  for (const auto& c : cases) {
    const SolidClassifier inside(c.solid);
    const BoundaryDistance boundary(c.solid);
    for (int k = 0; k < 60; ++k) {
      const Vec3 x{rng.uniform(-7, 7), rng.uniform(-7, 7), rng.uniform(-4, 9)};
      const double d = c.axis.boundary_distance(x);
      if (std::abs(d) < 1e-3) continue;
      ASSERT_EQ(inside.inside_or_on(x, 1e-7), d > 0);
      if (d > 0) ASSERT_NEAR(boundary.distance(x), d, 1e-6);
    }
  }
}

MedialMesh mesh_of(const std::vector<Point3>& vertices, const std::vector<std::vector<int>>& faces) {
  MedialMesh m;
  m.vertices = vertices;
  m.radius.assign(vertices.size(), 0.0);
  for (const auto& f : faces) {
    m.face_vertices.insert(m.face_vertices.end(), f.begin(), f.end());
    m.face_start.push_back(static_cast<int>(m.face_vertices.size()));
    m.kind.push_back(FaceKind::Voronoi);
    m.solid.push_back(0);
  }
  return m;
}

TEST(MeshMeasures, EulerCharacteristicOfKnownComplexes) {
  // A closed tetrahedron surface: 4 - 6 + 4 = 2.
  const MedialMesh tet = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                 {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}});
  EXPECT_EQ(euler_characteristic(tet, 1.0), 2);
  // A square annulus of 4 quads: 8 - 12 + 4 = 0, one piece.
  const MedialMesh ring = mesh_of({{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0},
                                   {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}},
                                  {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
  EXPECT_EQ(euler_characteristic(ring, 3.0), 0);
  EXPECT_EQ(connected_pieces(ring, 3.0), 1);
}

TEST(MeshMeasures, CoincidentVerticesAreWelded) {
  // Two triangles that share an edge only through duplicated vertices: one piece, chi = 1.
  const MedialMesh m = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}},
                               {{0, 1, 2}, {3, 5, 4}});
  EXPECT_EQ(connected_pieces(m, 1.5), 1);
  EXPECT_EQ(euler_characteristic(m, 1.5), 1);
  const MedialMesh apart = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}},
                                   {{0, 1, 2}, {3, 4, 5}});
  EXPECT_EQ(connected_pieces(apart, 6.0), 2);
}

TEST(MeshMeasures, DistanceToTriangles) {
  const MedialMesh m = mesh_of({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, {{0, 1, 2, 3}});
  const MeshDistance dist(m, 3.0);
  EXPECT_NEAR(dist.distance({1, 1, 0.5}), 0.5, 1e-12);
  EXPECT_NEAR(dist.distance({3, 1, 0}), 1.0, 1e-12);
  EXPECT_EQ(dist.num_triangles(), 2u);
}

}  // namespace
}  // namespace cadmedial::test

namespace cadmedial::test {
namespace {

TEST(ShapeReference, SolidEulerCharacteristicFromTheBrep) {
  EXPECT_EQ(solid_euler_characteristic(make_box(10, 8, 6)), 1);
  EXPECT_EQ(solid_euler_characteristic(make_sphere(3)), 1);
  EXPECT_EQ(solid_euler_characteristic(make_cylinder(2, 8)), 1);
  EXPECT_EQ(solid_euler_characteristic(make_torus(5, 1.5)), 0);
  EXPECT_EQ(solid_euler_characteristic(make_block_with_hole(10, 10, 4, 2)), 0);
  EXPECT_EQ(solid_euler_characteristic(make_l_block(8, 3, 3)), 1);
  EXPECT_EQ(solid_euler_characteristic(make_pocket_block(8, 4, 3, 5, 2)), 1);
  EXPECT_EQ(solid_euler_characteristic(make_filleted_box(8, 6, 4, 1.5)), 1);
}

}  // namespace
}  // namespace cadmedial::test
