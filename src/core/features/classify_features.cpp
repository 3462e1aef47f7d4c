#include "classify_features.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include "../errors.h"

namespace cadmedial {

const char* edge_kind_name(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::Smooth: return "smooth";
    case EdgeKind::Convex: return "convex";
    case EdgeKind::Concave: return "concave";
    case EdgeKind::Mixed: return "mixed";
    case EdgeKind::Seam: return "seam";
    case EdgeKind::Degenerate: return "degenerate";
  }
  return "?";
}

namespace {

constexpr double kPi = 3.14159265358979323846;
// How far inside a face (a fraction of its parameter range) the normal is taken when the face
// has none on the edge itself.
constexpr double kInset = 1e-4;

// The edge as it is traversed by the wires of `face` taken FORWARD: material lies on the left of
// its pcurve in the parameter plane, whatever the face's own orientation.
TopAbs_Orientation orientation_in_face(const TopoDS_Edge& edge, const TopoDS_Face& face) {
  for (TopExp_Explorer ex(face.Oriented(TopAbs_FORWARD), TopAbs_EDGE); ex.More(); ex.Next())
    if (ex.Current().IsSame(edge)) return ex.Current().Orientation();
  return TopAbs_FORWARD;
}

// BRepTools::UVBounds, NaN where it fails.
std::array<double, 4> uv_bounds(const TopoDS_Face& face) {
  try {
    std::array<double, 4> b{};
    BRepTools::UVBounds(face, b[0], b[1], b[2], b[3]);
    return b;
  } catch (const Standard_Failure&) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan};
  }
}

}  // namespace

std::array<double, 4> uv_bounds_of(const Features& features, int fi) {
  if (fi < static_cast<int>(features.face_uv_bounds.size()) && !std::isnan(features.face_uv_bounds[fi][0]))
    return features.face_uv_bounds[fi];
  std::array<double, 4> b{};
  BRepTools::UVBounds(TopoDS::Face(features.faces(fi + 1)), b[0], b[1], b[2], b[3]);
  return b;
}

EdgeGeometry::EdgeGeometry(const Features& features, int edge_index) : smooth_angle_deg_(features.smooth_angle_deg) {
  const TopoDS_Edge& edge = TopoDS::Edge(features.edges(edge_index + 1));
  double first = 0, last = 0;
  // BRep_Tool::Curve already applies the edge's location.
  curve_ = BRep_Tool::Curve(edge, first, last);
  for (int i = 0; i < 2; ++i) {
    const TopoDS_Face& face = TopoDS::Face(features.faces(features.edge_faces[edge_index][i] + 1));
    Side& side = side_[i];
    side.in_face = orientation_in_face(edge, face);
    side.face_reversed = face.Orientation() == TopAbs_REVERSED;
    const TopoDS_Face fwd = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    side.pcurve = BRep_Tool::CurveOnSurface(TopoDS::Edge(edge.Oriented(side.in_face)), fwd, first, last);
    side.surface = std::make_shared<BRepAdaptor_Surface>(fwd, Standard_False);
    // Only the inset normals need it: a face without bounds still has normals on its edges.
    const int fi = features.edge_faces[edge_index][i];
    const std::array<double, 4> b = fi < static_cast<int>(features.face_uv_bounds.size())
                                        ? features.face_uv_bounds[fi]
                                        : uv_bounds(fwd);
    side.uv_extent = std::isnan(b[0]) ? 0.0 : std::max(b[1] - b[0], b[3] - b[2]);
  }
}

EdgePoint EdgeGeometry::at(double t, double inset) const {
  EdgePoint ep;
  gp_Vec d1;
  if (!curve_.IsNull()) {
    gp_Pnt p;
    curve_->D1(t, p, d1);
    ep.point = p;
  }
  if (d1.Magnitude() < 1e-300) throw GeometryError("edge tangent undefined");
  ep.tangent = d1.Normalized();
  for (int i = 0; i < 2; ++i) {
    // The edge as the face's FORWARD wires traverse it: material lies on the left of its pcurve
    // in the parameter plane, whatever the face's own orientation.
    const Side& side = side_[i];
    if (side.pcurve.IsNull()) throw GeometryError("edge has no curve on its face");
    gp_Pnt2d uv;
    gp_Vec2d duv;
    side.pcurve->D1(t, uv, duv);
    const double sign = (side.in_face == TopAbs_REVERSED) ? -1.0 : 1.0;
    const gp_Vec2d left(-duv.Y() * sign, duv.X() * sign);
    gp_Pnt p;
    gp_Vec su, sv;
    side.surface->D1(uv.X(), uv.Y(), p, su, sv);
    // inset > 0: the normal and the inward direction are taken that far inside the face, across
    // the edge, where a collapsed boundary has a normal.
    if (inset > 0 && left.Magnitude() > 1e-300) {
      const gp_Vec2d step = left.Normalized() * (inset * side.uv_extent);
      gp_Pnt q;
      side.surface->D1(uv.X() + step.X(), uv.Y() + step.Y(), q, su, sv);
    }
    gp_Vec n = su.Crossed(sv);
    if (n.Magnitude() < 1e-300) throw GeometryError("face normal undefined on edge");
    n.Normalize();
    if (side.face_reversed) n.Reverse();
    gp_Vec in = su * left.X() + sv * left.Y();
    in -= ep.tangent * in.Dot(ep.tangent);
    in -= n * in.Dot(n);
    if (in.Magnitude() < 1e-300) throw GeometryError("face direction undefined on edge");
    ep.normal[i] = n;
    ep.inward[i] = in.Normalized();
    ep.uv[i] = uv;
    if (curve_.IsNull()) ep.point = p;
  }
  const double cosang = std::clamp(ep.normal[0].Dot(ep.normal[1]), -1.0, 1.0);
  const double angle = std::acos(cosang) * 180.0 / kPi;
  // Face 0 bends away from face 1's outward side at a convex edge: its inward direction points
  // against face 1's normal (and symmetrically).
  const double bend = ep.inward[0].Dot(ep.normal[1]) + ep.inward[1].Dot(ep.normal[0]);
  if (angle < smooth_angle_deg_) {
    ep.kind = PointKind::Smooth;
    ep.dihedral_deg = 180.0;
  } else if (bend < 0) {
    ep.kind = PointKind::Convex;
    ep.dihedral_deg = 180.0 - angle;
  } else {
    ep.kind = PointKind::Concave;
    ep.dihedral_deg = 180.0 + angle;
  }
  return ep;
}

EdgePoint edge_point(const Features& features, int edge_index, double t) {
  if (edge_index < static_cast<int>(features.edge_geometry.size()) && features.edge_geometry[edge_index])
    return features.edge_geometry[edge_index]->at(t);
  return EdgeGeometry(features, edge_index).at(t);
}

namespace {

// Votes of kPoints points along the edge; a point where a face's normal is undefined (the pole of a
// revolved face, a collapsed B-spline boundary) does not vote.
struct Votes {
  int convex = 0, concave = 0, defined = 0;
};

Votes vote_along(const EdgeGeometry& geometry, double first, double last, double inset) {
  // Ends and interior: an edge can change character along its length (a blend that runs out).
  constexpr int kPoints = 9;
  Votes votes;
  for (int i = 0; i < kPoints; ++i) {
    const double t = first + (last - first) * i / (kPoints - 1);
    PointKind k;
    try {
      k = geometry.at(t, inset).kind;
    } catch (const GeometryError&) {
      continue;
    }
    ++votes.defined;
    votes.convex += k == PointKind::Convex;
    votes.concave += k == PointKind::Concave;
  }
  return votes;
}

// Also makes the edge's geometry (f.edge_geometry[e]) for the later stages.
EdgeKind classify_edge(Features& f, int e) {
  const TopoDS_Edge& edge = TopoDS::Edge(f.edges(e + 1));
  if (BRep_Tool::Degenerated(edge)) return EdgeKind::Degenerate;
  if (f.edge_faces[e][0] == f.edge_faces[e][1]) {
    // The sampler asks a seam's normals too; where they cannot be had, it does without.
    try {
      f.edge_geometry[e] = std::make_shared<const EdgeGeometry>(f, e);
    } catch (const Standard_Failure&) {
    } catch (const GeometryError&) {
    }
    return EdgeKind::Seam;
  }
  double first = 0, last = 0;
  BRep_Tool::Range(edge, first, last);
  const auto geometry = std::make_shared<const EdgeGeometry>(f, e);
  f.edge_geometry[e] = geometry;
  Votes votes = vote_along(*geometry, first, last, 0.0);
  // No point of the edge has both normals (a face collapsed all along it): its character is the
  // limit of the normals just inside the faces.
  if (votes.defined == 0) votes = vote_along(*geometry, first, last, kInset);
  // Still none: nothing to tell a feature by; a smooth edge needs no normal downstream.
  if (votes.convex == 0 && votes.concave == 0) return EdgeKind::Smooth;
  if (votes.convex == votes.defined) return EdgeKind::Convex;
  if (votes.concave == votes.defined) return EdgeKind::Concave;
  return EdgeKind::Mixed;
}

// A singular vertex (cone apex): the end of a degenerate edge. The inner medial axis reaches it
// when the normals around it differ (not a smooth pole) and the surface around it is locally
// convex (an apex pointing out, not a pit).
bool singular_vertex_is_convex_corner(const Features& f, const TopoDS_Edge& degenerate, double smooth_angle_deg) {
  for (int fi = 1; fi <= f.faces.Extent(); ++fi) {
    const TopoDS_Face& face = TopoDS::Face(f.faces(fi));
    bool holds = false;
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More() && !holds; ex.Next()) holds = ex.Current().IsSame(degenerate);
    if (!holds) continue;
    const TopoDS_Face fwd = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    const TopAbs_Orientation ori = orientation_in_face(degenerate, face);
    double first = 0, last = 0;
    Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(TopoDS::Edge(degenerate.Oriented(ori)), fwd, first, last);
    if (pc.IsNull()) return false;
    BRepAdaptor_Surface surf(fwd, Standard_False);
    const double span = std::max({surf.LastUParameter() - surf.FirstUParameter(),
                                  surf.LastVParameter() - surf.FirstVParameter(), 1e-9});
    const double sign = (ori == TopAbs_REVERSED) ? -1.0 : 1.0;
    std::vector<gp_Pnt> pts;
    std::vector<gp_Vec> nrm;
    constexpr int kRing = 8;
    for (int i = 0; i < kRing; ++i) {
      const double t = first + (last - first) * (i + 0.5) / kRing;
      gp_Pnt2d uv;
      gp_Vec2d d;
      pc->D1(t, uv, d);
      if (d.Magnitude() < 1e-300) continue;
      const gp_Vec2d left = gp_Vec2d(-d.Y() * sign, d.X() * sign).Normalized();
      const gp_Pnt2d q(uv.X() + left.X() * 1e-3 * span, uv.Y() + left.Y() * 1e-3 * span);
      gp_Pnt p;
      gp_Vec su, sv;
      surf.D1(q.X(), q.Y(), p, su, sv);
      gp_Vec n = su.Crossed(sv);
      if (n.Magnitude() < 1e-300) continue;
      n.Normalize();
      if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
      pts.push_back(p);
      nrm.push_back(n);
    }
    if (pts.size() < 3) return false;
    double max_angle = 0;
    for (size_t i = 0; i < nrm.size(); ++i)
      for (size_t j = i + 1; j < nrm.size(); ++j)
        max_angle = std::max(max_angle, nrm[i].Angle(nrm[j]) * 180.0 / kPi);
    if (max_angle < smooth_angle_deg) return false;  // a smooth pole
    for (size_t i = 0; i < pts.size(); ++i)
      for (size_t j = 0; j < pts.size(); ++j)
        if (i != j && gp_Vec(pts[i], pts[j]).Dot(nrm[i]) > 1e-9 * pts[i].Distance(pts[j])) return false;
    return true;
  }
  return false;
}

}  // namespace

Features classify_features(const TopoDS_Solid& solid, double smooth_angle_deg) {
  Features f;
  f.smooth_angle_deg = smooth_angle_deg;
  TopExp::MapShapes(solid, TopAbs_FACE, f.faces);
  TopExp::MapShapes(solid, TopAbs_EDGE, f.edges);
  TopExp::MapShapes(solid, TopAbs_VERTEX, f.vertices);
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  f.face_uv_bounds.reserve(f.faces.Extent());
  for (int fi = 1; fi <= f.faces.Extent(); ++fi)
    f.face_uv_bounds.push_back(uv_bounds(TopoDS::Face(f.faces(fi).Oriented(TopAbs_FORWARD))));
  const int ne = f.edges.Extent();
  f.edge_faces.assign(ne, {-1, -1});
  f.edge_kind.assign(ne, EdgeKind::Smooth);
  f.edge_geometry.assign(ne, nullptr);
  for (int e = 0; e < ne; ++e) {
    const TopoDS_Shape& edge = f.edges(e + 1);
    const TopTools_ListOfShape& faces = edge_faces.FindFromKey(edge);
    int k = 0;
    for (const TopoDS_Shape& face : faces) {
      if (k < 2) f.edge_faces[e][k] = f.faces.FindIndex(face) - 1;
      ++k;
    }
    if (k == 1) f.edge_faces[e][1] = f.edge_faces[e][0];
    if (k == 0 || k > 2)
      throw InvalidInput("edge " + std::to_string(e + 1) + " is bounded by " + std::to_string(k) +
                         " faces: the solid is not a closed 2-manifold");
    try {
      f.edge_kind[e] = classify_edge(f, e);
    } catch (const Standard_Failure& err) {
      throw GeometryError("edge " + std::to_string(e + 1) + ": cannot classify: " + err.GetMessageString());
    } catch (const GeometryError& err) {
      throw GeometryError("edge " + std::to_string(e + 1) + ": cannot classify: " + err.what());
    }
  }

  const int nv = f.vertices.Extent();
  f.nonconcave_corner.assign(nv, false);
  f.sharp_vertex.assign(nv, false);
  TopTools_IndexedDataMapOfShapeListOfShape vertex_edges;
  TopExp::MapShapesAndUniqueAncestors(solid, TopAbs_VERTEX, TopAbs_EDGE, vertex_edges);
  for (int v = 0; v < nv; ++v) {
    const TopoDS_Vertex& vertex = TopoDS::Vertex(f.vertices(v + 1));
    if (!vertex_edges.Contains(vertex)) continue;
    bool convex = false, sharp = false;
    for (const TopoDS_Shape& s : vertex_edges.FindFromKey(vertex)) {
      const TopoDS_Edge& edge = TopoDS::Edge(s);
      const int e = f.edges.FindIndex(edge) - 1;
      const EdgeKind kind = f.edge_kind[e];
      if (kind == EdgeKind::Degenerate) {
        if (singular_vertex_is_convex_corner(f, edge, smooth_angle_deg)) convex = sharp = true;
        continue;
      }
      if (kind == EdgeKind::Seam || kind == EdgeKind::Smooth) continue;
      sharp = true;
      // The character of the edge at this vertex, not on average.
      const double t = BRep_Tool::Parameter(vertex, edge);
      try {
        if (f.edge_geometry[e]->at(t).kind == PointKind::Convex) convex = true;
      } catch (const GeometryError&) {
        if (kind == EdgeKind::Convex) convex = true;  // normal undefined at the end: the edge says
      }
    }
    f.nonconcave_corner[v] = convex;
    f.sharp_vertex[v] = sharp;
  }
  return f;
}

std::vector<std::array<int, 2>> convex_face_pairs(const Features& f) {
  std::vector<std::array<int, 2>> pairs;
  for (size_t e = 0; e < f.edge_kind.size(); ++e)
    if (f.edge_kind[e] == EdgeKind::Convex || f.edge_kind[e] == EdgeKind::Mixed) pairs.push_back(f.edge_faces[e]);
  return pairs;
}

}  // namespace cadmedial
