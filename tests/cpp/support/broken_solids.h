// Solids with one defect that OpenCASCADE's healing mends (or cannot), built with BRep_Builder as
// broken CAD exports come: the same constructions as tests/data/bad/make_healable_inputs.cpp.
#pragma once

#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

namespace cadmedial::test {

/// The box [0,a] x [0,b] x [0,c] rebuilt face by face, with face `which` (BRepPrimAPI_MakeBox's
/// order: x min, x max, y min, y max, z min, z max) reversed in its shell: BRepCheck refuses the
/// shell's orientation (BRepCheck_BadOrientationOfSubshape).
TopoDS_Solid box_with_reversed_face(double a, double b, double c, int which);
/// The same with every face whose bit is set in `mask` (bit i: face i) reversed. Three faces of a
/// box reversed cancel its volume (each face spans a sixth of it from the centre).
TopoDS_Solid box_with_reversed_faces(double a, double b, double c, unsigned mask);
/// The same box with face `which` moved by `gap` along its own normal axis, onto edges of its own:
/// the shell is open by `gap` all round that face.
TopoDS_Solid box_with_gap(double a, double b, double c, int which, double gap);
/// BRepPrimAPI_MakeBox(a, b, c) with its first vertex moved by (3, 2, 1) times 1e-7, its
/// tolerance: off its edges' ends by 3.7 times the tolerance (BRepCheck_InvalidPointOnCurve).
TopoDS_Shape box_with_vertex_off_its_edges(double a, double b, double c);
/// A solid with no shell.
TopoDS_Solid empty_solid();

}  // namespace cadmedial::test
