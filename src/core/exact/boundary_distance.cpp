#include "boundary_distance.h"
#include "box_tree.h"

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
#include <Extrema_LocateExtPC.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt2d.hxx>

#include "../sampling/lattice_classifier.h"
#include "../two_cores.h"

namespace cadmedial {

namespace {

Box box_of(const TopoDS_Shape& s, double enlarge) {
  Bnd_Box b;
  BRepBndLib::Add(s, b, false);  // from the geometry: a triangulation's box can fall short of it
  if (b.IsVoid()) return {1, 1, 1, -1, -1, -1};
  b.Enlarge(enlarge);
  Box out;
  b.Get(out[0], out[1], out[2], out[3], out[4], out[5]);
  return out;
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

namespace {

// Points of a curve or surface dense enough that every point of it is within `gap` of one: the
// distance to the nearest, less the gap, is a lower bound of the distance to the curve or
// surface (for a face: to its untrimmed surface, so to the face too). It spares most queries
// OpenCASCADE's search on the free-form faces and edges whose boxes hold the point but which are
// far from it: a screw's helical faces and edges have boxes as big as the screw (M6 screw: 38 s
// of 39 on the radii at 5,000 samples).
struct Cover {
  bool made = false;
  std::vector<Point3> points;
  std::vector<std::array<double, 2>> params;  // (u, v) of each point; a curve's in u
  int nu = 0, nv = 1;                         // points[i * nv + j]
  double gap = 0;

  // Blocks of bu x bv grid points with their boxes (index_blocks): a query looks only into the
  // blocks its bound reaches.
  struct Block {
    Box box;
    int i0, i1, j0, j1;  // points[i * nv + j], i0 <= i < i1, j0 <= j < j1
  };
  std::vector<Block> blocks;
  // Per query (one BoundaryDistance per thread): the distances in the blocks it reaches, the
  // others' infinite (farther than any point it reaches).
  mutable std::vector<double> d2;
  mutable std::vector<int> reached;

  void index_blocks() {
    const int bu = nv == 1 ? 32 : 8, bv = nv == 1 ? 1 : 8;
    blocks.clear();
    for (int i0 = 0; i0 < nu; i0 += bu)
      for (int j0 = 0; j0 < nv; j0 += bv) {
        Block b{{0, 0, 0, 0, 0, 0}, i0, std::min(i0 + bu, nu), j0, std::min(j0 + bv, nv)};
        const Point3& first = points[i0 * nv + j0];
        b.box = {first[0], first[1], first[2], first[0], first[1], first[2]};
        for (int i = b.i0; i < b.i1; ++i)
          for (int j = b.j0; j < b.j1; ++j)
            for (int k = 0; k < 3; ++k) {
              b.box[k] = std::min(b.box[k], points[i * nv + j][k]);
              b.box[k + 3] = std::max(b.box[k + 3], points[i * nv + j][k]);
            }
        blocks.push_back(b);
      }
    d2.assign(points.size(), std::numeric_limits<double>::infinity());
  }

  // The grid's local minima of the distance to p (each no farther than its neighbours) that may
  // beat best2 (may_beat), as (squared distance, point index), nearest first: where the local
  // search starts. A point out of that reach, or in a block out of it, is farther than every
  // point within it, so leaving it out changes no other point's verdict: the list is the full
  // one's head, which is all the callers read (they stop at the first that may not beat).
  std::vector<std::pair<double, int>> minima(const Point3& p, double best2) const {
    const double reach = std::sqrt(best2) + 2 * gap;
    const double reach2 = reach * reach;
    reached.clear();
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      if (!(sq_distance(blocks[b].box, p) < reach2)) continue;
      reached.push_back(static_cast<int>(b));
      for (int i = blocks[b].i0; i < blocks[b].i1; ++i)
        for (int j = blocks[b].j0; j < blocks[b].j1; ++j) {
          const Point3& q = points[i * nv + j];
          d2[i * nv + j] = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]);
        }
    }
    std::vector<std::pair<double, int>> out;
    for (int b : reached)
      for (int i = blocks[b].i0; i < blocks[b].i1; ++i)
        for (int j = blocks[b].j0; j < blocks[b].j1; ++j) {
          const double here = d2[i * nv + j];
          if (!(here < reach2)) continue;
          bool lowest = true;
          for (int di = -1; di <= 1 && lowest; ++di)
            for (int dj = -1; dj <= 1; ++dj) {
              const int a = i + di, c = j + dj;
              if ((di || dj) && a >= 0 && a < nu && c >= 0 && c < nv && d2[a * nv + c] < here) {
                lowest = false;
                break;
              }
            }
          if (lowest) out.push_back({here, i * nv + j});
        }
    for (int b : reached)
      for (int i = blocks[b].i0; i < blocks[b].i1; ++i)
        std::fill(d2.begin() + i * nv + blocks[b].j0, d2.begin() + i * nv + blocks[b].j1,
                  std::numeric_limits<double>::infinity());
    std::sort(out.begin(), out.end());
    return out;
  }
  // Whether a local minimum at squared distance d2 may hold a point nearer than sqrt(best2).
  bool may_beat(double d2, double best2) const {
    // Twice the gap: a curved cell's points can lie farther from its corners than its diagonal.
    const double d = std::sqrt(d2) - 2 * gap;
    return d <= 0 || d * d < best2;
  }
};

double distance(const Point3& a, const Point3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// A grid over the surface's parameter bounds; gap: the longest diagonal of a grid cell (a point
// of a cell is within it of the cell's corners while the cell is about flat). The grid follows
// the knot spans and is made finer until its cells are about a 40th of the face's size across
// (at most 256 x 256): the gap bounds which local minima are worth a search, and a helical face
// with cells 1.5 mm long had each point polish a minimum on every turn of the thread.
Cover surface_cover(const BRepAdaptor_Surface& s, double u0, double u1, double v0, double v1) {
  auto grid = [&](int nu, int nv) {
    Cover c;
    c.made = true;
    c.nu = nu;
    c.nv = nv;
    c.points.resize(static_cast<std::size_t>(nu * nv));
    c.params.resize(c.points.size());
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        const double u = u0 + (u1 - u0) * i / (nu - 1), v = v0 + (v1 - v0) * j / (nv - 1);
        c.points[i * nv + j] = to_point(s.Value(u, v));
        c.params[i * nv + j] = {u, v};
      }
    return c;
  };
  const int nu0 = std::clamp(4 * s.NbUIntervals(GeomAbs_C2) + 1, 25, 257);
  const int nv0 = std::clamp(4 * s.NbVIntervals(GeomAbs_C2) + 1, 25, 257);
  Cover c = grid(nu0, nv0);
  // The longest step along u and along v, and the face's size (its grid's box diagonal).
  double du = 0, dv = 0;
  Point3 lo = c.points[0], hi = c.points[0];
  for (int i = 0; i < nu0; ++i)
    for (int j = 0; j < nv0; ++j) {
      const Point3& q = c.points[i * nv0 + j];
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
      if (i + 1 < nu0) du = std::max(du, distance(q, c.points[(i + 1) * nv0 + j]));
      if (j + 1 < nv0) dv = std::max(dv, distance(q, c.points[i * nv0 + j + 1]));
    }
  const double target = distance(lo, hi) / 40.0;
  if (target > 0) {
    const int nu = std::clamp(static_cast<int>(std::ceil((nu0 - 1) * du / target)) + 1, nu0, 257);
    const int nv = std::clamp(static_cast<int>(std::ceil((nv0 - 1) * dv / target)) + 1, nv0, 257);
    if (nu > nu0 || nv > nv0) c = grid(nu, nv);
  }
  for (int i = 0; i + 1 < c.nu; ++i)
    for (int j = 0; j + 1 < c.nv; ++j)
      c.gap = std::max({c.gap, distance(c.points[i * c.nv + j], c.points[(i + 1) * c.nv + j + 1]),
                        distance(c.points[(i + 1) * c.nv + j], c.points[i * c.nv + j + 1])});
  return c;
}

// n points along the curve; gap: the longest chord (a point of an about straight piece is within
// half of it of an end).
Cover curve_cover(const BRepAdaptor_Curve& curve, double first, double last) {
  Cover c;
  c.made = true;
  const int n = std::clamp(8 * curve.NbIntervals(GeomAbs_C2) + 1, 65, 1025);
  c.nu = n;
  for (int i = 0; i < n; ++i) {
    const double u = first + (last - first) * i / (n - 1);
    c.points.push_back(to_point(curve.Value(u)));
    c.params.push_back({u, 0.0});
  }
  for (int i = 0; i + 1 < n; ++i) c.gap = std::max(c.gap, distance(c.points[i], c.points[i + 1]));
  return c;
}

}  // namespace

struct BoundaryDistance::Impl {

  struct Face {
    TopoDS_Face face;
    Box box;
    bool reversed = false;
    std::optional<gp_Pln> plane;  // the fast path: most faces of mechanical parts are planes
    // Made on first use: most faces are far from most points.
    std::unique_ptr<BRepAdaptor_Surface> surface;
    std::unique_ptr<Extrema_ExtPS> extrema;
    std::unique_ptr<BRepTopAdaptor_FClass2d> inside;
    std::unique_ptr<LatticeClassifier> answers;  // inside's answers without its scans
    Cover cover;  // a free-form face's lower bound, made on first use
  };
  struct Edge {
    TopoDS_Edge edge;
    Box box;
    double first = 0, last = 0;
    gp_Pnt ends[2];
    std::unique_ptr<BRepAdaptor_Curve> curve;
    std::unique_ptr<Extrema_ExtPC> extrema;
    Cover cover;  // a free-form edge's lower bound
    std::unique_ptr<Extrema_LocateExtPC> local;  // initialised once: its set-up samples the curve
  };
  std::vector<Face> faces;
  std::vector<Edge> edges;
  BoxTree face_tree, edge_tree;
  std::vector<int> candidates;  // scratch of nearest()

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
    std::vector<Box> boxes;
    for (const Face& f : faces) boxes.push_back(f.box);
    face_tree = BoxTree(boxes);
    boxes.clear();
    for (const Edge& e : edges) boxes.push_back(e.box);
    edge_tree = BoxTree(boxes);
  }

  BRepAdaptor_Surface& surface(Face& f) {
    if (!f.surface) f.surface = std::make_unique<BRepAdaptor_Surface>(f.face);
    return *f.surface;
  }

  bool in_face(Face& f, double u, double v) {
    if (!f.inside) {
      f.inside = std::make_unique<BRepTopAdaptor_FClass2d>(f.face, Precision::PConfusion());
      // A lattice of about 16 cells per wire over the face's bounds: a point in a cell no wire's
      // box reaches is answered by its region, without testing the wires. exact() alone tested
      // every wire for every point: a plate with 248 holes spent 49 s of 79 in the radii, most of
      // it there.
      double u0, u1, v0, v1;
      BRepTools::UVBounds(f.face, u0, u1, v0, v1);
      int wires = 0;
      for (TopExp_Explorer w(f.face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
      const long n = std::clamp(static_cast<long>(std::ceil(8.0 * std::sqrt(wires))), 1L, 256L);
      f.answers = std::make_unique<LatticeClassifier>(*f.inside, surface(f),
                                                      UvLattice{u0, v0, (u1 - u0) / n, (v1 - v0) / n, n, n});
    }
    const gp_Pnt2d uv(u, v);
    LatticeClassifier::Answer a = f.answers->classify(uv);
    if (a == LatticeClassifier::Answer::Ask) a = f.answers->exact(uv);
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
      if (f.extrema->IsDone()) take_extrema(i, *f.extrema, p, best2, out);
      return;
    }
    // A free-form surface: from each local minimum of the distance over its cover that may beat
    // the best so far, nearest first, a descent to the surface's local minimum. OpenCASCADE's
    // global search (Extrema_GenExtPS: a grid per point, every minimum polished) took 38 s of 39
    // on the M6 screw's helical faces at 5,000 samples; this takes half, with the same radii.
    if (!f.cover.made) {
      BRepAdaptor_Surface& s = surface(f);
      f.cover = surface_cover(s, s.FirstUParameter(), s.LastUParameter(), s.FirstVParameter(), s.LastVParameter());
      f.cover.index_blocks();
    }
    for (const auto& [d2, k] : f.cover.minima(p, best2)) {
      if (!f.cover.may_beat(d2, best2)) break;
      double u = f.cover.params[k][0], v = f.cover.params[k][1];
      const double q2 = descend(f, p, u, v);
      if (q2 >= best2 || !in_face(f, u, v)) continue;
      take_face_point(i, surface(f).Value(u, v), u, v, q2, p, best2, out);
    }
  }

  // The squared distance from p to f's surface, minimised from (u, v) (updated): damped Newton on
  // |S(u, v) - p|^2 within the parameter bounds, each step a descent (OpenCASCADE's locators
  // stopped at saddles of the distance, or gave up, where a medial ball touches a lofted face
  // almost along a curve and the distance is nearly flat).
  double descend(Face& f, const Point3& p, double& u, double& v) {
    BRepAdaptor_Surface& s = surface(f);
    const double u0 = s.FirstUParameter(), u1 = s.LastUParameter(), v0 = s.FirstVParameter(),
                 v1 = s.LastVParameter();
    auto value = [&](double a, double b) { return sq_dist(s.Value(a, b), p); };
    double f0 = value(u, v);
    for (int it = 0; it < 50; ++it) {
      gp_Pnt q;
      gp_Vec su, sv, suu, svv, suv;
      s.D2(u, v, q, su, sv, suu, svv, suv);
      const gp_Vec w(gp_Pnt(p[0], p[1], p[2]), q);  // S - p
      const double gu = w.Dot(su), gv = w.Dot(sv);
      double a = su.Dot(su) + w.Dot(suu), b = su.Dot(sv) + w.Dot(suv), c = sv.Dot(sv) + w.Dot(svv);
      // Not positive definite (a saddle or a ridge): shift towards steepest descent.
      const double scale = std::max(su.Dot(su) + sv.Dot(sv), 1e-300);
      double lambda = 0;
      const double det = a * c - b * b;
      if (a <= 0 || det <= 1e-12 * scale * scale) lambda = std::abs(std::min({a, c, 0.0})) + 1e-3 * scale;
      bool moved = false;
      for (int tries = 0; tries < 30 && !moved; ++tries) {
        const double A = a + lambda, C = c + lambda, D = A * C - b * b;
        if (D > 0) {
          double du = -(C * gu - b * gv) / D, dv = -(A * gv - b * gu) / D;
          const double nu = std::clamp(u + du, u0, u1), nv = std::clamp(v + dv, v0, v1);
          const double f1 = value(nu, nv);
          if (f1 < f0) {
            moved = true;
            const double step = std::abs(nu - u) + std::abs(nv - v);
            u = nu, v = nv;
            const bool settled = f0 - f1 <= 1e-15 * std::max(f0, 1e-300) ||
                                 step <= 1e-12 * (std::abs(u1 - u0) + std::abs(v1 - v0));
            f0 = f1;
            if (settled) return f0;
          }
        }
        lambda = lambda > 0 ? lambda * 4 : 1e-6 * scale;
      }
      if (!moved) break;  // no step lowers it: a minimum (or the bounds hold it)
    }
    return f0;
  }

  void take_face_point(int i, const gp_Pnt& q, double u, double v, double d2, const Point3& p, double& best2,
                       Nearest& out) {
    Face& f = faces[i];
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

  // The extrema of face i's surface nearer than sqrt(best2) and inside the face: updates best2 and
  // out. Returns false when the nearest extremum was nearer but outside the face.
  template <class Extrema>
  bool take_extrema(int i, Extrema& ext, const Point3& p, double& best2, Nearest& out) {
    Face& f = faces[i];
    bool settled = true;
    for (int k = 1; k <= ext.NbExt(); ++k) {
      const double d2 = ext.SquareDistance(k);
      double u, v;
      ext.Point(k).Parameter(u, v);
      if (d2 >= best2) continue;
      if (!in_face(f, u, v)) {
        settled = false;
        continue;
      }
      take_face_point(i, ext.Point(k).Value(), u, v, d2, p, best2, out);
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
    // Lines and circles are cheap to ask globally. Other curves: from each local minimum of the
    // distance over the cover that may beat the best, OpenCASCADE's local search
    // (Extrema_ExtPC sampled the whole curve again for every point).
    if (e.curve->GetType() != GeomAbs_Line && e.curve->GetType() != GeomAbs_Circle) {
      if (!e.cover.made) {
        e.cover = curve_cover(*e.curve, e.first, e.last);
        e.cover.index_blocks();
        e.local = std::make_unique<Extrema_LocateExtPC>();
        e.local->Initialize(*e.curve, e.first, e.last, Precision::PConfusion());
      }
      for (const auto& [d2, k] : e.cover.minima(p, best2)) {
        if (!e.cover.may_beat(d2, best2)) break;
        take(gp_Pnt(e.cover.points[k][0], e.cover.points[k][1], e.cover.points[k][2]));
        e.local->Perform(gp, e.cover.params[k][0]);
        if (e.local->IsDone()) take(e.local->Point().Value());
      }
      return;
    }
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
    // The boxes within the bound, from the trees, then asked in index order as the bound
    // shrinks: the same answer as a scan of every box.
    edge_tree.near(p, best2, candidates);
    for (int i : candidates)
      if (sq_distance(edges[i].box, p) < best2) ask_edge(i, p, best2, out);
    face_tree.near(p, best2, candidates);
    for (int i : candidates)
      if (sq_distance(faces[i].box, p) < best2) ask_face(i, p, best2, out);
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
  const std::vector<int> todo = mesh.vertices_of_solid(solid_index);
  st.vertices = todo.size();
  if (todo.empty()) return st;

  // A sample lies on the boundary within the faces' tolerance: the nearest sample's distance,
  // a little enlarged, bounds the distance to the boundary.
  const double slack = 1e-9 * diag;
  std::vector<double> excess(todo.size(), 0.0);
  std::vector<std::uint8_t> moved(todo.size(), 0);
  BoundaryDistance dist[2] = {BoundaryDistance(solid), BoundaryDistance(solid)};
  // Every other vertex on each thread: the costly ones (near free-form faces) lie together, and
  // halves left one thread with most of them (M6 screw: one core busy).
  internal::on_two_halves(todo.size(), [&](int part, std::size_t, std::size_t) {
    for (std::size_t k = static_cast<std::size_t>(part); k < todo.size(); k += 2) {
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
