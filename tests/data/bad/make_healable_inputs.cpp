// Writes the healable inputs of this corpus (README.md): parts with one defect that OpenCASCADE's
// healing mends, or one bad solid beside good ones. BRep_Builder makes what FreeCAD's Part refuses
// to build (an empty solid, a face reversed in its shell). Build and run (from tests/data/bad/):
//   g++ -std=c++17 -I/usr/include/opencascade make_healable_inputs.cpp -o /tmp/mhi \
//       -lTKernel -lTKMath -lTKG3d -lTKBRep -lTKTopAlgo -lTKPrim && /tmp/mhi
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

// A 10 x 20 x 30 box rebuilt face by face; face `which` (MakeBox's order: x min, x max, y min,
// y max, z min, z max) reversed, or moved by `gap` along its normal's axis (then its edges are
// its own: the shell is open by `gap`).
TopoDS_Solid box_with_face(int which, bool reversed, double gap) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 20, 30).Shape();
  BRep_Builder b;
  TopoDS_Shell shell;
  b.MakeShell(shell);
  int i = 0;
  for (TopExp_Explorer fx(box, TopAbs_FACE); fx.More(); fx.Next(), ++i) {
    TopoDS_Shape f = fx.Current();
    if (i == which && reversed) f.Reverse();
    if (i == which && gap != 0) {
      gp_Trsf t;
      t.SetTranslation(gp_Vec(which / 2 == 0 ? gap : 0, which / 2 == 1 ? gap : 0, which / 2 == 2 ? gap : 0));
      f = BRepBuilderAPI_Transform(f, t, /*copy=*/true).Shape();
    }
    b.Add(shell, f);
  }
  return BRepBuilderAPI_MakeSolid(shell).Solid();
}

int main() {
  BRep_Builder b;
  // Three 10 mm cubes in a row, touching, and an empty solid (no shell) as the third of four.
  TopoDS_Compound assembly;
  b.MakeCompound(assembly);
  TopoDS_Solid empty;
  b.MakeSolid(empty);
  for (int i = 0; i < 3; ++i) {
    if (i == 2) b.Add(assembly, empty);
    b.Add(assembly, BRepPrimAPI_MakeBox(gp_Pnt(10.0 * i, 0, 0), 10, 10, 10).Shape());
  }
  BRepTools::Write(assembly, "assembly_with_empty_solid.brep");
  // The box with its top face (z = 30) reversed in the shell: BRepCheck refuses the shell's
  // orientation, ShapeFix_Shell reorients it.
  BRepTools::Write(box_with_face(5, true, 0.0), "reversed_face.brep");
  // The box with its x = 10 face moved out by 0.001: a gap of 0.001 all round that face.
  BRepTools::Write(box_with_face(1, false, 0.001), "gap_of_0.001.brep");
  return 0;
}
