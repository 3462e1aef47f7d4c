// OpenCASCADE's Linux build defines this (see read_shape.cpp): OCC_CATCH_SIGNALS below turns a
// fault on the second thread into a Standard_Failure. Before any OpenCASCADE header.
#define OCC_CONVERT_SIGNALS
#include "check_solid.h"

#include <cctype>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include <BRepBndLib.hxx>
#include <BRepCheck.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <BRepGProp_Domain.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp_Vinert.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>

#include "../two_cores.h"
#include "shape_text.h"

namespace cadmedial::internal {

// Every edge of a closed 2-manifold shell is used twice: by two faces, or twice by one face
// (the seam of a periodic surface). Degenerate edges (a sphere's pole) are used once and are fine.
// Returns "" or the reason the shell is not closed, with an edge number from `edge_index`.
std::string open_or_nonmanifold_edge(const TopoDS_Shape& shell, const TopTools_IndexedMapOfShape& edge_index) {
  TopTools_IndexedMapOfShape edges;
  std::vector<int> uses;
  std::vector<TopTools_IndexedMapOfShape> faces_of;
  for (TopExp_Explorer fx(shell, TopAbs_FACE); fx.More(); fx.Next()) {
    for (TopExp_Explorer ex(fx.Current(), TopAbs_EDGE); ex.More(); ex.Next()) {
      const int i = edges.Add(ex.Current());
      if (i > static_cast<int>(uses.size())) {
        uses.push_back(0);
        faces_of.emplace_back();
      }
      ++uses[i - 1];
      faces_of[i - 1].Add(fx.Current());
    }
  }
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
    if (BRep_Tool::Degenerated(edge)) continue;
    const int nfaces = faces_of[i - 1].Extent();
    const int n = uses[i - 1];
    if (n == 2) continue;
    const std::string name = "edge " + std::to_string(edge_index.FindIndex(edge));
    if (n < 2)
      return name + " is bounded by 1 face (the shell is open)" + edge_location(edge);
    return name + " is bounded by " + std::to_string(nfaces) + " faces (non-manifold)" + edge_location(edge);
  }
  return "";
}

namespace {

std::string status_name(BRepCheck_Status status) {
  std::ostringstream s;
  BRepCheck::Print(status, s);
  std::string text = s.str();
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

}  // namespace

// The first defect BRepCheck_Analyzer found on a sub-shape of `solid`, as "vertex 3 is invalid
// (BRepCheck_...)", smallest sub-shapes first since a bad vertex also makes its edges and faces
// invalid. A defect can be recorded on the shape itself or "in the context" of a larger one (a
// vertex that is off its edge's curve): both are looked at.
std::string first_check_failure(const TopoDS_Shape& solid, const BRepCheck_Analyzer& analyzer) {
  auto first_error = [](const BRepCheck_ListOfStatus& list) {
    for (BRepCheck_ListOfStatus::Iterator it(list); it.More(); it.Next())
      if (it.Value() != BRepCheck_NoError) return it.Value();
    return BRepCheck_NoError;
  };
  const std::pair<TopAbs_ShapeEnum, const char*> kinds[] = {
      {TopAbs_VERTEX, "vertex"}, {TopAbs_EDGE, "edge"}, {TopAbs_WIRE, "wire"},
      {TopAbs_FACE, "face"},     {TopAbs_SHELL, "shell"}};
  for (const auto& [type, type_name] : kinds) {
    TopTools_IndexedMapOfShape subs;
    TopExp::MapShapes(solid, type, subs);
    for (int i = 1; i <= subs.Extent(); ++i) {
      Handle(BRepCheck_Result) result;
      try {
        result = analyzer.Result(subs(i));
      } catch (const Standard_Failure&) {
        continue;  // not analysed (the analyzer keeps only what it reached)
      }
      if (result.IsNull()) continue;
      BRepCheck_Status status = first_error(result->Status());
      for (result->InitContextIterator(); status == BRepCheck_NoError && result->MoreShapeInContext();
           result->NextShapeInContext())
        status = first_error(result->StatusOnShape());
      if (status == BRepCheck_NoError) continue;
      std::string where;
      if (type == TopAbs_EDGE) where = edge_location(TopoDS::Edge(subs(i)));
      if (type == TopAbs_VERTEX) where = " at " + point_text(BRep_Tool::Pnt(TopoDS::Vertex(subs(i))));
      return std::string(type_name) + " " + std::to_string(i) + " is invalid (" + status_name(status) + ")" + where;
    }
  }
  return "the solid is invalid (BRepCheck_Analyzer names no sub-shape)";
}

// The solid's volume as BRepGProp::VolumeProperties computes it (each face's Gauss integral from
// the mean of the vertices), the two cores taking the next face in turn: on B-spline-rich parts this
// was half the set-up (NIST CTC 02: 0.13 s of 0.27 on one core). A fault on the second thread is
// caught there as on this one.
double signed_volume(const TopoDS_Solid& solid) {
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer ex(solid, TopAbs_FACE); ex.More(); ex.Next()) faces.push_back(TopoDS::Face(ex.Current()));
  gp_XYZ mean(0, 0, 0);
  int nv = 0;
  for (TopExp_Explorer ex(solid, TopAbs_VERTEX); ex.More(); ex.Next(), ++nv)
    mean += BRep_Tool::Pnt(TopoDS::Vertex(ex.Current())).XYZ();
  if (nv > 0) mean /= nv;
  std::vector<double> volume(faces.size(), 0.0);
  internal::on_two_cores_each(faces.size(), [&](std::size_t k) {
    OCC_CATCH_SIGNALS
    const TopoDS_Face& f = faces[k];
    const TopAbs_Orientation o = f.Orientation();
    TopLoc_Location loc;
    if ((o != TopAbs_FORWARD && o != TopAbs_REVERSED) || BRep_Tool::Surface(f, loc).IsNull()) return;
    BRepGProp_Vinert inertia;
    inertia.SetLocation(gp_Pnt(mean));
    BRepGProp_Face face(f);
    if (f.NbChildren() == 0) {
      inertia.Perform(face);
    } else {
      BRepGProp_Domain domain(f);
      inertia.Perform(face, domain);
    }
    volume[k] = inertia.Mass();
  });
  double sum = 0;
  for (double v : volume) sum += v;  // in face order, as one pass
  return sum;
}

double diagonal(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  if (box.IsVoid()) return 0.0;
  return std::sqrt(box.SquareExtent());
}

}  // namespace cadmedial::internal
