#include "support/solids.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepLib.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace cadmedial::test {

namespace {

// The one solid of a shape, checked valid.
TopoDS_Solid single_valid_solid(const TopoDS_Shape& shape, const char* what) {
  TopoDS_Solid solid;
  int count = 0;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next(), ++count) solid = TopoDS::Solid(e.Current());
  if (count != 1) throw std::runtime_error(std::string(what) + ": " + std::to_string(count) + " solids");
  if (!BRepCheck_Analyzer(solid).IsValid()) throw std::runtime_error(std::string(what) + ": invalid solid");
  return solid;
}

TopoDS_Solid prism_of_polygon(const std::vector<std::array<double, 2>>& polygon, double height,
                              const char* what) {
  BRepBuilderAPI_MakePolygon wire;
  for (const auto& p : polygon) wire.Add(gp_Pnt(p[0], p[1], 0));
  wire.Close();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), /*OnlyPlane=*/true).Face();
  return single_valid_solid(BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, height)).Shape(), what);
}

}  // namespace

TopoDS_Solid make_box(double a, double b, double c) {
  return single_valid_solid(BRepPrimAPI_MakeBox(a, b, c).Solid(), "make_box");
}

TopoDS_Solid make_prism(const std::vector<std::array<double, 2>>& polygon, double height) {
  return prism_of_polygon(polygon, height, "make_prism");
}

TopoDS_Solid make_polytope_solid(const ConvexPolytope& polytope) {
  BRepBuilderAPI_Sewing sewing(1e-7 * polytope.bbox_diagonal());
  for (const auto& facet : polytope.facet_vertices) {
    BRepBuilderAPI_MakePolygon wire;
    for (int v : facet) {
      const Vec3& p = polytope.vertices[v];
      wire.Add(gp_Pnt(p[0], p[1], p[2]));
    }
    wire.Close();
    sewing.Add(BRepBuilderAPI_MakeFace(wire.Wire(), /*OnlyPlane=*/true).Face());
  }
  sewing.Perform();
  TopExp_Explorer shells(sewing.SewedShape(), TopAbs_SHELL);
  if (!shells.More()) throw std::runtime_error("make_polytope_solid: sewing gave no shell");
  BRepBuilderAPI_MakeSolid maker(TopoDS::Shell(shells.Current()));
  TopoDS_Solid solid = maker.Solid();
  BRepLib::OrientClosedSolid(solid);
  return single_valid_solid(solid, "make_polytope_solid");
}

TopoDS_Solid make_cylinder(double R, double H) {
  return single_valid_solid(BRepPrimAPI_MakeCylinder(R, H).Solid(), "make_cylinder");
}

TopoDS_Solid make_sphere(double R) { return single_valid_solid(BRepPrimAPI_MakeSphere(R).Solid(), "make_sphere"); }

TopoDS_Solid make_torus(double R, double r) {
  return single_valid_solid(BRepPrimAPI_MakeTorus(R, r).Solid(), "make_torus");
}

TopoDS_Solid make_cone(double R, double H) {
  return single_valid_solid(BRepPrimAPI_MakeCone(R, 0.0, H).Solid(), "make_cone");
}

TopoDS_Solid make_block_with_hole(double a, double b, double c, double r) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(a, b, c).Shape();
  // Taller than the box so that no face of the tool coincides with a face of the box.
  const TopoDS_Shape tool =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(a / 2, b / 2, -1.0), gp_Dir(0, 0, 1)), r, c + 2.0).Shape();
  return single_valid_solid(BRepAlgoAPI_Cut(box, tool).Shape(), "make_block_with_hole");
}

TopoDS_Solid make_l_block(double a, double t, double c) {
  return prism_of_polygon({{0, 0}, {a, 0}, {a, t}, {t, t}, {t, a}, {0, a}}, c, "make_l_block");
}

TopoDS_Solid make_pocket_block(double a, double c, double p0, double p1, double depth) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(a, a, c).Shape();
  // The tool sticks out above the top face so that the cut opens the pocket cleanly.
  const TopoDS_Shape tool = BRepPrimAPI_MakeBox(gp_Pnt(p0, p0, c - depth), gp_Pnt(p1, p1, c + 1.0)).Shape();
  return single_valid_solid(BRepAlgoAPI_Cut(box, tool).Shape(), "make_pocket_block");
}

TopoDS_Solid make_filleted_box(double a, double b, double c, double r) {
  // BRepFilletAPI lives in TKFillet, which the core does not link; the same solid is the union of
  // two boxes and the quarter-round cylinder, with coplanar faces merged (ShapeUpgrade).
  const TopoDS_Shape lower = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(a, b, c - r)).Shape();
  const TopoDS_Shape upper = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, c - r), gp_Pnt(a - r, b, c)).Shape();
  const TopoDS_Shape round =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(a - r, 0, c - r), gp_Dir(0, 1, 0)), r, b).Shape();
  TopoDS_Shape fused = BRepAlgoAPI_Fuse(BRepAlgoAPI_Fuse(lower, upper).Shape(), round).Shape();
  ShapeUpgrade_UnifySameDomain unify(fused, /*UnifyEdges=*/true, /*UnifyFaces=*/true, /*ConcatBSplines=*/false);
  unify.Build();
  return single_valid_solid(unify.Shape(), "make_filleted_box");
}

TopoDS_Shape make_compound(const std::vector<TopoDS_Solid>& solids) {
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (const auto& s : solids) builder.Add(compound, s);
  return compound;
}

}  // namespace cadmedial::test
