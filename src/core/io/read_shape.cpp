// Reading STEP / IGES / BREP into a shape, and turning a shape into checked, closed solids.
//
// What extract_solids accepts, and why:
// - solids (also inside compounds and compsolids): checked as they are;
// - closed shells that are not solids: made solids (BRepBuilderAPI_MakeSolid, ShapeFix_Solid for
//   the orientation), since STEP/IGES exports often stop at the shell;
// - loose faces (IGES often holds only faces): sewn together; every shell that sewing makes must be
//   closed, or the whole shape is refused: a face left out would silently change the medial axis;
// - loose wires, edges and vertices (construction geometry): ignored, they bound no volume. When the
//   shape holds nothing else, the "no solid" message counts them so the user sees what was there.
// Edge, face and vertex numbers in messages are 1-based indices of TopExp::MapShapes over the solid
// (or shell), which is the numbering FreeCAD shows as Edge12, Face3, ...
// OpenCASCADE's Linux build defines this; without it OCC_CATCH_SIGNALS (below) is empty and a fault
// caught by OSD's handler aborts the process instead of becoming a Standard_Failure. It must come
// before any OpenCASCADE header.
#define OCC_CONVERT_SIGNALS
#include "read_shape.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ios>
#include <new>
#include <sstream>

#include <signal.h>

#include <mutex>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <BRepGProp_Domain.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp_Vinert.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IGESControl_Reader.hxx>
#include <OSD.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeFix_Solid.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Vertex.hxx>
#include <Geom_Curve.hxx>
#include <BRep_CurveRepresentation.hxx>
#include <BRep_GCurve.hxx>
#include <BRep_ListOfCurveRepresentation.hxx>
#include <BRep_TEdge.hxx>
#include <Geom2d_Conic.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_Conic.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_Surface.hxx>
#include <Geom_TrimmedCurve.hxx>

#include "../errors.h"
#include "../two_cores.h"
#include "heal_shape.h"

namespace cadmedial {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string failure_text(const Standard_Failure& e) {
  const char* m = e.GetMessageString();
  std::string text = (m && *m) ? m : "";
  std::string type = e.DynamicType()->Name();
  return text.empty() ? type : type + ": " + text;
}

std::string point_text(const gp_Pnt& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p.X() << ", " << p.Y() << ", " << p.Z() << ")";
  return s.str();
}

// Midpoint of an edge's 3D curve, to tell the user where a bad edge is.
std::string edge_location(const TopoDS_Edge& edge) {
  try {
    double first = 0, last = 0;
    Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
    if (curve.IsNull()) return "";
    return " near " + point_text(curve->Value(0.5 * (first + last)));
  } catch (const Standard_Failure&) {
    return "";
  }
}

// ---- reading --------------------------------------------------------------------------------

// OpenCASCADE's readers guard their geometry parsing with OCC_CATCH_SIGNALS (GeomTools_*Set::Read*:
// an offset curve whose basis is unknown dereferences null, and the reader catches that and goes
// on without the curve), but that only works once OSD::SetSignal has installed OpenCASCADE's
// SIGSEGV/SIGBUS/SIGFPE/SIGILL handlers; without them the process dies (fuzz/fuzz_read_brep.cpp,
// tests/data/bad/fuzz/). FreeCAD installs them at start-up; the CLI and a plain Python process
// get them here, on the first read. Only the fault signals: SIGINT and the other job-control
// signals keep their handlers (Python's KeyboardInterrupt, the shell's Ctrl-C), and floating-point
// traps stay off.
void enable_reader_fault_recovery() {
  static std::once_flag once;
  std::call_once(once, [] {
    const int keep[] = {SIGINT, SIGHUP, SIGQUIT, SIGTERM, SIGABRT, SIGTRAP, SIGSYS, SIGCHLD, SIGPIPE};
    struct sigaction saved[sizeof keep / sizeof keep[0]];
    for (std::size_t i = 0; i < sizeof keep / sizeof keep[0]; ++i) ::sigaction(keep[i], nullptr, &saved[i]);
    OSD::SetSignal(false);
    for (std::size_t i = 0; i < sizeof keep / sizeof keep[0]; ++i) ::sigaction(keep[i], &saved[i], nullptr);
  });
}

TopoDS_Shape read_step(const std::string& path) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw InvalidInput(path + ": not a readable STEP file (the STEP parser failed)");
  if (reader.TransferRoots() == 0 || reader.NbShapes() == 0)
    throw InvalidInput(path + ": the STEP file holds no shape");
  return reader.OneShape();
}

TopoDS_Shape read_iges(const std::string& path) {
  IGESControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw InvalidInput(path + ": not a readable IGES file (the IGES parser failed)");
  if (reader.TransferRoots() == 0 || reader.NbShapes() == 0)
    throw InvalidInput(path + ": the IGES file holds no shape");
  return reader.OneShape();
}

// BRepTools::Read prints to std::cout and returns nothing useful on text that is not BREP, so
// look for the header it writes ("CASCADE Topology V1/V2/V3...") first.
bool has_brep_header(std::istream& in) {
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  in.clear();
  in.seekg(0);
  return head.find("CASCADE Topology V") != std::string::npos;
}

// BRepTools::Read loops over a shape's sub-shape list until it reads the '*' that ends it. When
// the stream fails first (the text is truncated, or a number is not a number), every later read
// is a no-op and that loop never ends, appending the same sub-shape until memory runs out (found
// by fuzz/fuzz_read_brep.cpp; tests/data/bad/fuzz/). So the stream throws on the first failed
// read instead: a failed read is always a broken file, since a valid one is read to its last
// token and no further (eofbit alone, at the very end, does not throw).
TopoDS_Shape parse_brep(std::istream& in, const std::string& context) {
  enable_reader_fault_recovery();
  in.exceptions(std::ios::failbit | std::ios::badbit);
  TopoDS_Shape shape;
  try {
    BRep_Builder builder;
    BRepTools::Read(shape, in, builder);
  } catch (const std::ios_base::failure&) {
    throw InvalidInput(context + "not valid BREP (truncated, or a malformed number near byte " +
                       std::to_string(std::max<long long>(0, static_cast<long long>(in.rdbuf()->pubseekoff(0, std::ios::cur, std::ios::in)))) + ")");
  } catch (const std::bad_alloc&) {
    throw InvalidInput(context + "not valid BREP (a count in it asks for more memory than there is)");
  }
  in.exceptions(std::ios::goodbit);
  return shape;
}

TopoDS_Shape read_brep_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput(path + ": cannot open for reading");
  if (!has_brep_header(in)) throw InvalidInput(path + ": not a BREP file (no 'CASCADE Topology' header)");
  const TopoDS_Shape shape = parse_brep(in, path + ": ");
  if (shape.IsNull()) throw InvalidInput(path + ": not a BREP file, or it holds no shape");
  return shape;
}

// ---- checking -------------------------------------------------------------------------------

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

std::string status_name(BRepCheck_Status status) {
  std::ostringstream s;
  BRepCheck::Print(status, s);
  std::string text = s.str();
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

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

// ---- geometry sanity ------------------------------------------------------------------------
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

void run_check(const DeferredCheck& check) {
  BRepCheck_Analyzer analyzer(check.solid);
  if (!analyzer.IsValid()) throw FailedBRepCheck(check.name + ": " + first_check_failure(check.solid, analyzer));
}

std::vector<TopoDS_Shell> sew_faces(const std::vector<TopoDS_Face>& faces, double relative_tolerance = 1e-6,
                                    double* used_tolerance = nullptr);
TopoDS_Solid solid_from_closed_shell(const TopoDS_Shell& shell);

// A solid whose one shell is open (its faces do not share their edges, or a gap lies between
// them) made of its faces sewn, at a millionth of its size as loose faces are, then at a
// ten-thousandth: a gap that size is far below any sample spacing, and the warning gives the
// tolerance that closed it. Null when sewing does not give one closed shell.
TopoDS_Solid sewn_solid(const TopoDS_Solid& solid, double& tolerance) {
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer ex(solid, TopAbs_FACE); ex.More(); ex.Next()) faces.push_back(TopoDS::Face(ex.Current()));
  for (double relative : {1e-6, 1e-4}) {
    try {
      const std::vector<TopoDS_Shell> shells = sew_faces(faces, relative, &tolerance);
      if (shells.size() == 1) return solid_from_closed_shell(shells.front());
      return TopoDS_Solid();  // several shells: sewing cannot tell which bound a void
    } catch (const InvalidInput&) {
      // still open, or non-manifold: try the wider tolerance
    } catch (const Standard_Failure&) {
      return TopoDS_Solid();  // sewing broke on its geometry (a curve of zero range): not healable
    }
  }
  return TopoDS_Solid();
}

TopoDS_Solid healed_or_refused(const TopoDS_Solid& solid, const std::string& name, const std::string& failure,
                               std::vector<std::string>* warnings);

// The checks of `solid` but BRepCheck's: every shell closed and manifold, a positive volume.
// Returns it, reversed when its volume came out negative (faces oriented inward). When `may_heal`,
// a solid whose shell is open is sewn, and one whose volume is zero (half of it inside out) is
// given to ShapeFix, each said in `warnings`. Throws InvalidInput naming the defect.
TopoDS_Solid closed_solid(TopoDS_Solid solid, const std::string& name, std::vector<std::string>* warnings,
                          bool may_heal) {
  TopTools_IndexedMapOfShape edge_index;
  TopExp::MapShapes(solid, TopAbs_EDGE, edge_index);
  int nshells = 0;
  std::string open;
  for (TopExp_Explorer sx(solid, TopAbs_SHELL); sx.More(); sx.Next()) {
    ++nshells;
    if (open.empty()) open = open_or_nonmanifold_edge(sx.Current(), edge_index);
  }
  if (nshells == 0) throw InvalidInput(name + ": has no shell (an empty solid)");
  if (!open.empty()) {
    double tolerance = 0;
    const TopoDS_Solid sewn = may_heal && nshells == 1 ? sewn_solid(solid, tolerance) : TopoDS_Solid();
    if (sewn.IsNull()) throw InvalidInput(name + ": " + open);
    solid = closed_solid(sewn, name, nullptr, false);
    if (warnings)
      warnings->push_back(name + ": " + open + "; closed by sewing its faces (tolerance " + message_number(tolerance) + ")");
    return solid;
  }

  // Orientation first: an inside-out solid (negative volume) is fixed by reversing it, and only
  // then checked, so that BRepCheck does not refuse it for its orientation.
  const double volume = signed_volume(solid);
  const double d = diagonal(solid);
  // Relative to the box: a volume this small against d^3 is a flat shape, or one whose parts
  // cancel out (half of it inside out: ShapeFix may orient its faces as one).
  const double tiny = 1e-12 * d * d * d;
  if (!std::isfinite(volume) || std::abs(volume) <= tiny) {
    const std::string failure = name + ": has zero volume (flat, or partly inside out)";
    if (!may_heal) throw InvalidInput(failure);
    return healed_or_refused(solid, name, failure, warnings);
  }
  if (volume < 0) solid.Reverse();
  return solid;
}

// What ShapeFix makes of `solid` (refused for `failure`, which names it) if that is one solid,
// closed, valid for BRepCheck and of the same size; said in `warnings`. Else throws InvalidInput
// with `failure` and why it could not be healed.
TopoDS_Solid healed_or_refused(const TopoDS_Solid& solid, const std::string& name, const std::string& failure,
                               std::vector<std::string>* warnings) {
  const HealedSolid healed = heal_solid(solid);
  std::string why_not = healed.fixes;
  if (!healed.solid.IsNull()) {
    try {
      const TopoDS_Solid fixed = closed_solid(healed.solid, name, nullptr, false);
      const BRepCheck_Analyzer again(fixed);
      const double d = diagonal(solid), d_fixed = diagonal(fixed);
      if (!again.IsValid()) {
        why_not = "still invalid after ShapeFix: " + first_check_failure(fixed, again);
      } else if (!(std::abs(d_fixed - d) <= 1e-3 * d)) {
        // Healing that moved the part's extent changed the part, not its representation.
        why_not = "ShapeFix changed its size (diagonal " + message_number(d) + " to " + message_number(d_fixed) + ")";
      } else {
        if (warnings)
          warnings->push_back(failure + "; healed by ShapeFix" + (healed.fixes.empty() ? "" : " (" + healed.fixes + ")"));
        return fixed;
      }
    } catch (const InvalidInput& e) {
      const std::string what = e.what(), prefix = name + ": ";
      why_not = "ShapeFix left it broken: " + (what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
    }
  }
  throw InvalidInput(failure + "; ShapeFix cannot heal it" + (why_not.empty() ? "" : " (" + why_not + ")"));
}

// `solid` if BRepCheck_Analyzer finds it valid, else healed_or_refused with BRepCheck's first
// complaint about the solid as given.
TopoDS_Solid valid_solid(const TopoDS_Solid& solid, const std::string& name, std::vector<std::string>* warnings) {
  const BRepCheck_Analyzer analyzer(solid);
  if (analyzer.IsValid()) return solid;
  return healed_or_refused(solid, name, name + ": " + first_check_failure(solid, analyzer), warnings);
}

// Checks a solid, healing it where OpenCASCADE can (closed_solid, valid_solid). BRepCheck_Analyzer's
// check is added to `deferred` when given, else run here.
TopoDS_Solid checked_solid(TopoDS_Solid solid, const std::string& name, std::vector<DeferredCheck>* deferred,
                           std::vector<std::string>* warnings) {
  solid = closed_solid(solid, name, warnings, true);
  if (!deferred) return valid_solid(solid, name, warnings);
  deferred->push_back({solid, name});
  return solid;
}

// check_geometry on `shape`; when it refuses a shape of several solids, on each of them: returns,
// per solid of `solids`, "" or why its own geometry is refused (its edges numbered over it).
// Throws check_geometry's refusal when the shape is one solid, or when the defect is not in the
// solids (a shell or face beside them), so that what was refused before still is.
std::vector<std::string> solids_with_broken_geometry(const TopoDS_Shape& shape, const std::vector<TopoDS_Solid>& solids,
                                                     const std::vector<TopoDS_Shell>& shells,
                                                     const std::vector<TopoDS_Face>& faces) {
  std::vector<std::string> why(solids.size());
  try {
    check_geometry(shape);
    return why;
  } catch (const InvalidInput&) {
    if (solids.size() < 2) throw;
    bool in_a_solid = false;
    for (std::size_t i = 0; i < solids.size(); ++i) {
      try {
        check_geometry(solids[i]);
      } catch (const InvalidInput& e) {
        why[i] = e.what();
        in_a_solid = true;
      }
    }
    BRep_Builder builder;
    TopoDS_Compound rest;
    builder.MakeCompound(rest);
    for (const TopoDS_Shell& s : shells) builder.Add(rest, s);
    for (const TopoDS_Face& f : faces) builder.Add(rest, f);
    bool rest_sane = true;
    try {
      check_geometry(rest);
    } catch (const InvalidInput&) {
      rest_sane = false;
    }
    if (!in_a_solid || !rest_sane) throw;
  }
  return why;
}

TopoDS_Solid solid_from_closed_shell(const TopoDS_Shell& shell) {
  // ShapeFix_Solid::SolidFromShell orients the shell so that the solid has its material inside.
  ShapeFix_Solid fix;
  TopoDS_Solid solid = fix.SolidFromShell(shell);
  if (solid.IsNull()) solid = BRepBuilderAPI_MakeSolid(shell).Solid();
  return solid;
}

// What a shape holds at its top level (inside compounds), sorted by kind.
struct Parts {
  std::vector<TopoDS_Solid> solids;
  std::vector<TopoDS_Shell> shells;
  std::vector<TopoDS_Face> faces;
  int loose_wires = 0, loose_edges = 0, loose_vertices = 0;
};

void collect(const TopoDS_Shape& shape, Parts& parts) {
  switch (shape.ShapeType()) {
    case TopAbs_COMPOUND:
    case TopAbs_COMPSOLID:
      for (TopoDS_Iterator it(shape); it.More(); it.Next()) collect(it.Value(), parts);
      break;
    case TopAbs_SOLID: parts.solids.push_back(TopoDS::Solid(shape)); break;
    case TopAbs_SHELL: parts.shells.push_back(TopoDS::Shell(shape)); break;
    case TopAbs_FACE: parts.faces.push_back(TopoDS::Face(shape)); break;
    case TopAbs_WIRE: ++parts.loose_wires; break;
    case TopAbs_EDGE: ++parts.loose_edges; break;
    case TopAbs_VERTEX: ++parts.loose_vertices; break;
    default: break;
  }
}

// Shells made by sewing the loose faces; throws when they do not close. `relative_tolerance` is
// against the faces' diagonal; the tolerance used goes to `used_tolerance` when given.
std::vector<TopoDS_Shell> sew_faces(const std::vector<TopoDS_Face>& faces, double relative_tolerance,
                                    double* used_tolerance) {
  BRep_Builder builder;
  TopoDS_Compound all;
  builder.MakeCompound(all);
  double max_tol = 0.0;
  for (const TopoDS_Face& f : faces) {
    builder.Add(all, f);
    for (TopExp_Explorer vx(f, TopAbs_VERTEX); vx.More(); vx.Next())
      max_tol = std::max(max_tol, BRep_Tool::Tolerance(TopoDS::Vertex(vx.Current())));
  }
  // The files' own tolerance (IGES readers set it from the file's resolution), and at least a
  // millionth of the size: gaps below that are round-off of the exporter, not holes.
  const double tol = std::max({1e-7, relative_tolerance * diagonal(all), 2.0 * max_tol});
  if (used_tolerance) *used_tolerance = tol;
  BRepBuilderAPI_Sewing sewing(tol);
  for (const TopoDS_Face& f : faces) sewing.Add(f);
  sewing.Perform();
  const bool one = faces.size() == 1;
  const std::string what = std::to_string(faces.size()) + (one ? " loose face" : " loose faces");
  if (sewing.NbFreeEdges() > 0)
    throw InvalidInput(what + " (not in any solid or shell)" + (one ? " does" : " do") + " not sew into closed shells: " +
                       std::to_string(sewing.NbFreeEdges()) + " edges stay open, e.g. one" +
                       edge_location(sewing.FreeEdge(1)));
  if (sewing.NbMultipleEdges() > 0)
    throw InvalidInput(what + " (not in any solid or shell) sew into a non-manifold shape: " +
                       std::to_string(sewing.NbMultipleEdges()) + " edges have more than two faces, e.g. one" +
                       edge_location(sewing.MultipleEdge(1)));
  Parts sewn;
  collect(sewing.SewedShape(), sewn);
  if (!sewn.faces.empty())
    throw InvalidInput(what + " (not in any solid or shell): " + std::to_string(sewn.faces.size()) +
                       " face(s) do not join any other after sewing");
  return sewn.shells;
}

}  // namespace

TopoDS_Shape read_shape_file(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string ext = lower(fs::path(path).extension().string());
  enum class Format { Step, Iges, Brep } format;
  if (ext == ".step" || ext == ".stp") format = Format::Step;
  else if (ext == ".iges" || ext == ".igs") format = Format::Iges;
  else if (ext == ".brep" || ext == ".brp") format = Format::Brep;
  else
    throw InvalidInput(path + ": unknown file type '" + ext +
                       "' (expected .step, .stp, .iges, .igs, .brep or .brp)");

  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InvalidInput(path + ": no such file");
  if (fs::is_directory(st)) throw InvalidInput(path + ": is a directory, not a file");
  if (fs::is_regular_file(st) && fs::file_size(path, ec) == 0 && !ec) throw InvalidInput(path + ": the file is empty");
  if (!std::ifstream(path)) throw InvalidInput(path + ": cannot open for reading (permissions?)");

  enable_reader_fault_recovery();
  try {
    OCC_CATCH_SIGNALS
    TopoDS_Shape shape;
    switch (format) {
      case Format::Step: shape = read_step(path); break;
      case Format::Iges: shape = read_iges(path); break;
      case Format::Brep: shape = read_brep_file(path); break;
    }
    if (shape.IsNull()) throw InvalidInput(path + ": the file holds no shape");
    return shape;
  } catch (const Standard_Failure& e) {
    throw InvalidInput(path + ": cannot read (broken or truncated file?): " + failure_text(e));
  } catch (const InvalidInput&) {
    throw;
  } catch (const std::exception& e) {
    throw InvalidInput(path + ": cannot read: " + e.what());
  }
}

TopoDS_Shape read_brep_string(const std::string& text) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InvalidInput("BREP text: it is empty");
  try {
    OCC_CATCH_SIGNALS
    std::istringstream in(text);
    if (!has_brep_header(in)) throw InvalidInput("BREP text: not BREP (no 'CASCADE Topology' header)");
    const TopoDS_Shape shape = parse_brep(in, "BREP text: ");
    if (shape.IsNull()) throw InvalidInput("BREP text: does not parse, or holds no shape");
    return shape;
  } catch (const Standard_Failure& e) {
    throw InvalidInput("BREP text: does not parse: " + failure_text(e));
  }
}

namespace {

std::vector<TopoDS_Solid> extract_solids(const TopoDS_Shape& shape, std::vector<std::string>* skipped,
                                         std::vector<DeferredCheck>* deferred, std::vector<std::string>* warnings) {
  if (shape.IsNull()) throw InvalidInput("the shape is empty (null)");
  enable_reader_fault_recovery();
  try {
    // A fault inside OpenCASCADE on broken geometry (sewing or checking a shape that the reader
    // left half-built) becomes a Standard_Failure, caught below (see enable_reader_fault_recovery).
    OCC_CATCH_SIGNALS
    Parts parts;
    collect(shape, parts);
    // Geometry no check may touch (the messages number its edges over the whole shape); in an
    // assembly, only the solids that hold it are left out (below).
    const std::vector<std::string> broken = solids_with_broken_geometry(shape, parts.solids, parts.shells, parts.faces);

    std::vector<TopoDS_Solid> solids;
    std::vector<std::string> open_parts;  // refused only when nothing else is there
    // Solids that cannot be healed: skipped beside others (an assembly with one empty solid is
    // still the other parts), refused when they are all there is. Each is numbered among all
    // the shape's solids, as FreeCAD numbers them, whether or not an earlier one was skipped.
    std::vector<std::string> rejected;
    int candidates = 0;
    auto add = [&](const TopoDS_Solid& solid, const std::string& origin) {
      const std::string name = "solid " + std::to_string(++candidates) + origin;
      try {
        solids.push_back(checked_solid(solid, name, deferred, warnings));
      } catch (const FailedBRepCheck&) {
        throw;
      } catch (const InvalidInput& e) {
        rejected.push_back(e.what());
      }
    };
    for (std::size_t i = 0; i < parts.solids.size(); ++i) {
      if (broken[i].empty()) {
        add(parts.solids[i], "");
      } else {
        rejected.push_back("solid " + std::to_string(++candidates) + ": " + broken[i]);
      }
    }

    // Shells that are not inside a solid: each must be closed; then it becomes a solid. STEP
    // exporters often write a part as a shell whose faces do not share their edges (each face has
    // its own copy): sewing closes such a shell, and only a shell that stays open is refused.
    for (std::size_t i = 0; i < parts.shells.size(); ++i) {
      TopTools_IndexedMapOfShape edge_index;
      TopExp::MapShapes(parts.shells[i], TopAbs_EDGE, edge_index);
      const std::string why = open_or_nonmanifold_edge(parts.shells[i], edge_index);
      if (!why.empty()) {
        std::vector<TopoDS_Face> faces;
        for (TopExp_Explorer ex(parts.shells[i], TopAbs_FACE); ex.More(); ex.Next()) faces.push_back(TopoDS::Face(ex.Current()));
        std::vector<TopoDS_Shell> sewn;
        try {
          sewn = sew_faces(faces);
        } catch (const InvalidInput&) {
          const std::string msg = "shell " + std::to_string(i + 1) + " (not a solid): " + why + "; sewing does not close it";
          open_parts.push_back(msg);
          continue;
        }
        for (const TopoDS_Shell& shell : sewn)
          add(solid_from_closed_shell(shell), " (sewn from shell " + std::to_string(i + 1) + ")");
        continue;
      }
      add(solid_from_closed_shell(parts.shells[i]), " (made from shell " + std::to_string(i + 1) + ")");
    }

    if (!parts.faces.empty()) {
      try {
        for (const TopoDS_Shell& shell : sew_faces(parts.faces)) add(solid_from_closed_shell(shell), " (sewn from loose faces)");
      } catch (const FailedBRepCheck&) {
        throw;
      } catch (const InvalidInput& e) {
        open_parts.push_back(e.what());
      }
    }
    if (!rejected.empty()) {
      if (solids.empty()) throw InvalidInput(rejected.front());
      if (warnings)
        for (const std::string& why : rejected)
          warnings->push_back(why + "; skipped: the axis is that of the other solids (the result numbers them without it)");
    }
    if (!open_parts.empty()) {
      if (solids.empty()) throw InvalidInput(open_parts.front());
      if (skipped) skipped->insert(skipped->end(), open_parts.begin(), open_parts.end());
    }

    if (solids.empty()) {
      std::string held;
      auto count = [&held](int n, const char* one, const char* many) {
        if (n == 0) return;
        held += (held.empty() ? "" : ", ") + std::to_string(n) + " " + (n == 1 ? one : many);
      };
      count(parts.loose_wires, "loose wire", "loose wires");
      count(parts.loose_edges, "loose edge", "loose edges");
      count(parts.loose_vertices, "loose vertex", "loose vertices");
      throw InvalidInput("holds no solid, closed shell or face" + (held.empty() ? std::string() : " (only " + held + ")"));
    }
    return solids;
  } catch (const Standard_Failure& e) {
    throw InvalidInput("checking the solids failed: " + failure_text(e));
  }
}

}  // namespace

std::vector<TopoDS_Solid> extract_solids(const TopoDS_Shape& shape, std::vector<std::string>* skipped,
                                         std::vector<std::string>* warnings) {
  return extract_solids(shape, skipped, nullptr, warnings);
}

std::vector<TopoDS_Solid> extract_solids(const TopoDS_Shape& shape, std::vector<std::string>* skipped,
                                         std::vector<DeferredCheck>& deferred, std::vector<std::string>* warnings) {
  return extract_solids(shape, skipped, &deferred, warnings);
}

void run_deferred_checks(const std::vector<DeferredCheck>& checks) {
  enable_reader_fault_recovery();
  try {
    OCC_CATCH_SIGNALS
    for (const DeferredCheck& check : checks) run_check(check);
  } catch (const Standard_Failure& e) {
    throw InvalidInput("checking the solids failed: " + failure_text(e));
  }
}

}  // namespace cadmedial
