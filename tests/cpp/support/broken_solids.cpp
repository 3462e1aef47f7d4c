#include "support/broken_solids.h"

#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Trsf.hxx>

namespace cadmedial::test {
namespace {

TopoDS_Solid rebuilt_box(double a, double b, double c, int which, unsigned reversed, double gap) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(a, b, c).Shape();
  BRep_Builder builder;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  int i = 0;
  for (TopExp_Explorer fx(box, TopAbs_FACE); fx.More(); fx.Next(), ++i) {
    TopoDS_Shape f = fx.Current();
    if (reversed & (1u << i)) f.Reverse();
    if (i == which && gap != 0) {
      const int axis = which / 2;
      gp_Trsf t;
      t.SetTranslation(gp_Vec(axis == 0 ? gap : 0, axis == 1 ? gap : 0, axis == 2 ? gap : 0));
      f = BRepBuilderAPI_Transform(f, t, /*copy=*/true).Shape();
    }
    builder.Add(shell, f);
  }
  return BRepBuilderAPI_MakeSolid(shell).Solid();
}

}  // namespace

TopoDS_Solid box_with_reversed_face(double a, double b, double c, int which) {
  return rebuilt_box(a, b, c, which, 1u << which, 0.0);
}

TopoDS_Solid box_with_reversed_faces(double a, double b, double c, unsigned mask) {
  return rebuilt_box(a, b, c, -1, mask, 0.0);
}

TopoDS_Solid box_with_gap(double a, double b, double c, int which, double gap) {
  return rebuilt_box(a, b, c, which, 0u, gap);
}

TopoDS_Shape box_with_vertex_off_its_edges(double a, double b, double c) {
  const TopoDS_Shape shape = BRepPrimAPI_MakeBox(a, b, c).Shape();
  const TopoDS_Vertex v = TopoDS::Vertex(TopExp_Explorer(shape, TopAbs_VERTEX).Current());
  BRep_Builder().UpdateVertex(v, BRep_Tool::Pnt(v).Translated(gp_Vec(3e-7, 2e-7, 1e-7)), 1e-7);
  return shape;
}

TopoDS_Solid empty_solid() {
  TopoDS_Solid s;
  BRep_Builder().MakeSolid(s);
  return s;
}

}  // namespace cadmedial::test
