// Feature classification (4.1.1, 4.2.1) on solids whose features are known by construction.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <TopoDS.hxx>

#include "core/features/classify_features.h"
#include "support/solids.h"

namespace cadmedial {
namespace {

using test::Vec3;

gp_Pnt edge_midpoint(const Features& f, int e) {
  BRepAdaptor_Curve curve(TopoDS::Edge(f.edges.FindKey(e + 1)));
  return curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
}

gp_Pnt vertex_point(const Features& f, int v) { return BRep_Tool::Pnt(TopoDS::Vertex(f.vertices.FindKey(v + 1))); }

bool is_degenerate(const Features& f, int e) { return BRep_Tool::Degenerated(TopoDS::Edge(f.edges.FindKey(e + 1))); }

// Edge indices whose midpoint satisfies pred.
std::vector<int> edges_where(const Features& f, const std::function<bool(const gp_Pnt&)>& pred) {
  std::vector<int> out;
  for (int e = 0; e < f.edges.Extent(); ++e)
    if (!is_degenerate(f, e) && pred(edge_midpoint(f, e))) out.push_back(e);
  return out;
}

int vertex_at(const Features& f, double x, double y, double z) {
  for (int v = 0; v < f.vertices.Extent(); ++v)
    if (vertex_point(f, v).Distance(gp_Pnt(x, y, z)) < 1e-7) return v;
  return -1;
}

std::string kinds(const Features& f) {
  std::string s;
  for (int e = 0; e < static_cast<int>(f.edge_kind.size()); ++e) {
    const gp_Pnt p = edge_midpoint(f, e);
    s += "\n  edge " + std::to_string(e) + " at (" + std::to_string(p.X()) + ", " + std::to_string(p.Y()) + ", " +
         std::to_string(p.Z()) + "): " + edge_kind_name(f.edge_kind[e]);
  }
  return s;
}

void expect_sizes(const Features& f) {
  EXPECT_EQ(static_cast<int>(f.edge_kind.size()), f.edges.Extent());
  EXPECT_EQ(static_cast<int>(f.nonconcave_corner.size()), f.vertices.Extent());
}

TEST(ConvexEdges, BoxEdgesAreAllConvex) {
  const Features f = classify_features(test::make_box(10, 8, 6));
  expect_sizes(f);
  ASSERT_EQ(f.edges.Extent(), 12);
  for (int e = 0; e < 12; ++e) EXPECT_EQ(f.edge_kind.at(e), EdgeKind::Convex) << kinds(f);
}

TEST(ConvexEdges, BoxEdgeDihedralAngleIsNinetyDegrees) {
  const Features f = classify_features(test::make_box(10, 8, 6));
  for (int e = 0; e < f.edges.Extent(); ++e) {
    BRepAdaptor_Curve curve(TopoDS::Edge(f.edges.FindKey(e + 1)));
    const EdgePoint p = edge_point(f, e, 0.5 * (curve.FirstParameter() + curve.LastParameter()));
    EXPECT_NEAR(p.dihedral_deg, 90.0, 1e-6) << "edge " << e;
    EXPECT_EQ(p.kind, PointKind::Convex) << "edge " << e;
  }
}

TEST(NonconcaveCorners, BoxCornersAreAllNonconcave) {
  const Features f = classify_features(test::make_box(10, 8, 6));
  expect_sizes(f);
  ASSERT_EQ(f.vertices.Extent(), 8);
  for (int v = 0; v < 8; ++v) EXPECT_TRUE(f.nonconcave_corner.at(v)) << "vertex " << v;
}

TEST(ConcaveEdges, LBlockHasExactlyOneConcaveEdge) {
  // L over (0,0) (8,0) (8,3) (3,3) (3,8) (0,8), height 3: the vertical edge at (3, 3) is concave
  // (the solid fills 270 degrees around it); the other 17 are convex.
  const Features f = classify_features(test::make_l_block(8, 3, 3));
  expect_sizes(f);
  int concave = 0, convex = 0;
  for (int e = 0; e < static_cast<int>(f.edge_kind.size()); ++e) {
    if (f.edge_kind[e] == EdgeKind::Concave) {
      ++concave;
      const gp_Pnt m = edge_midpoint(f, e);
      EXPECT_NEAR(m.X(), 3, 1e-9);
      EXPECT_NEAR(m.Y(), 3, 1e-9);
    }
    convex += f.edge_kind[e] == EdgeKind::Convex;
  }
  EXPECT_EQ(concave, 1) << kinds(f);
  EXPECT_EQ(convex, f.edges.Extent() - 1) << kinds(f);
}

TEST(ConcaveEdges, LBlockConcaveEdgeDihedralIs270Degrees) {
  const Features f = classify_features(test::make_l_block(8, 3, 3));
  const auto e = edges_where(f, [](const gp_Pnt& p) { return std::abs(p.X() - 3) < 1e-9 && std::abs(p.Y() - 3) < 1e-9; });
  ASSERT_EQ(e.size(), 1u);
  BRepAdaptor_Curve curve(TopoDS::Edge(f.edges.FindKey(e[0] + 1)));
  const EdgePoint p = edge_point(f, e[0], 0.5 * (curve.FirstParameter() + curve.LastParameter()));
  EXPECT_NEAR(p.dihedral_deg, 270.0, 1e-6);
  EXPECT_EQ(p.kind, PointKind::Concave);
}

// Pocket block: box [0,8]^2 x [0,4], pocket [3,5]^2 x [2,4].
TEST(NonconcaveCorners, PocketFloorCornerIsNotNonconcave) {
  // A floor corner has three concave edges (two floor edges, one vertical wall edge): the solid's
  // exterior near it is a convex octant, so the inner medial axis does not reach it.
  const Features f = classify_features(test::make_pocket_block(8, 4, 3, 5, 2));
  expect_sizes(f);
  for (double x : {3.0, 5.0})
    for (double y : {3.0, 5.0}) {
      const int v = vertex_at(f, x, y, 2);
      ASSERT_GE(v, 0) << "no vertex at (" << x << ", " << y << ", 2)";
      EXPECT_FALSE(f.nonconcave_corner.at(v)) << "floor corner (" << x << ", " << y << ", 2)";
    }
}

TEST(ConcaveEdges, PocketWallAndFloorEdgesAreConcave) {
  const Features f = classify_features(test::make_pocket_block(8, 4, 3, 5, 2));
  // Floor edges (z = 2) and the vertical pocket edges (x, y in {3, 5}, 2 < z < 4).
  const auto e = edges_where(f, [](const gp_Pnt& p) {
    const bool in_pocket = p.X() > 3 - 1e-9 && p.X() < 5 + 1e-9 && p.Y() > 3 - 1e-9 && p.Y() < 5 + 1e-9;
    return in_pocket && p.Z() < 4 - 1e-9;
  });
  ASSERT_EQ(e.size(), 8u) << kinds(f);
  for (int k : e) EXPECT_EQ(f.edge_kind.at(k), EdgeKind::Concave) << kinds(f);
}

TEST(NonconcaveCorners, SaddleCornerIsNonconcave) {
  // A rim corner of the pocket has two convex rim edges and one concave vertical edge: a saddle, and
  // the inner medial axis reaches it along the convex edges.
  const Features f = classify_features(test::make_pocket_block(8, 4, 3, 5, 2));
  for (double x : {3.0, 5.0})
    for (double y : {3.0, 5.0}) {
      const int v = vertex_at(f, x, y, 4);
      ASSERT_GE(v, 0);
      EXPECT_TRUE(f.nonconcave_corner.at(v)) << "rim corner (" << x << ", " << y << ", 4)";
    }
}

TEST(SeamEdges, CylinderSeamIsSeamAndRimsAreConvex) {
  const Features f = classify_features(test::make_cylinder(2, 8));
  expect_sizes(f);
  int seams = 0, rims = 0;
  for (int e = 0; e < static_cast<int>(f.edge_kind.size()); ++e) {
    const gp_Pnt m = edge_midpoint(f, e);
    if (std::abs(m.Z() - 4) < 1e-9) {  // the seam runs from z = 0 to z = 8
      EXPECT_EQ(f.edge_kind[e], EdgeKind::Seam) << kinds(f);
      ++seams;
    } else {
      EXPECT_EQ(f.edge_kind[e], EdgeKind::Convex) << kinds(f);
      ++rims;
    }
  }
  EXPECT_EQ(seams, 1);
  EXPECT_EQ(rims, 2);
}

TEST(NonconcaveCorners, ConeApexIsNonconcave) {
  const Features f = classify_features(test::make_cone(3, 5));
  expect_sizes(f);
  const int apex = vertex_at(f, 0, 0, 5);
  ASSERT_GE(apex, 0) << "the cone has no vertex at its apex";
  EXPECT_TRUE(f.nonconcave_corner.at(apex));
}

TEST(DegenerateEdges, ConeApexEdgeIsDegenerate) {
  const Features f = classify_features(test::make_cone(3, 5));
  int degenerate = 0;
  for (int e = 0; e < f.edges.Extent(); ++e)
    if (is_degenerate(f, e)) {
      ++degenerate;
      EXPECT_EQ(f.edge_kind.at(e), EdgeKind::Degenerate) << "edge " << e;
    }
  if (degenerate == 0) GTEST_SKIP() << "OpenCASCADE built this cone without a degenerate edge";
}

TEST(SmoothSurfaces, SphereHasNoSharpFeature) {
  const Features f = classify_features(test::make_sphere(3));
  expect_sizes(f);
  for (int e = 0; e < static_cast<int>(f.edge_kind.size()); ++e)
    EXPECT_TRUE(f.edge_kind[e] == EdgeKind::Seam || f.edge_kind[e] == EdgeKind::Degenerate ||
                f.edge_kind[e] == EdgeKind::Smooth)
        << kinds(f);
  for (int v = 0; v < static_cast<int>(f.nonconcave_corner.size()); ++v) {
    EXPECT_FALSE(f.nonconcave_corner[v]) << "sphere vertex " << v << " (a pole: smooth point)";
    EXPECT_FALSE(f.sharp_vertex.at(v)) << "sphere vertex " << v;
  }
}

TEST(SmoothSurfaces, TorusHasNoSharpFeature) {
  const Features f = classify_features(test::make_torus(5, 1.5));
  for (int e = 0; e < static_cast<int>(f.edge_kind.size()); ++e)
    EXPECT_EQ(f.edge_kind[e], EdgeKind::Seam) << kinds(f);
  for (int v = 0; v < static_cast<int>(f.nonconcave_corner.size()); ++v) EXPECT_FALSE(f.nonconcave_corner[v]);
}

TEST(SmoothEdges, RoundedEdgeBoundariesAreSmooth) {
  // Box [0,8] x [0,6] x [0,4], edge x = 8, z = 4 rounded with r = 1.5: the round meets the top face
  // along x = 6.5, z = 4 and the side face along x = 8, z = 2.5, tangentially.
  const Features f = classify_features(test::make_filleted_box(8, 6, 4, 1.5));
  expect_sizes(f);
  const auto smooth = edges_where(f, [](const gp_Pnt& p) {
    return (std::abs(p.X() - 6.5) < 1e-7 && std::abs(p.Z() - 4) < 1e-7) ||
           (std::abs(p.X() - 8) < 1e-7 && std::abs(p.Z() - 2.5) < 1e-7);
  });
  ASSERT_EQ(smooth.size(), 2u) << kinds(f);
  for (int e : smooth) EXPECT_EQ(f.edge_kind.at(e), EdgeKind::Smooth) << kinds(f);
  // Every other edge of this solid is a sharp convex edge (including the round's end arcs).
  for (int e = 0; e < f.edges.Extent(); ++e)
    if (std::find(smooth.begin(), smooth.end(), e) == smooth.end())
      EXPECT_EQ(f.edge_kind.at(e), EdgeKind::Convex) << kinds(f);
}

}  // namespace
}  // namespace cadmedial
