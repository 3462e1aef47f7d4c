// The test measures count the medial mesh's 1-D edges: hand-built complexes whose V - E + F and
// pieces are known.
#include "support/mesh_measures.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cadmedial::test {
namespace {

MedialMesh mesh_of(const std::vector<Point3>& points, const std::vector<std::vector<int>>& faces,
                   const std::vector<std::array<int, 2>>& edges, int edge_solid = 0) {
  MedialMesh m;
  m.vertices = points;
  m.radius.assign(points.size(), 1.0);
  for (const auto& f : faces) m.add_face(f, FaceKind::Voronoi, 0);
  m.edges = edges;
  m.edge_solid.assign(edges.size(), edge_solid);
  return m;
}

const std::vector<Point3> kTriangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

TEST(MeshMeasures, TriangleWithADanglingEdgeIsOnePieceOfEulerOne) {
  std::vector<Point3> p = kTriangle;
  p.push_back({0, 0, 2});
  const MedialMesh m = mesh_of(p, {{0, 1, 2}}, {{0, 3}});
  EXPECT_EQ(euler_characteristic(m, 3.0), 1);  // 4 - 4 + 1
  EXPECT_EQ(connected_pieces(m, 3.0), 1);
}

TEST(MeshMeasures, AnEdgeJoinsTwoTriangles) {
  const std::vector<Point3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  const MedialMesh apart = mesh_of(p, {{0, 1, 2}, {3, 4, 5}}, {});
  EXPECT_EQ(connected_pieces(apart, 8.0), 2);
  EXPECT_EQ(euler_characteristic(apart, 8.0), 2);
  const MedialMesh joined = mesh_of(p, {{0, 1, 2}, {3, 4, 5}}, {{1, 3}});
  EXPECT_EQ(connected_pieces(joined, 8.0), 1);
  EXPECT_EQ(euler_characteristic(joined, 8.0), 1);  // 6 - 7 + 2
}

TEST(MeshMeasures, SquareLoopOfEdgesIsACircle) {
  const MedialMesh m = mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
  EXPECT_EQ(euler_characteristic(m, 2.0), 0);  // 4 - 4
  EXPECT_EQ(connected_pieces(m, 2.0), 1);      // its vertices are not isolated points
  EXPECT_EQ(connected_pieces(m, 2.0, 0), 1);   // and the loop belongs to solid 0
}

TEST(MeshMeasures, AnEdgeThatIsAFaceSideCountsOnce) {
  const MedialMesh m = mesh_of(kTriangle, {{0, 1, 2}}, {{1, 0}});
  EXPECT_EQ(euler_characteristic(m, 2.0), 1);  // 3 - 3 + 1
}

TEST(MeshMeasures, EdgeEndsAreWeldedToCoincidentFaceVertices) {
  // The edge's first end duplicates vertex 1 of the triangle: the edge hangs off the triangle.
  std::vector<Point3> p = kTriangle;
  p.push_back({1, 0, 0});
  p.push_back({2, 0, 0});
  const MedialMesh m = mesh_of(p, {{0, 1, 2}}, {{3, 4}});
  EXPECT_EQ(connected_pieces(m, 3.0), 1);
  EXPECT_EQ(euler_characteristic(m, 3.0), 1);  // 4 welded - 4 + 1
}

TEST(MeshMeasures, EdgesOfAnotherSolidAreLeftOut) {
  std::vector<Point3> p = kTriangle;
  p.push_back({0, 0, 2});
  MedialMesh m = mesh_of(p, {{0, 1, 2}}, {{0, 3}}, /*edge_solid=*/1);
  EXPECT_EQ(euler_characteristic(m, 3.0, 0), 1);  // the triangle alone
  EXPECT_EQ(connected_pieces(m, 3.0, 0), 1);
  EXPECT_EQ(euler_characteristic(m, 3.0, 1), 1);  // the edge alone: 2 - 1
  EXPECT_EQ(connected_pieces(m, 3.0, 1), 1);
  const MeshDistance triangle_only(m, 3.0, 0);
  EXPECT_NEAR(triangle_only.distance({0, 0, 2}), 2.0, 1e-12);
}

TEST(MeshMeasures, DistanceReachesTheInsideOfAnEdge) {
  // From (1, 1, 0) the segment's middle is at 1, its ends at sqrt(2).
  const MedialMesh m = mesh_of({{0, 0, 0}, {2, 0, 0}}, {}, {{0, 1}});
  const MeshDistance dist(m, 3.0);
  EXPECT_NEAR(dist.distance({1, 1, 0}), 1.0, 1e-12);
  EXPECT_EQ(dist.num_triangles(), 0u);
}

TEST(MeshMeasures, DistanceToAFaceAndAnEdgeIsTheNearer) {
  std::vector<Point3> p = kTriangle;
  p.push_back({0, 0, 4});
  const MedialMesh m = mesh_of(p, {{0, 1, 2}}, {{0, 3}});
  const MeshDistance dist(m, 5.0);
  EXPECT_NEAR(dist.distance({0.5, 0, 3}), 0.5, 1e-12);    // the edge, not the triangle 3 below
  EXPECT_NEAR(dist.distance({0.2, 0.2, -1}), 1.0, 1e-12);  // the triangle
}

}  // namespace
}  // namespace cadmedial::test
