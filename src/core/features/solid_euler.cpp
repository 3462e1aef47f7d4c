#include "solid_euler.h"

#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shape.hxx>

namespace cadmedial {

long solid_euler_characteristic(const TopoDS_Shape& solid) {
  TopTools_IndexedMapOfShape vertices, edges, faces;
  TopExp::MapShapes(solid, TopAbs_VERTEX, vertices);
  TopExp::MapShapes(solid, TopAbs_EDGE, edges);
  TopExp::MapShapes(solid, TopAbs_FACE, faces);
  long chi = vertices.Extent();
  for (int e = 1; e <= edges.Extent(); ++e)
    if (!BRep_Tool::Degenerated(TopoDS::Edge(edges(e)))) --chi;
  for (int f = 1; f <= faces.Extent(); ++f) {
    long wires = 0;
    for (TopExp_Explorer w(faces(f), TopAbs_WIRE); w.More(); w.Next()) ++wires;
    chi += 2 - wires;
  }
  return chi / 2;
}

}  // namespace cadmedial
