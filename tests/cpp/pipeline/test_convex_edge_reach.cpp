// convex_edge_reach on hand-made samples: two convex edges of a right-angled wedge, one with axis
// vertices beside every sample, one with vertices beside its first half only.
#include <gtest/gtest.h>

#include "core/pipeline/convex_edge_reach.h"

namespace cadmedial {
namespace {

// Samples along x on two edges (0 at y = z = 0, 1 at y = 10), faces turning by 90 degrees.
Samples two_edges(int per_edge) {
  Samples s;
  for (int e = 0; e < 2; ++e)
    for (int k = 0; k < per_edge; ++k) {
      s.points.push_back({static_cast<double>(k), 10.0 * e, 0.0});
      s.tag.push_back(SampleTag{});
      s.normal.push_back({0, 0, 1});
      s.normal2.push_back({0, -1, 0});
      s.edge_convex.push_back(1);
      s.curvature.push_back(0);
      s.face.push_back(-1);
      s.edge.push_back(e);
      s.vertex.push_back(-1);
      s.nonconcave.push_back(0);
    }
  return s;
}

TEST(ConvexEdgeReach, NamesTheEdgeReachedAlongHalfItsLength) {
  const Samples s = two_edges(20);
  std::vector<Point3> axis;
  for (int k = 0; k < 20; ++k) axis.push_back({static_cast<double>(k), 0.3, -0.3});  // edge 0: all
  for (int k = 0; k < 10; ++k) axis.push_back({static_cast<double>(k), 10.3, -0.3});  // edge 1: half
  const EdgeReach r = convex_edge_reach(s, SpacingField(1.0), axis);
  EXPECT_DOUBLE_EQ(r.reached, 30.0 / 40.0);
  ASSERT_EQ(r.short_edges.size(), 1u);
  EXPECT_EQ(r.short_edges[0].edge, 1);
  EXPECT_DOUBLE_EQ(r.short_edges[0].reached, 0.5);
  EXPECT_DOUBLE_EQ(r.short_edges[0].at[1], 10.0);
  EXPECT_GE(r.short_edges[0].at[0], 10.0);  // a sample the axis does not come near
}

TEST(ConvexEdgeReach, FartherThanTheSpacingIsNotReached) {
  const Samples s = two_edges(5);
  std::vector<Point3> axis;
  for (int e = 0; e < 2; ++e)
    for (int k = 0; k < 5; ++k) axis.push_back({static_cast<double>(k), 10.0 * e + 0.8, -0.8});  // 1.13 away
  EXPECT_DOUBLE_EQ(convex_edge_reach(s, SpacingField(1.2), axis).reached, 1.0);
  const EdgeReach r = convex_edge_reach(s, SpacingField(1.0), axis);
  EXPECT_DOUBLE_EQ(r.reached, 0.0);
  EXPECT_EQ(r.short_edges.size(), 2u);
}

TEST(ConvexEdgeReach, SmoothAndGentleEdgesAreNotCounted) {
  Samples s = two_edges(5);
  for (int i = 0; i < 5; ++i) s.normal2[i] = {0, -0.1, 0.995};  // edge 0 turns by 6 degrees
  for (int i = 5; i < 10; ++i) s.edge_convex[i] = 0;            // edge 1 smooth
  const EdgeReach r = convex_edge_reach(s, SpacingField(1.0), {});
  EXPECT_DOUBLE_EQ(r.reached, 1.0);
  EXPECT_TRUE(r.short_edges.empty());
}

}  // namespace
}  // namespace cadmedial
