#include "boundary_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <ElSLib.hxx>
#include <Extrema_ExtPC.hxx>
#include <Extrema_ExtPS.hxx>
#include <Extrema_GenExtPS.hxx>
#include <Extrema_GenLocateExtPS.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt2d.hxx>

#include "../sampling/lattice_classifier.h"
#include "../two_cores.h"

namespace cadmedial {

namespace {

using Box = std::array<double, 6>;  // min x y z, max x y z

Box box_of(const TopoDS_Shape& s, double enlarge) {
  Bnd_Box b;
  BRepBndLib::Add(s, b, false);  // from the geometry: a triangulation's box can fall short of it
  if (b.IsVoid()) return {1, 1, 1, -1, -1, -1};
  b.Enlarge(enlarge);
  Box out;
  b.Get(out[0], out[1], out[2], out[3], out[4], out[5]);
  return out;
}

// Squared distance from p to the box (0 inside); infinite for an empty box.
double sq_distance(const Box& b, const Point3& p) {
  if (b[0] > b[3]) return std::numeric_limits<double>::infinity();
  double s = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = std::max({b[k] - p[k], 0.0, p[k] - b[k + 3]});
    s += d * d;
  }
  return s;
}

double sq_dist(const gp_Pnt& a, const Point3& p) {
  const double dx = a.X() - p[0], dy = a.Y() - p[1], dz = a.Z() - p[2];
  return dx * dx + dy * dy + dz * dz;
}

// The plane's normal as its parametrisation orients it (du x dv): on a left-handed frame that is
// the opposite of the frame's main direction.
gp_Dir surface_normal(const gp_Pln& pln) {
  const gp_Ax3& ax = pln.Position();
  return ax.Direct() ? ax.Direction() : ax.Direction().Reversed();
}

bool is_elementary(GeomAbs_SurfaceType t) {
  return t == GeomAbs_Plane || t == GeomAbs_Cylinder || t == GeomAbs_Cone || t == GeomAbs_Sphere ||
         t == GeomAbs_Torus;
}

Point3 to_point(const gp_Pnt& a) { return {a.X(), a.Y(), a.Z()}; }

}  // namespace

struct BoundaryDistance::Impl {
  static constexpr int kGrid = 12;  // a free-form face's search grid, per direction

  struct Face {
    TopoDS_Face face;
    Box box;
    bool reversed = false;
    std::optional<gp_Pln> plane;  // the fast path: most faces of mechanical parts are planes
    // Made on first use: most faces are far from most points.
    std::unique_ptr<BRepAdaptor_Surface> surface;
    std::unique_ptr<Extrema_ExtPS> extrema;
    std::unique_ptr<Extrema_GenExtPS> free_form;
    std::unique_ptr<BRepTopAdaptor_FClass2d> inside;
    std::unique_ptr<LatticeClassifier> answers;  // inside's answers without its scans
  };
  struct Edge {
    TopoDS_Edge edge;
    Box box;
    double first = 0, last = 0;
    gp_Pnt ends[2];
    std::unique_ptr<BRepAdaptor_Curve> curve;
    std::unique_ptr<Extrema_ExtPC> extrema;
  };
  std::vector<Face> faces;
  std::vector<Edge> edges;

  explicit Impl(const TopoDS_Solid& solid) {
    TopTools_IndexedMapOfShape fmap, emap;
    TopExp::MapShapes(solid, TopAbs_FACE, fmap);
    TopExp::MapShapes(solid, TopAbs_EDGE, emap);
    faces.resize(fmap.Extent());
    for (int i = 1; i <= fmap.Extent(); ++i) {
      Face& f = faces[i - 1];
      f.face = TopoDS::Face(fmap(i));
      f.box = box_of(f.face, BRep_Tool::Tolerance(f.face));
      f.reversed = f.face.Orientation() == TopAbs_REVERSED;
      BRepAdaptor_Surface s(f.face, false);
      if (s.GetType() == GeomAbs_Plane) f.plane = s.Plane();
    }
    for (int i = 1; i <= emap.Extent(); ++i) {
      const TopoDS_Edge& e = TopoDS::Edge(emap(i));
      if (BRep_Tool::Degenerated(e)) continue;  // a point, which its other edges end at
      Edge ed;
      ed.edge = e;
      ed.box = box_of(e, BRep_Tool::Tolerance(e));
      BRep_Tool::Range(e, ed.first, ed.last);
      edges.push_back(std::move(ed));
    }
  }

  BRepAdaptor_Surface& surface(Face& f) {
    if (!f.surface) f.surface = std::make_unique<BRepAdaptor_Surface>(f.face);
    return *f.surface;
  }

  bool in_face(Face& f, double u, double v) {
    if (!f.inside) {
      f.inside = std::make_unique<BRepTopAdaptor_FClass2d>(f.face, Precision::PConfusion());
      // One lattice cell over the face's bounds: exact() needs no finer one.
      double u0, u1, v0, v1;
      BRepTools::UVBounds(f.face, u0, u1, v0, v1);
      f.answers = std::make_unique<LatticeClassifier>(*f.inside, surface(f), UvLattice{u0, v0, u1 - u0, v1 - v0, 1, 1});
    }
    const gp_Pnt2d uv(u, v);
    const LatticeClassifier::Answer a = f.answers->exact(uv);
    if (a != LatticeClassifier::Answer::Ask) return a == LatticeClassifier::Answer::In;
    const TopAbs_State s = f.inside->Perform(uv);
    return s == TopAbs_IN || s == TopAbs_ON;
  }

  // Outer normal at parameters (u, v) of f.
  Point3 normal_at(Face& f, double u, double v) {
    gp_Pnt q;
    gp_Vec du, dv;
    surface(f).D1(u, v, q, du, dv);
    gp_Vec n = du.Crossed(dv);
    const double len = n.Magnitude();
    if (len < 1e-300) return {0, 0, 0};
    n /= len;
    if (f.reversed) n.Reverse();
    return {n.X(), n.Y(), n.Z()};
  }

  // The nearest point of f's interior to p closer than sqrt(best2), if any: updates best2 and out.
  void ask_face(int i, const Point3& p, double& best2, Nearest& out) {
    Face& f = faces[i];
    const gp_Pnt gp(p[0], p[1], p[2]);
    if (f.plane) {
      const gp_Ax3& ax = f.plane->Position();
      const gp_Dir n = surface_normal(*f.plane);
      const double s = (p[0] - ax.Location().X()) * n.X() + (p[1] - ax.Location().Y()) * n.Y() +
                       (p[2] - ax.Location().Z()) * n.Z();
      if (s * s >= best2) return;
      double u, v;
      ElSLib::Parameters(*f.plane, gp, u, v);
      if (!in_face(f, u, v)) return;
      best2 = s * s;
      out.point = {p[0] - s * n.X(), p[1] - s * n.Y(), p[2] - s * n.Z()};
      out.face = i;
      out.edge = -1;
      // n is the plane's normal; the face's outer normal is n, or -n on a reversed face.
      const double outer = f.reversed ? -s : s;
      out.side = outer > 0 ? 1 : (outer < 0 ? -1 : 0);
      out.uv = {u, v};
      const double k = f.reversed ? -1.0 : 1.0;
      out.normal = {k * n.X(), k * n.Y(), k * n.Z()};
      return;
    }
    if (is_elementary(surface(f).GetType())) {
      if (!f.extrema) {
        BRepAdaptor_Surface& s = surface(f);
        f.extrema = std::make_unique<Extrema_ExtPS>();
        f.extrema->Initialize(s, s.FirstUParameter(), s.LastUParameter(), s.FirstVParameter(),
                              s.LastVParameter(), Precision::PConfusion(), Precision::PConfusion());
      }
      f.extrema->Perform(gp);
      if (f.extrema->IsDone()) take_extrema(i, *f.extrema, false, gp, p, best2, out);
      return;
    }
    // A free-form surface: every local minimum from a coarse grid (OpenCASCADE's default grid
    // computes 32 x 32 distances a point, 60 % of the time on SOT23's B-spline faces; its tree
    // search gives one local minimum, not always the nearest: 1.3e-3 off on the B-spline loft),
    // each polished by Newton on the distance.
    if (!f.free_form) {
      BRepAdaptor_Surface& s = surface(f);
      f.free_form = std::make_unique<Extrema_GenExtPS>();
      f.free_form->SetFlag(Extrema_ExtFlag_MIN);
      f.free_form->Initialize(s, kGrid, kGrid, s.FirstUParameter(), s.LastUParameter(), s.FirstVParameter(),
                              s.LastVParameter(), Precision::PConfusion(), Precision::PConfusion());
    }
    f.free_form->Perform(gp);
    if (f.free_form->IsDone()) take_extrema(i, *f.free_form, true, gp, p, best2, out);
  }

  // The extrema of face i's surface nearer than sqrt(best2) and inside the face: updates best2 and
  // out. Returns false when the nearest extremum was nearer but outside the face.
  template <class Extrema>
  bool take_extrema(int i, Extrema& ext, bool polish, const gp_Pnt& gp, const Point3& p, double& best2,
                    Nearest& out) {
    Face& f = faces[i];
    bool settled = true;
    for (int k = 1; k <= ext.NbExt(); ++k) {
      double d2 = ext.SquareDistance(k);
      double u, v;
      ext.Point(k).Parameter(u, v);
      gp_Pnt q = ext.Point(k).Value();
      if (polish) {
        // A grid's nearest point, refined: Newton on the distance from there settles it.
        Extrema_GenLocateExtPS local(surface(f), Precision::PConfusion(), Precision::PConfusion());
        local.Perform(gp, u, v, Standard_True);
        if (local.IsDone() && local.SquareDistance() < d2) {
          d2 = local.SquareDistance();
          local.Point().Parameter(u, v);
          q = local.Point().Value();
        }
      }
      if (d2 >= best2) continue;
      if (!in_face(f, u, v)) {
        settled = false;
        continue;
      }
      best2 = d2;
      out.point = to_point(q);
      out.face = i;
      out.edge = -1;
      const Point3 n = normal_at(f, u, v);
      const double outer = (p[0] - q.X()) * n[0] + (p[1] - q.Y()) * n[1] + (p[2] - q.Z()) * n[2];
      out.side = outer > 0 ? 1 : (outer < 0 ? -1 : 0);
      out.uv = {u, v};
      out.normal = n;
    }
    return settled;
  }

  void ask_edge(int i, const Point3& p, double& best2, Nearest& out) {
    Edge& e = edges[i];
    if (!e.curve) {
      e.curve = std::make_unique<BRepAdaptor_Curve>(e.edge);
      e.ends[0] = e.curve->Value(e.first);
      e.ends[1] = e.curve->Value(e.last);
      e.extrema = std::make_unique<Extrema_ExtPC>();
      e.extrema->Initialize(*e.curve, e.first, e.last, Precision::PConfusion());
    }
    auto take = [&](const gp_Pnt& q) {
      const double d2 = sq_dist(q, p);
      if (d2 >= best2) return;
      best2 = d2;
      out.point = to_point(q);
      out.face = -1;
      out.edge = i;
      out.side = 0;
    };
    take(e.ends[0]);
    take(e.ends[1]);
    const gp_Pnt gp(p[0], p[1], p[2]);
    e.extrema->Perform(gp);
    if (!e.extrema->IsDone()) return;
    for (int k = 1; k <= e.extrema->NbExt(); ++k)
      if (e.extrema->SquareDistance(k) < best2) take(e.extrema->Point(k).Value());
  }

  Nearest nearest(const Point3& p, double bound) {
    Nearest out;
    double best2 = bound * bound;
    // Edges first: a point near a convex edge, where most radii are off, settles there, and the
    // smaller bound spares most faces their projection.
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (sq_distance(edges[i].box, p) < best2) ask_edge(static_cast<int>(i), p, best2, out);
    for (std::size_t i = 0; i < faces.size(); ++i)
      if (sq_distance(faces[i].box, p) < best2) ask_face(static_cast<int>(i), p, best2, out);
    out.distance = std::sqrt(best2);
    if (out.face < 0 && out.edge < 0) out.point = p;
    return out;
  }
};

BoundaryDistance::BoundaryDistance(const TopoDS_Solid& solid) : impl_(std::make_unique<Impl>(solid)) {}
BoundaryDistance::~BoundaryDistance() = default;

BoundaryDistance::Nearest BoundaryDistance::nearest(const Point3& p, double bound) { return impl_->nearest(p, bound); }

Point3 BoundaryDistance::normal(int face, const Point3& point) {
  Impl::Face& f = impl_->faces.at(static_cast<std::size_t>(face));
  if (f.plane) {
    gp_Dir n = surface_normal(*f.plane);
    if (f.reversed) n.Reverse();
    return {n.X(), n.Y(), n.Z()};
  }
  BRepAdaptor_Surface& s = impl_->surface(f);
  Extrema_ExtPS ext(gp_Pnt(point[0], point[1], point[2]), s, Precision::PConfusion(), Precision::PConfusion());
  if (!ext.IsDone() || ext.NbExt() == 0) return {0, 0, 0};
  int best = 1;
  for (int k = 2; k <= ext.NbExt(); ++k)
    if (ext.SquareDistance(k) < ext.SquareDistance(best)) best = k;
  double u, v;
  ext.Point(best).Parameter(u, v);
  return impl_->normal_at(f, u, v);
}

std::size_t BoundaryDistance::num_faces() const { return impl_->faces.size(); }
int BoundaryDistance::face_index(int face) const { return face; }

ExactRadiiStats exact_radii(const TopoDS_Solid& solid, int solid_index, double diag, MedialMesh& mesh) {
  ExactRadiiStats st;
  std::vector<std::uint8_t> mine(mesh.num_vertices(), 0);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f)
    if (mesh.solid[f] == solid_index)
      for (int k = 0; k < mesh.face_size(f); ++k) mine[mesh.face(f)[k]] = 1;
  for (std::size_t e = 0; e < mesh.num_edges(); ++e)
    if (mesh.edge_solid[e] == solid_index) mine[mesh.edges[e][0]] = mine[mesh.edges[e][1]] = 1;
  std::vector<int> todo;
  for (std::size_t v = 0; v < mine.size(); ++v)
    if (mine[v]) todo.push_back(static_cast<int>(v));
  st.vertices = todo.size();
  if (todo.empty()) return st;

  // A sample lies on the boundary within the faces' tolerance: the nearest sample's distance,
  // a little enlarged, bounds the distance to the boundary.
  const double slack = 1e-9 * diag;
  std::vector<double> excess(todo.size(), 0.0);
  std::vector<std::uint8_t> moved(todo.size(), 0);
  BoundaryDistance dist[2] = {BoundaryDistance(solid), BoundaryDistance(solid)};
  internal::on_two_halves(todo.size(), [&](int part, std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const int v = todo[k];
      const double r = mesh.radius[v];
      const BoundaryDistance::Nearest n = dist[part].nearest(mesh.vertices[v], r + 2 * slack);
      if (n.side > 0 && n.distance > slack) {
        // Outside the solid: its ball is not inside at all. On the boundary it is a ball of 0.
        mesh.vertices[v] = n.point;
        mesh.radius[v] = 0;
        moved[k] = 1;
        excess[k] = r;
        continue;
      }
      excess[k] = std::max(0.0, r - n.distance);
      mesh.radius[v] = std::min(r, n.distance);
    }
  }, 64);
  double sum = 0;
  for (std::size_t k = 0; k < todo.size(); ++k) {
    sum += excess[k];
    st.max_excess = std::max(st.max_excess, excess[k]);
    st.corrected += excess[k] > slack;
    st.moved_inside += moved[k];
  }
  st.mean_excess = sum / static_cast<double>(todo.size());
  return st;
}

}  // namespace cadmedial
