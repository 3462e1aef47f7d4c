#include "check_geometry.h"

#include <cmath>
#include <string>

#include <BRep_CurveRepresentation.hxx>
#include <BRep_GCurve.hxx>
#include <BRep_ListOfCurveRepresentation.hxx>
#include <BRep_TEdge.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Conic.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_Conic.hxx>
#include <Geom_Curve.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_Surface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>

#include "../errors.h"
#include "shape_text.h"

namespace cadmedial::internal {

namespace {

// Geometry sanity.
//
// OpenCASCADE's release build does not check gp_Dir's norm (Standard_ConstructionError is compiled
// out), so BREP text can hand it a plane with a zero normal, a line with a zero direction or NaN
// coordinates; BRepCheck_Analyzer then dereferences null results and crashes (SIGSEGV in
// BRepCheck_Edge::InContext, found by fuzz/fuzz_read_brep.cpp). These cheap checks refuse such
// geometry first.

bool unit(const gp_XYZ& d) { return std::isfinite(d.Modulus()) && std::abs(d.Modulus() - 1.0) < 1e-6; }
bool unit(const gp_XY& d) { return std::isfinite(d.Modulus()) && std::abs(d.Modulus() - 1.0) < 1e-6; }
bool finite(const gp_XYZ& p) { return std::isfinite(p.X()) && std::isfinite(p.Y()) && std::isfinite(p.Z()); }
bool finite(const gp_XY& p) { return std::isfinite(p.X()) && std::isfinite(p.Y()); }

bool sane(const gp_Ax3& a) {
  return finite(a.Location().XYZ()) && unit(a.Direction().XYZ()) && unit(a.XDirection().XYZ()) &&
         unit(a.YDirection().XYZ()) && std::abs(a.Direction().XYZ().Dot(a.XDirection().XYZ())) < 1e-6;
}
bool sane(const gp_Ax2& a) {
  return finite(a.Location().XYZ()) && unit(a.Direction().XYZ()) && unit(a.XDirection().XYZ()) &&
         unit(a.YDirection().XYZ()) && std::abs(a.Direction().XYZ().Dot(a.XDirection().XYZ())) < 1e-6;
}

bool sane_surface(Handle(Geom_Surface) s) {
  for (int depth = 0; depth < 16 && !s.IsNull(); ++depth) {
    if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = t->BasisSurface();
    else if (auto o = Handle(Geom_OffsetSurface)::DownCast(s)) {
      if (!std::isfinite(o->Offset())) return false;
      s = o->BasisSurface();
    } else break;
  }
  if (s.IsNull()) return false;
  if (auto e = Handle(Geom_ElementarySurface)::DownCast(s)) return sane(e->Position());
  return true;
}

bool sane_curve(Handle(Geom_Curve) c) {
  for (int depth = 0; depth < 16 && !c.IsNull(); ++depth) {
    auto t = Handle(Geom_TrimmedCurve)::DownCast(c);
    if (t.IsNull()) break;
    c = t->BasisCurve();
  }
  if (c.IsNull()) return false;
  if (auto l = Handle(Geom_Line)::DownCast(c))
    return finite(l->Position().Location().XYZ()) && unit(l->Position().Direction().XYZ());
  if (auto k = Handle(Geom_Conic)::DownCast(c)) return sane(k->Position());
  return true;
}

bool sane_curve(Handle(Geom2d_Curve) c) {
  for (int depth = 0; depth < 16 && !c.IsNull(); ++depth) {
    auto t = Handle(Geom2d_TrimmedCurve)::DownCast(c);
    if (t.IsNull()) break;
    c = t->BasisCurve();
  }
  if (c.IsNull()) return false;
  if (auto l = Handle(Geom2d_Line)::DownCast(c))
    return finite(l->Position().Location().XY()) && unit(l->Position().Direction().XY());
  if (auto k = Handle(Geom2d_Conic)::DownCast(c)) {
    const gp_Ax22d a = k->Position();
    return finite(a.Location().XY()) && unit(a.XDirection().XY()) && unit(a.YDirection().XY());
  }
  return true;
}

// ---- curve ends -----------------------------------------------------------------------------
//
// BRepCheck_Analyzer refuses an edge whose 3D curve does not end at its vertices (BRepCheck_Vertex:
// farther than max(vertex, edge tolerance), InvalidPointOnCurve) or whose curve on a face strays
// from the 3D curve (BRepCheck_Edge: InvalidCurveOnSurface, sampled from end to end). But it checks
// the wires first, and on mangled BREP (tests/data/bad/fuzz-slow/: a 1e-6 box whose pcurves lie 10
// away, or whose range became 3) BRepCheck_Wire::SelfIntersect runs for minutes. The same two
// conditions, at the curve ends only, cost microseconds per edge: refuse on them first. The factor
// keeps this strictly looser than BRepCheck (it refuses from 1 x the tolerance), so no shape that
// BRepCheck accepts is refused here.
constexpr double kEndSlack = 10.0;

// "" or why edge `e` (numbered `index`) has a curve that does not end where it should; `faces`
// are the faces that hold it (BRepCheck checks the curves on those faces only).
std::string curve_end_defect(const TopoDS_Edge& e, int index, const TopTools_ListOfShape& faces) {
  if (BRep_Tool::Degenerated(e)) return "";
  double first = 0, last = 0;
  const Handle(Geom_Curve) curve = BRep_Tool::Curve(e, first, last);  // with the edge's location
  if (curve.IsNull()) return "";  // BRepCheck refuses an edge without a 3D curve on its own
  TopoDS_Vertex first_vertex, last_vertex;
  TopExp::Vertices(TopoDS::Edge(e.Oriented(TopAbs_FORWARD)), first_vertex, last_vertex);
  double tol = BRep_Tool::Tolerance(e);
  for (const TopoDS_Vertex& v : {first_vertex, last_vertex})
    if (!v.IsNull()) tol = std::max(tol, BRep_Tool::Tolerance(v));
  const double allowed = kEndSlack * tol;
  const std::string name = "edge " + std::to_string(index);

  const gp_Pnt end3d[2] = {curve->Value(first), curve->Value(last)};
  const TopoDS_Vertex ends[2] = {first_vertex, last_vertex};
  for (int k = 0; k < 2; ++k) {
    if (ends[k].IsNull()) continue;
    const double d = end3d[k].Distance(BRep_Tool::Pnt(ends[k]));
    if (!(d <= allowed))
      return name + "'s curve does not end at its vertex: " + message_number(d) + " away, tolerance " +
             message_number(tol) + edge_location(e);
  }
  // Its curve on each face, at the ends of its own range (the 3D curve's range on a valid edge:
  // BRepCheck refuses an edge that is not SameRange). A seam has one per orientation.
  for (TopTools_ListOfShape::Iterator it(faces); it.More(); it.Next()) {
    const TopoDS_Face face = TopoDS::Face(it.Value());
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);  // with the face's location
    if (surface.IsNull()) continue;
    for (TopAbs_Orientation o : {TopAbs_FORWARD, TopAbs_REVERSED}) {
      double f = 0, l = 0;
      const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Oriented(o)), face, f, l);
      if (pc.IsNull()) continue;
      const double params[2] = {f, l};
      for (int k = 0; k < 2; ++k) {
        const gp_Pnt2d uv = pc->Value(params[k]);
        const double d = surface->Value(uv.X(), uv.Y()).Distance(end3d[k]);
        if (!(d <= allowed))
          return name + "'s curve on a face strays from its 3D curve: " + message_number(d) +
                 " apart at an end, tolerance " + message_number(tol) + edge_location(e);
      }
    }
  }
  return "";
}

}  // namespace

// Throws InvalidInput naming the first face, edge or vertex (numbered over `shape`) whose geometry
// is degenerate or not finite, or whose curves do not meet at their ends (above).
void check_geometry(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape subs;
  TopExp::MapShapes(shape, TopAbs_VERTEX, subs);
  for (int i = 1; i <= subs.Extent(); ++i) {
    const TopoDS_Vertex& v = TopoDS::Vertex(subs(i));
    if (!finite(BRep_Tool::Pnt(v).XYZ()) || !std::isfinite(BRep_Tool::Tolerance(v)))
      throw InvalidInput("vertex " + std::to_string(i) + " has a coordinate or tolerance that is not a finite number");
  }
  subs.Clear();
  TopExp::MapShapes(shape, TopAbs_EDGE, subs);
  for (int i = 1; i <= subs.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(subs(i));
    const auto* tedge = dynamic_cast<const BRep_TEdge*>(e.TShape().get());
    if (!tedge) throw InvalidInput("edge " + std::to_string(i) + " is not an edge");
    for (BRep_ListOfCurveRepresentation::Iterator it(tedge->Curves()); it.More(); it.Next()) {
      const Handle(BRep_CurveRepresentation)& cr = it.Value();
      bool ok = true;
      if (auto g = Handle(BRep_GCurve)::DownCast(cr)) {
        double first = 0, last = 0;
        g->Range(first, last);
        ok = std::isfinite(first) && std::isfinite(last);
      }
      if (ok && cr->IsCurve3D()) ok = cr->Curve3D().IsNull() || sane_curve(cr->Curve3D());
      if (ok && cr->IsCurveOnSurface()) {
        ok = sane_curve(cr->PCurve()) && sane_surface(cr->Surface());
        if (ok && cr->IsCurveOnClosedSurface()) ok = sane_curve(cr->PCurve2());
      }
      if (!ok)
        throw InvalidInput("edge " + std::to_string(i) + " has a degenerate curve (a zero direction, or a number that is not finite)");
    }
  }
  subs.Clear();
  TopExp::MapShapes(shape, TopAbs_FACE, subs);
  for (int i = 1; i <= subs.Extent(); ++i) {
    TopLoc_Location loc;
    const Handle(Geom_Surface)& surface = BRep_Tool::Surface(TopoDS::Face(subs(i)), loc);
    if (surface.IsNull()) throw InvalidInput("face " + std::to_string(i) + " has no surface");
    if (!sane_surface(surface))
      throw InvalidInput("face " + std::to_string(i) + " has a degenerate surface (a zero axis, or a number that is not finite)");
  }
  // Only now that every curve and surface can be evaluated.
  subs.Clear();
  TopExp::MapShapes(shape, TopAbs_EDGE, subs);  // the numbering of the messages above
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edge_faces.FindKey(i));
    std::string why;
    try {
      why = curve_end_defect(e, subs.FindIndex(e), edge_faces(i));
    } catch (const Standard_Failure&) {
      // A curve this check cannot evaluate (an edge of zero range projected on its plane): BRepCheck
      // and the shell checks will say what is wrong.
    }
    if (!why.empty()) throw InvalidInput(why);
  }
}

}  // namespace cadmedial::internal
