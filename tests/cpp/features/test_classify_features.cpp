// Feature classification (4.1.1, 4.2.1) on solids whose features are known by construction.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <ShapeFix_Solid.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>

#include "core/errors.h"

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

// Points of edge e (of the 9 that classification looks at) where a face's normal is undefined.
int undefined_points(const Features& f, int e) {
  double first = 0, last = 0;
  BRep_Tool::Range(TopoDS::Edge(f.edges.FindKey(e + 1)), first, last);
  int n = 0;
  for (int i = 0; i < 9; ++i) {
    try {
      edge_point(f, e, first + (last - first) * i / 8);
    } catch (const GeometryError&) {
      ++n;
    }
  }
  return n;
}

TopoDS_Solid first_solid(const TopoDS_Shape& shape) {
  TopExp_Explorer ex(shape, TopAbs_SOLID);
  if (!ex.More()) throw std::runtime_error("no solid");
  return TopoDS::Solid(ex.Current());
}

// As in SOT23.igs (FreeCAD's IDF library): a face of revolution whose profile ends on the axis
// has no normal there (the derivative along the rotation vanishes). Here the quarter "disc"
// under the B-spline arc (1,0,0) -> (0,0,1), revolved by 90 degrees about z.
TopoDS_Solid make_revolved_profile_touching_axis() {
  TColgp_Array1OfPnt poles(1, 3);
  poles(1) = gp_Pnt(1, 0, 0);
  poles(2) = gp_Pnt(1, 0, 1);
  poles(3) = gp_Pnt(0, 0, 1);
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0;
  knots(2) = 1;
  TColStd_Array1OfInteger mults(1, 2);
  mults(1) = mults(2) = 3;
  const TopoDS_Edge arc = BRepBuilderAPI_MakeEdge(new Geom_BSplineCurve(poles, knots, mults, 2));
  const TopoDS_Edge axis = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 1), gp_Pnt(0, 0, 0));
  const TopoDS_Edge base = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0));
  const TopoDS_Face profile = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(arc, axis, base), Standard_True);
  return first_solid(BRepPrimAPI_MakeRevol(profile, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), M_PI / 2));
}

// The unit cube whose top face is a flat B-spline patch with its first row of poles doubled
// (y = v^2): the derivative across the edge y = 0, z = 1 vanishes all along it, so the top face
// has no normal at any point of that edge.
TopoDS_Solid make_cube_with_collapsed_top_boundary() {
  TColgp_Array2OfPnt poles(1, 2, 1, 3);
  for (int i = 1; i <= 2; ++i) {
    const double x = i - 1;
    poles(i, 1) = gp_Pnt(x, 0, 1);
    poles(i, 2) = gp_Pnt(x, 0, 1);
    poles(i, 3) = gp_Pnt(x, 1, 1);
  }
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0;
  knots(2) = 1;
  TColStd_Array1OfInteger u_mults(1, 2), v_mults(1, 2);
  u_mults(1) = u_mults(2) = 2;
  v_mults(1) = v_mults(2) = 3;
  BRepBuilderAPI_Sewing sewing(1e-7);
  sewing.Add(BRepBuilderAPI_MakeFace(new Geom_BSplineSurface(poles, knots, knots, u_mults, v_mults, 1, 2), 1e-7));
  const auto quad = [&](gp_Pnt a, gp_Pnt b, gp_Pnt c, gp_Pnt d) {
    sewing.Add(BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakePolygon(a, b, c, d, Standard_True).Wire(), Standard_True));
  };
  quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  quad({0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1});
  quad({0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1});
  quad({0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1});
  quad({1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1});
  sewing.Perform();
  TopExp_Explorer shell(sewing.SewedShape(), TopAbs_SHELL);
  if (!shell.More()) throw std::runtime_error("the faces do not sew into a shell");
  ShapeFix_Solid fix(BRepBuilderAPI_MakeSolid(TopoDS::Shell(shell.Current())).Solid());
  fix.Perform();
  return first_solid(fix.Shape());
}

TEST(UndefinedNormals, EdgesEndingAtARevolvedFacesPoleAreConvex) {
  const TopoDS_Solid solid = make_revolved_profile_touching_axis();
  ASSERT_TRUE(BRepCheck_Analyzer(solid).IsValid());
  const Features f = classify_features(solid);  // threw "face normal undefined on edge" before
  expect_sizes(f);
  // The two arcs from the equator to the pole (0, 0, 1), in the planes y = 0 and x = 0, where the
  // revolved face meets a flat side at 90 degrees.
  const auto arcs = edges_where(f, [](const gp_Pnt& p) {
    return p.Z() > 0.1 && p.Z() < 0.9 && p.X() + p.Y() > 0.1 && (std::abs(p.X()) < 1e-7 || std::abs(p.Y()) < 1e-7);
  });
  ASSERT_EQ(arcs.size(), 2u) << kinds(f);
  for (int e : arcs) {
    EXPECT_EQ(undefined_points(f, e), 1) << "edge " << e << ": the face has no normal at the pole only";
    EXPECT_EQ(f.edge_kind.at(e), EdgeKind::Convex) << kinds(f);
  }
  const int pole = vertex_at(f, 0, 0, 1);
  ASSERT_GE(pole, 0);
  EXPECT_TRUE(f.nonconcave_corner.at(pole));
}

TEST(UndefinedNormals, EdgeWithNoNormalAnywhereIsClassifiedFromJustInsideItsFaces) {
  const TopoDS_Solid solid = make_cube_with_collapsed_top_boundary();
  ASSERT_TRUE(BRepCheck_Analyzer(solid).IsValid());
  const Features f = classify_features(solid);
  expect_sizes(f);
  ASSERT_EQ(f.edges.Extent(), 12);
  const auto collapsed = edges_where(f, [](const gp_Pnt& p) {
    return std::abs(p.Y()) < 1e-7 && std::abs(p.Z() - 1) < 1e-7;
  });
  ASSERT_EQ(collapsed.size(), 1u) << kinds(f);
  EXPECT_EQ(undefined_points(f, collapsed[0]), 9) << "no point of the edge votes";
  // Still a cube: every edge is convex, every corner non-concave.
  for (int e = 0; e < 12; ++e) EXPECT_EQ(f.edge_kind.at(e), EdgeKind::Convex) << kinds(f);
  for (int v = 0; v < f.vertices.Extent(); ++v) EXPECT_TRUE(f.nonconcave_corner.at(v)) << "vertex " << v;
}

}  // namespace
}  // namespace cadmedial
