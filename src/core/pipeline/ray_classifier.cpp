#include "ray_classifier.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Extrema_ExtPC.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Lin.hxx>
#include <gp_Pnt2d.hxx>

#include "../sampling/lattice_classifier.h"

namespace cadmedial::internal {

namespace {

// Directions spread over the sphere (a golden-angle spiral) and turned off the axes, so that a ray
// is seldom parallel to a plane face or along an edge of a part drawn on the axes.
constexpr int kDirections = 8;
const std::array<std::array<double, 3>, kDirections>& directions() {
  static const auto dirs = [] {
    std::array<std::array<double, 3>, kDirections> out{};
    for (int k = 0; k < kDirections; ++k) {
      const double z = 1.0 - (2.0 * k + 1.0) / kDirections;
      const double r = std::sqrt(1.0 - z * z);
      const double phi = 2.399963229728653 * k + 0.3183098861837907;
      // A fixed tilt about x and y takes the spiral off the axes.
      double d[3] = {r * std::cos(phi), r * std::sin(phi), z};
      const double a = 0.1234567, b = 0.2718281;
      const double y1 = d[1] * std::cos(a) - d[2] * std::sin(a), z1 = d[1] * std::sin(a) + d[2] * std::cos(a);
      const double x2 = d[0] * std::cos(b) + z1 * std::sin(b), z2 = -d[0] * std::sin(b) + z1 * std::cos(b);
      out[k] = {x2, y1, z2};
    }
    return out;
  }();
  return dirs;
}

// Where the ray p + t d enters the box (t >= -tol), or false when it misses.
bool enters(const std::array<double, 6>& box, const std::array<double, 3>& p, const std::array<double, 3>& d,
            double tol, double& t_in, double& t_out) {
  double lo = -tol, hi = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (p[k] < box[k] || p[k] > box[k + 3]) return false;
      continue;
    }
    double t0 = (box[k] - p[k]) / d[k], t1 = (box[k + 3] - p[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
    if (lo > hi) return false;
  }
  t_in = lo, t_out = hi;
  return true;
}

}  // namespace

RayClassifier::RayClassifier(const TopoDS_Solid& solid, double tol) : tol_(tol) {
  double largest_tolerance = 0;
  Bnd_Box all;
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& f = TopoDS::Face(e.Current());
    Bnd_Box box;
    BRepBndLib::Add(f, box, false);  // from the geometry: a triangulation's box can be short of it
    if (box.IsVoid()) continue;
    faces_.push_back(f);
    all.Add(box);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    boxes_.push_back({x0, y0, z0, x1, y1, z1});
  }
  for (TopExp_Explorer e(solid, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    if (BRep_Tool::Degenerated(edge)) continue;
    const double t = std::max(BRep_Tool::Tolerance(edge), tol);
    largest_tolerance = std::max(largest_tolerance, t);
    Bnd_Box box;
    BRepBndLib::Add(edge, box, false);  // with the edge's tolerance
    if (box.IsVoid()) continue;
    box.Enlarge(tol);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    edges_.push_back(edge);
    edge_boxes_.push_back({x0, y0, z0, x1, y1, z1});
  }
  const double diag = all.IsVoid() ? 0.0 : std::sqrt(all.SquareExtent());
  // Two faces' crossings where a ray passes through their common edge differ by up to the edge's
  // tolerance; 1e-5 of the part's size keeps them one crossing on precise parts too.
  margin_ = std::max({1e-5 * diag, 4 * largest_tolerance, 10 * tol});
  reach_ = 4 * diag + 1;
  for (auto& b : boxes_)
    for (int k = 0; k < 3; ++k) b[k] -= margin_, b[k + 3] += margin_;
  intersectors_.resize(faces_.size());
  boundaries_.resize(faces_.size());
  boundary_answers_.resize(faces_.size());
}

RayClassifier::~RayClassifier() = default;

IntCurvesFace_Intersector& RayClassifier::intersector(int face) {
  if (!intersectors_[face])
    intersectors_[face] = std::make_unique<IntCurvesFace_Intersector>(faces_[face], tol_, true, false);
  return *intersectors_[face];
}

bool RayClassifier::on_edge(const std::array<double, 3>& p) const {
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const auto& b = edge_boxes_[e];
    if (p[0] < b[0] || p[1] < b[1] || p[2] < b[2] || p[0] > b[3] || p[1] > b[4] || p[2] > b[5]) continue;
    const gp_Pnt x(p[0], p[1], p[2]);
    const double t = std::max(BRep_Tool::Tolerance(edges_[e]), tol_);
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(edges_[e], v0, v1);
    for (const TopoDS_Vertex& v : {v0, v1})
      if (!v.IsNull() && BRep_Tool::Pnt(v).Distance(x) <= std::max(t, BRep_Tool::Tolerance(v))) return true;
    const BRepAdaptor_Curve curve(edges_[e]);
    Extrema_ExtPC near(x, curve);
    if (!near.IsDone()) continue;
    for (int i = 1; i <= near.NbExt(); ++i)
      if (near.SquareDistance(i) <= t * t) return true;
  }
  return false;
}

bool RayClassifier::near_boundary(int face, double u, double v) {
  if (!boundaries_[face] || !boundary_answers_[face]) {
    // Both or neither: OpenCASCADE may fail on the face between the two (the call is then refused).
    const BRepAdaptor_Surface surface(faces_[face], false);
    const double uv = std::max(surface.UResolution(margin_), surface.VResolution(margin_));
    auto boundary = std::make_unique<BRepTopAdaptor_FClass2d>(faces_[face], uv);
    // One lattice cell over the face's bounds: exact() needs no finer one.
    double u0, u1, v0, v1;
    BRepTools::UVBounds(faces_[face], u0, u1, v0, v1);
    auto answers = std::make_unique<LatticeClassifier>(*boundary, surface, UvLattice{u0, v0, u1 - u0, v1 - v0, 1, 1});
    boundaries_[face] = std::move(boundary);
    boundary_answers_[face] = std::move(answers);
  }
  // Perform's answer: from the polygons near (u, v), or from Perform within their tolerance.
  const gp_Pnt2d uv(u, v);
  const LatticeClassifier::Answer a = boundary_answers_[face]->exact(uv);
  if (a != LatticeClassifier::Answer::Ask) return a != LatticeClassifier::Answer::In;
  return boundaries_[face]->Perform(uv) != TopAbs_IN;
}

RayClassifier::Answer RayClassifier::cast(const std::array<double, 3>& p, const std::array<double, 3>& d) {
  order_.clear();
  double far = 0;
  for (int f = 0; f < static_cast<int>(boxes_.size()); ++f) {
    double t_in, t_out;
    if (!enters(boxes_[f], p, d, tol_, t_in, t_out)) continue;
    order_.push_back({t_in, f});
    far = std::max(far, t_out);
  }
  if (order_.empty()) return Answer::Outside;
  std::sort(order_.begin(), order_.end());
  const gp_Lin line(gp_Pnt(p[0], p[1], p[2]), gp_Dir(d[0], d[1], d[2]));
  struct Crossing {
    double w;
    bool clean;   // inside the face (not on its boundary), not tangent
    bool leaves;  // from inside the solid to outside
    int face;
    double u, v;
  };
  std::vector<Crossing> crossings;
  double first = std::min(far, reach_) + margin_;
  for (const auto& [t_in, f] : order_) {
    if (t_in > first + margin_) break;  // boxes nearest first: no later face crosses sooner
    IntCurvesFace_Intersector& x = intersector(f);
    // A little longer both ways, as OpenCASCADE's classifier does: on a face intersected through
    // a polyhedron, a crossing near an end of the segment can be missed.
    const double extra = std::max(10 * tol_, 0.01 * first);
    x.Perform(line, -extra, first + margin_ + extra);
    if (!x.IsDone() || (x.NbPnt() == 0 && x.IsParallel())) return Answer::Unknown;
    for (int i = 1; i <= x.NbPnt(); ++i) {
      const double w = x.WParameter(i);
      if (w < -tol_) continue;                         // behind the point
      if (std::abs(w) <= tol_) return Answer::Inside;  // on the boundary
      const IntCurveSurface_TransitionOnCurve tr = x.Transition(i);
      crossings.push_back({w, x.State(i) == TopAbs_IN && tr != IntCurveSurface_Tangent, tr == IntCurveSurface_Out, f,
                           x.UParameter(i), x.VParameter(i)});
      first = std::min(first, w);
    }
  }
  if (crossings.empty()) return Answer::Outside;
  // The first crossing decides when it is clean and nothing within the margin of it says
  // otherwise (a ray through an edge or a vertex crosses two or more faces there).
  int leaves = -1;
  for (const Crossing& c : crossings) {
    if (c.w > first + margin_) continue;
    if (!c.clean || near_boundary(c.face, c.u, c.v)) return Answer::Unknown;
    if (leaves >= 0 && leaves != static_cast<int>(c.leaves)) return Answer::Unknown;
    leaves = c.leaves;
  }
  return leaves ? Answer::Inside : Answer::Outside;
}

RayClassifier::Answer RayClassifier::classify(const std::array<double, 3>& p) {
  // An OpenCASCADE failure on a face or an edge leaves the point to the caller's classifier.
  try {
    if (on_edge(p)) return Answer::Inside;
    int inside = 0, outside = 0;
    for (const auto& d : directions()) {
      const Answer a = cast(p, d);
      inside += a == Answer::Inside;
      outside += a == Answer::Outside;
      if (inside && outside) return Answer::Unknown;  // a ray missed a crossing: ask OpenCASCADE
      if (inside == 2) return Answer::Inside;
      if (outside == 2) return Answer::Outside;
    }
  } catch (const Standard_Failure&) {
  }
  return Answer::Unknown;
}

}  // namespace cadmedial::internal
