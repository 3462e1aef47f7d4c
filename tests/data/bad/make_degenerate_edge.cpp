// Writes degenerate_edge.brep: a 10 x 20 x 30 box whose top face's wire holds an extra edge of
// zero length (a line from one corner vertex back to itself, parameter range [0, 0]), not flagged
// as degenerated. FreeCAD's Part refuses to build such an edge, so it is made here with
// BRep_Builder. Build and run (from tests/data/bad/):
//   g++ -std=c++17 -I/usr/include/opencascade make_degenerate_edge.cpp -o /tmp/mde \
//       -lTKernel -lTKMath -lTKG3d -lTKBRep -lTKTopAlgo -lTKPrim && /tmp/mde degenerate_edge.brep
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRepTools_ReShape.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Line.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Dir.hxx>

int main(int argc, char** argv) {
  if (argc != 2) return 1;
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 20, 30).Shape();
  TopoDS_Face top;
  for (TopExp_Explorer fx(box, TopAbs_FACE); fx.More(); fx.Next()) {
    double u0, u1, v0, v1;
    BRepTools::UVBounds(TopoDS::Face(fx.Current()), u0, u1, v0, v1);
    gp_Pnt c = BRep_Tool::Surface(TopoDS::Face(fx.Current()))->Value(0.5 * (u0 + u1), 0.5 * (v0 + v1));
    if (c.Z() > 29.9) top = TopoDS::Face(fx.Current());
  }
  BRep_Builder b;
  const TopoDS_Wire outer = BRepTools::OuterWire(top);
  TopoDS_Wire wire;
  b.MakeWire(wire);
  bool inserted = false;
  for (BRepTools_WireExplorer wx(outer, top); wx.More(); wx.Next()) {
    b.Add(wire, wx.Current());
    if (inserted) continue;
    // The zero-length edge, at the vertex where this edge ends.
    const TopoDS_Vertex v = TopExp::LastVertex(wx.Current(), true);
    TopoDS_Edge zero;
    b.MakeEdge(zero, new Geom_Line(BRep_Tool::Pnt(v), gp_Dir(1, 0, 0)), 1e-7);
    b.Add(zero, v.Oriented(TopAbs_FORWARD));
    b.Add(zero, v.Oriented(TopAbs_REVERSED));
    b.Range(zero, 0.0, 0.0);
    b.Add(wire, zero);
    inserted = true;
  }
  TopoDS_Face face;
  b.MakeFace(face, BRep_Tool::Surface(top), 1e-7);
  b.Add(face, wire);
  face.Orientation(top.Orientation());
  Handle(BRepTools_ReShape) reshape = new BRepTools_ReShape;
  reshape->Replace(top, face);
  return BRepTools::Write(reshape->Apply(box), argv[1]) ? 0 : 1;
}
