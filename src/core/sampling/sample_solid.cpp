// 4.2.1 Sampling. The order matters: corners, ball points and edge samples first, then triplets,
// then face interiors, which keep clear of everything placed before them.
#include "sample_solid.h"
#include "face_interior.h"
#include "edge_walls.h"
#include "mirror_thin_walls.h"
#include <cstdlib>
#include <cstdio>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <future>
#include <limits>
#include <memory>
#include <tuple>
#include <optional>
#include <random>
#include <unordered_map>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomLProp_CLProps.hxx>
#include <Geom_Curve.hxx>
#include <Standard_Failure.hxx>
#include <Standard_ErrorHandler.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include "../errors.h"
#include "../two_cores.h"
#include "arc_length.h"
#include "lattice_classifier.h"
#include "point_grid.h"

namespace cadmedial {

SampleSpacing sample_spacing(double spacing) {
  SampleSpacing s;
  s.face = spacing;
  s.edge = 0.5 * spacing;     // sharp features are sampled conservatively (4.2.1)
  s.triplet = 0.5 * spacing;  // legs s-s_l, s-s_r: at most the face spacing keeps s s_l s_r Delaunay
  s.min_face = spacing / 8.0;
  // Chords on a curve turn by at most 4 degrees, so that a Delaunay edge between near neighbours
  // on a curved face that the reconstruction did not keep still fails the Angle condition at
  // theta = 5 degrees (section 3). Measured on a cylinder R = 1, h = 0.1: at 8 degrees spurious
  // fins reached 0.3 R from the axis, at 4 degrees 0.16 R, at 3 degrees 0.09 R.
  s.max_turn_rad = 4.0 * 3.14159265358979323846 / 180.0;
  return s;
}

namespace {

Point3 to_point(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Point3 to_point(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

// Unit normals more than 120 degrees apart (zero normals, on corners, are never opposite).
bool opposite(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < -0.5; }

struct ChainPoint {
  int sample;
  double t;
  int point = -1;  ///< its edge_point() in Sampler::edge_points_, -1 on corners or where it failed
};

}  // namespace

namespace sampling_detail {

// A face's mean metric and its lattice of candidates over its parameter bounds: cells of about
// half the smallest local spacing in space (metric and curvature probed on a 13 x 13 grid).
struct FacePlan {
  bool planar = false;
  double spacing = 0;  ///< the local spacing the lattice is fine enough for
  double u_scale = 1, v_scale = 1;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;  ///< the face's parameter bounds
  UvLattice lattice;
};

// A sample placed before the face interiors, as the interiors' crowding test sees it.
struct FixedSample {
  Point3 point, normal;
  double exclusion;
  bool operator<(const FixedSample& o) const {
    return std::tie(point, normal, exclusion) < std::tie(o.point, o.normal, o.exclusion);
  }
  bool operator==(const FixedSample& o) const {
    return point == o.point && normal == o.normal && exclusion == o.exclusion;
  }
};

}  // namespace sampling_detail

struct FaceDomainBuilder::Data {
  const Features* features = nullptr;
  std::vector<std::vector<ChainPoint>> chains;
  std::unordered_map<int, std::vector<std::pair<int, std::array<double, 2>>>> face_points;
  /// Per face: its mean metric and parameter bounds (the face plans' u_scale, v_scale, u0, u1, v0, v1).
  std::vector<std::array<double, 6>> plans;
};

struct FaceSetup::Data {
  std::vector<std::unique_ptr<BRepAdaptor_Surface>> surfaces;
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> classifiers;
};

struct SolidSampler::State {
  TopoDS_Solid solid;
  Features features;
  // Per face, made ahead (FaceSetup) or on first use; during the face interiors only the thread
  // sampling a face touches its entries.
  std::vector<std::unique_ptr<BRepAdaptor_Surface>> surfaces;
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> classifiers;
  double plan_spacing = 0;  ///< the spacing `plans` are for
  std::vector<std::optional<sampling_detail::FacePlan>> plans;
  // The last pass with one spacing everywhere: its fixed samples (sorted) and face interiors.
  double last_spacing = 0;
  std::vector<sampling_detail::FixedSample> last_fixed;
  std::vector<sampling_detail::FaceInterior> last_interiors;
  int kept_faces = 0;  ///< by the last pass
  std::unique_ptr<BoundaryDistance> boundaries[2];  ///< the thin walls' mirrors, one per thread
  bool mirror = true;
  std::size_t mirrored = 0;  ///< by the last pass
};

namespace {

using namespace sampling_detail;

// The crowding tests' grids have cells twice the radius they ask, so that a test looks in 8
// cells, not 27: the Y-rod mount's sampling at 250k samples took a quarter less. The fixed
// samples' grid is asked about the face spacing; a face's own grid about its spacing where it
// curves most (its plan's) and up: twice the face spacing there, fillets' cells held so many
// samples that NIST FTC 11's sampling took half as long again. A face's cells are at least the
// spacing (a test then looks in 27 at most), and where walls are refined both grids keep cells
// of the spacing: twice as large, their lists were longer than the lookups they saved.
constexpr double kCellsPerRadius = 2.0;

class Sampler {
 public:
  Sampler(SolidSampler::State& state, const SpacingField& field, const Progress& progress)
      : state_(state), f_(state.features), sp_(sample_spacing(field.uniform())), field_(field), progress_(progress),
        grid_(field.is_uniform() ? kCellsPerRadius * field.uniform() : field.uniform()), surfaces_(state.surfaces), classifiers_(state.classifiers), plans_(state.plans) {
    out_.spacing = field.uniform();
    const int nf = f_.faces.Extent();
    surfaces_.resize(nf);
    classifiers_.resize(nf);
    if (state.plan_spacing != field.uniform()) plans_.assign(nf, std::nullopt);
    state.plan_spacing = field.uniform();
    lattices_.resize(nf);
  }

  /// The samples; their face domains are left to `later`.
  Samples run(FaceDomainBuilder::Data& later) {
    sample_corners();
    sample_edges();
    report(progress_, "sampling", 0.1);
    sample_triplets();
    sample_faces();
    const int nf = f_.faces.Extent();
    later.features = &f_;
    later.plans.resize(nf);
    for (int fi = 0; fi < nf; ++fi) {
      const FacePlan& plan = face_plan(fi);
      later.plans[fi] = {plan.u_scale, plan.v_scale, plan.u0, plan.u1, plan.v0, plan.v1};
    }
    later.chains = std::move(chains_);
    later.face_points = std::move(face_points_);
    return std::move(out_);
  }

 private:
  // Room for samples up to `size`, with add()'s defaults and `tag`, not in the crowding grid.
  void grow_to(std::size_t size, SampleTag tag) {
    out_.points.resize(size);
    out_.tag.resize(size, tag);
    out_.normal.resize(size, {0, 0, 0});
    out_.normal2.resize(size, {0, 0, 0});
    out_.edge_convex.resize(size, 0);
    out_.curvature.resize(size, 0.0f);
    out_.face.resize(size, -1);
    out_.edge.resize(size, -1);
    out_.vertex.resize(size, -1);
    out_.nonconcave.resize(size, 0);
    exclusion_.resize(size, 0.0);
  }

  int add(const Point3& p, SampleTag tag, double exclusion = 0.0) {
    const int id = static_cast<int>(out_.points.size());
    out_.points.push_back(p);
    out_.tag.push_back(tag);
    out_.normal.push_back({0, 0, 0});
    out_.normal2.push_back({0, 0, 0});
    out_.edge_convex.push_back(0);
    out_.curvature.push_back(0.0f);
    out_.face.push_back(-1);
    out_.edge.push_back(-1);
    out_.vertex.push_back(-1);
    out_.nonconcave.push_back(0);
    exclusion_.push_back(exclusion);
    max_exclusion_ = std::max(max_exclusion_, exclusion);
    grid_.insert(p, id);
    return id;
  }

  bool is_sharp(int e) const {
    const EdgeKind k = f_.edge_kind[e];
    return k == EdgeKind::Convex || k == EdgeKind::Concave || k == EdgeKind::Mixed;
  }

  // Ball radius around a sharp corner: below the minimum size, conservatively a fraction of the
  // shortest incident edge (4.2.1: "we avoided computing the minimum size ... conservative").
  void sample_corners() {
    const int nv = f_.vertices.Extent();
    corner_sample_.assign(nv, -1);
    ball_radius_.assign(nv, 0.0);
    std::vector<double> shortest(nv, 1e300);
    for (int e = 0; e < f_.edges.Extent(); ++e) {
      const TopoDS_Edge& edge = TopoDS::Edge(f_.edges(e + 1));
      if (BRep_Tool::Degenerated(edge)) continue;
      const double len = GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(edge));
      edge_length_.push_back(len);
      TopoDS_Vertex a, b;
      TopExp::Vertices(edge, a, b);
      for (const TopoDS_Vertex& v : {a, b}) {
        if (v.IsNull()) continue;
        const int vi = f_.vertices.FindIndex(v) - 1;
        shortest[vi] = std::min(shortest[vi], len);
      }
    }
    for (int v = 0; v < nv; ++v) {
      const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(f_.vertices(v + 1)));
      if (f_.sharp_vertex[v]) ball_radius_[v] = std::min(sample_spacing(field_.at(to_point(p))).edge, 0.3 * shortest[v]);
      const int id = add(to_point(p), SampleTag::Corner, ball_radius_[v]);
      out_.vertex[id] = v;
      out_.nonconcave[id] = f_.nonconcave_corner[v] ? 1 : 0;
      corner_sample_[v] = id;
    }
  }

  // The two faces' normals and the local character at an edge sample: what the inner axis
  // separation needs to tell inside from outside near it. Returns the index of the edge point
  // kept for the triplets of a convex or mixed edge, or -1.
  int describe_edge_sample(int id, int e, const EdgeGeometry* geometry, double t) {
    int kept = -1;
    if (!geometry) return kept;
    try {
      const EdgePoint ep = geometry->at(t);
      if (f_.edge_kind[e] == EdgeKind::Convex || f_.edge_kind[e] == EdgeKind::Mixed) {
        kept = static_cast<int>(edge_points_.size());
        edge_points_.push_back(ep);
      }
      out_.normal[id] = to_point(ep.normal[0]);
      out_.normal2[id] = to_point(ep.normal[1]);
      out_.edge_convex[id] = ep.kind == PointKind::Convex ? 1 : ep.kind == PointKind::Concave ? 2 : 0;
      float k = 0;
      for (int side = 0; side < 2; ++side) k = std::max(k, static_cast<float>(curvature_at(f_.edge_faces[e][side], ep.uv[side].X(), ep.uv[side].Y())));
      out_.curvature[id] = k;
    } catch (const Standard_Failure&) {
    } catch (const GeometryError&) {
    }
    return kept;
  }

  double curvature_at(int fi, double u, double v) {
    const BRepAdaptor_Surface& surf = surface(fi);
    if (surf.GetType() == GeomAbs_Plane) return 0.0;
    BRepLProp_SLProps props(surf, u, v, 2, 1e-9);
    if (!props.IsCurvatureDefined()) return 0.0;
    return std::max(std::abs(props.MaxCurvature()), std::abs(props.MinCurvature()));
  }

  // The largest spacing along an edge that keeps chords within max_turn_rad of the curve.
  double curve_spacing(const BRepAdaptor_Curve& curve, double base) const {
    double kmax = 0;
    const double a = curve.FirstParameter(), b = curve.LastParameter();
    for (int i = 0; i <= 16; ++i) {
      gp_Pnt p;
      gp_Vec d1, d2;
      curve.D2(a + (b - a) * i / 16.0, p, d1, d2);
      const double n1 = d1.Magnitude();
      if (n1 > 1e-300) kmax = std::max(kmax, d1.Crossed(d2).Magnitude() / (n1 * n1 * n1));
    }
    double h = base;
    if (kmax > 0) h = std::min(h, sp_.max_turn_rad / kmax);
    return std::max(h, 0.25 * sp_.min_face);
  }

  // An edge's samples before they get ids: parameter, point and tag of each (ball, interior,
  // ball), and the exclusion radius they carry; or why OpenCASCADE could not place them.
  struct EdgePlan {
    int ia = -1, ib = -1;  ///< the corners at its ends (vertex indices), -1 for none
    double t0 = 0, t1 = 0;  ///< its parameter range
    std::vector<std::pair<double, SampleTag>> params;
    std::vector<Point3> points;
    double excl = 0.0;
    std::string error;
  };

  // Edge e's samples (4.2.1: evenly spaced, the ball rule at sharp corners). Only reads: two
  // threads plan edges at once, each through its own curve adaptor.
  EdgePlan plan_edge(int e) const {
    EdgePlan plan;
    const TopoDS_Edge& edge = TopoDS::Edge(f_.edges(e + 1));
    TopoDS_Vertex va, vb;
    TopExp::Vertices(edge, va, vb);
    plan.ia = va.IsNull() ? -1 : f_.vertices.FindIndex(va) - 1;
    plan.ib = vb.IsNull() ? -1 : f_.vertices.FindIndex(vb) - 1;
    BRep_Tool::Range(edge, plan.t0, plan.t1);
    const int ia = plan.ia, ib = plan.ib;
    const double t0 = plan.t0, t1 = plan.t1;
    if (BRep_Tool::Degenerated(edge)) return plan;
    try {
      BRepAdaptor_Curve curve(edge);
      const bool sharp = is_sharp(e);
      const SampleSpacing local = sample_spacing(field_.on_edge(e));
      const double h = curve_spacing(curve, sharp ? local.edge : local.face);
      const bool convex = f_.edge_kind[e] == EdgeKind::Convex || f_.edge_kind[e] == EdgeKind::Mixed;
      plan.excl = convex ? 1.05 * local.triplet : 0.0;
      const ArcLength arc(curve, t0, t1);
      const double len = arc.length(t0, t1);
      // 4.2.1 ball rule: the ball around a sharp corner meets the edge in one sample, and no
      // other sample lies inside the ball.
      const double ra = ia >= 0 ? ball_radius_[ia] : 0.0, rb = ib >= 0 ? ball_radius_[ib] : 0.0;
      double a = t0, b = t1;
      if (ra > 0 && ra < 0.5 * len) {
        a = arc.parameter(ra, t0);
        plan.params.push_back({a, SampleTag::Ball});
      }
      const double rest_b = rb > 0 && rb < 0.5 * len ? rb : 0.0;
      if (rest_b > 0) b = arc.parameter(-rb, t1);
      const double inner = arc.length(a, b);
      const int n = std::max(1, static_cast<int>(std::ceil(inner / h)));
      for (int i = 1; i < n; ++i) plan.params.push_back({arc.parameter(inner * i / n, a), SampleTag::Edge});
      if (rest_b > 0) plan.params.push_back({b, SampleTag::Ball});
      for (const auto& [t, tag] : plan.params) plan.points.push_back(to_point(curve.Value(t)));
    } catch (const Standard_Failure& err) {
      plan.params.clear();
      plan.points.clear();
      plan.error = "edge " + std::to_string(e + 1) + ": cannot sample: " + err.GetMessageString();
    }
    return plan;
  }

  void sample_edges() {
    const int ne = f_.edges.Extent();
    chains_.assign(ne, {});
    // The edges' parameters on two threads, each taking the next edge (arc length along B-spline
    // edges, found anew for every sample, was 0.15 to 0.2 s of NIST CTC 02's 0.2 to 0.25 s here
    // at 66k samples); then the samples in edge order, as one thread placed them.
    std::vector<EdgePlan> plans(ne);
    std::atomic<int> next{0};
    internal::on_two_cores(
        [&] {
          for (int e; (e = next++) < ne;) {
            report(progress_, "sampling", 0.1 * e / std::max(1, ne));
            plans[e] = plan_edge(e);
          }
        },
        [&](const std::atomic<bool>& stop) {
          for (int e; !stop && (e = next++) < ne;) plans[e] = plan_edge(e);
        });
    for (int e = 0; e < ne; ++e) {
      const EdgePlan& plan = plans[e];
      auto& chain = chains_[e];
      if (plan.ia >= 0) chain.push_back({corner_sample_[plan.ia], plan.t0});
      if (!plan.error.empty()) throw GeometryError(plan.error);
      if (!plan.params.empty()) {
        // The edge's curves and faces, looked up once by the classification (edge_point per
        // sample was 40 % of sampling); where that failed, every edge_point would have.
        const EdgeGeometry* geometry = nullptr;
        std::optional<EdgeGeometry> own;  // for features made without their geometry
        if (e < static_cast<int>(f_.edge_geometry.size())) {
          geometry = f_.edge_geometry[e].get();
        } else {
          try {
            geometry = &own.emplace(f_, e);
          } catch (const Standard_Failure&) {
          } catch (const GeometryError&) {
          }
        }
        try {
          for (std::size_t k = 0; k < plan.params.size(); ++k) {
            const auto& [t, tag] = plan.params[k];
            const int id = add(plan.points[k], tag, plan.excl);
            out_.edge[id] = e;
            chain.push_back({id, t, describe_edge_sample(id, e, geometry, t)});
          }
        } catch (const Standard_Failure& err) {
          throw GeometryError("edge " + std::to_string(e + 1) + ": cannot sample: " + err.GetMessageString());
        }
      }
      if (plan.ib >= 0) chain.push_back({corner_sample_[plan.ib], plan.t1});
    }
  }

  // A point on face `fi`'s surface at distance d from p, in the plane through p normal to the edge
  // tangent T, starting from uv0 along `dir` (4.2.1: s_l s and s_r s perpendicular to e, equal
  // lengths). Whether it lies inside the face's boundary is the caller's question (inside_face).
  bool point_on_surface_at(int fi, const gp_Pnt& p, const gp_Vec& tangent, const gp_Vec& dir, const gp_Pnt2d& uv0,
                        double d, gp_Pnt2d& uv, gp_Pnt& q) {
    const BRepAdaptor_Surface& surf = surface(fi);
    double u = uv0.X(), v = uv0.Y();
    gp_Pnt s;
    gp_Vec su, sv;
    surf.D1(u, v, s, su, sv);
    // Initial guess: solve [su sv] (du dv) = d*dir in least squares.
    {
      const double a = su.Dot(su), b = su.Dot(sv), c = sv.Dot(sv);
      const double ru = su.Dot(dir) * d, rv = sv.Dot(dir) * d;
      const double det = a * c - b * b;
      if (std::abs(det) < 1e-300) return false;
      u += (c * ru - b * rv) / det;
      v += (a * rv - b * ru) / det;
    }
    for (int it = 0; it < 30; ++it) {
      surf.D1(u, v, s, su, sv);
      const gp_Vec w(p, s);
      const double f1 = w.Dot(tangent), f2 = w.Dot(w) - d * d;
      if (std::abs(f1) < 1e-10 * d && std::abs(f2) < 1e-10 * d * d) break;
      const double j11 = su.Dot(tangent), j12 = sv.Dot(tangent);
      const double j21 = 2 * w.Dot(su), j22 = 2 * w.Dot(sv);
      const double det = j11 * j22 - j12 * j21;
      if (std::abs(det) < 1e-300) return false;
      u -= (j22 * f1 - j12 * f2) / det;
      v -= (-j21 * f1 + j11 * f2) / det;
    }
    surf.D0(u, v, s);
    const gp_Vec w(p, s);
    if (std::abs(w.Magnitude() - d) > 1e-6 * d || w.Dot(dir) <= 0.5 * d) return false;
    uv = gp_Pnt2d(u, v);
    q = s;
    return true;
  }

  gp_Vec outward_normal(int fi, double u, double v) {
    gp_Pnt p;
    gp_Vec su, sv;
    surface(fi).D1(u, v, p, su, sv);
    gp_Vec n = su.Crossed(sv);
    if (n.Magnitude() < 1e-300) return gp_Vec(0, 0, 0);
    n.Normalize();
    if (f_.faces(fi + 1).Orientation() == TopAbs_REVERSED) n.Reverse();
    return n;
  }

  // One side of a triplet, as its face sees it (the Newton walk, the face's classifier, the
  // normal and curvature): what the sequential pass below would compute, with any error kept
  // until that pass would have met it.
  struct TripletSide {
    bool on_surface = false, inside = false;
    gp_Pnt2d uv;
    gp_Pnt q;
    Point3 normal{0, 0, 0};
    float curvature = 0;
    std::exception_ptr surface_error, inside_error, describe_error;
  };

  // The edge samples that get triplets (a convex edge's non-corner samples where the edge is
  // convex), in the order of the sequential pass: (edge, chain index).
  std::vector<std::array<int, 2>> triplet_slots() const {
    std::vector<std::array<int, 2>> slots;
    const int ne = f_.edges.Extent();
    for (int e = 0; e < ne; ++e) {
      const EdgeKind kind = f_.edge_kind[e];
      if (kind != EdgeKind::Convex && kind != EdgeKind::Mixed) continue;
      const auto& chain = chains_[e];
      for (size_t i = 0; i < chain.size(); ++i) {
        // No edge point: edge_point() threw for describe_edge_sample, and would again here.
        if (out_.tag[chain[i].sample] == SampleTag::Corner || chain[i].point < 0) continue;
        if (edge_points_[chain[i].point].kind != PointKind::Convex) continue;
        slots.push_back({e, static_cast<int>(i)});
      }
    }
    return slots;
  }

  // Both sides of every slot, face by face on two threads (a face's surface, lattice and
  // classifier are touched by one thread only, as in sample_faces). Sides that the sequential
  // pass skips (the other side failed first, a crowded point) are computed too: the two threads
  // still finish sooner (the classifier near a face's boundary is the slowest part).
  std::vector<TripletSide> triplet_sides(const std::vector<std::array<int, 2>>& slots) {
    std::vector<TripletSide> sides(2 * slots.size());
    const int nf = f_.faces.Extent();
    std::vector<std::vector<int>> of_face(nf);
    for (size_t k = 0; k < sides.size(); ++k) of_face[f_.edge_faces[slots[k / 2][0]][k % 2]].push_back(static_cast<int>(k));
    std::vector<int> order;
    for (int fi = 0; fi < nf; ++fi)
      if (!of_face[fi].empty()) order.push_back(fi);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return of_face[a].size() > of_face[b].size(); });
    const int todo = static_cast<int>(order.size());
    std::atomic<int> next{0}, done{0};
    std::atomic<bool> stop{false};
    const auto work = [&](bool reports) {
      try {
        for (int n; !stop && (n = next++) < todo;) {
          const int fi = order[n];
          for (int k : of_face[fi]) {
            const auto [e, i] = slots[k / 2];
            const EdgePoint& ep = edge_points_[chains_[e][i].point];
            const double d = sample_spacing(field_.on_edge(e)).triplet;
            TripletSide& side = sides[k];
            try {
              side.on_surface = point_on_surface_at(fi, ep.point, ep.tangent, ep.inward[k % 2], ep.uv[k % 2], d, side.uv, side.q);
            } catch (...) {
              side.surface_error = std::current_exception();
              continue;
            }
            if (!side.on_surface) continue;
            try {
              side.inside = inside_face(fi, side.uv);
            } catch (...) {
              side.inside_error = std::current_exception();
              continue;
            }
            if (!side.inside) continue;
            try {
              side.normal = to_point(outward_normal(fi, side.uv.X(), side.uv.Y()));
              side.curvature = static_cast<float>(curvature_at(fi, side.uv.X(), side.uv.Y()));
            } catch (...) {
              side.describe_error = std::current_exception();
            }
          }
          ++done;
          if (reports) report(progress_, "sampling", 0.1 + 0.1 * done / std::max(1, todo));
        }
      } catch (...) {
        stop = true;
        throw;
      }
    };
    if (todo < 2)
      work(true);
    else
      internal::on_two_cores([&] { work(true); }, [&](const std::atomic<bool>&) { work(false); });
    return sides;
  }

  // 4.2.1 triplets: for every sample s on a convex edge, s_l and s_r on the two faces.
  void sample_triplets() {
    const std::vector<std::array<int, 2>> slots = triplet_slots();
    const std::vector<TripletSide> sides = triplet_sides(slots);
    for (size_t slot = 0; slot < slots.size(); ++slot) {
      const auto [e, i] = slots[slot];
      const auto& chain = chains_[e];
      const int s = chain[i].sample;
      const double d = sample_spacing(field_.on_edge(e)).triplet;
      int side[2] = {-1, -1};
      bool ok = true;
      for (int k = 0; k < 2 && ok; ++k) {
        const int fi = f_.edge_faces[e][k];
        const TripletSide& t = sides[2 * slot + k];
        if (t.surface_error) std::rethrow_exception(t.surface_error);
        ok = t.on_surface;
        const Point3 q = to_point(t.q);
        // Keep clear of samples from other edges: near a corner two edges' triplets meet. At a
        // right-angled corner they meet exactly, and then share the point.
        if (ok)
          ok = !grid_.any_near(q, 0.5 * d, [&](int id) {
            if (id == s) return false;
            const double d2 = distance2(out_.points[id], q);
            if (d2 < 1e-12 * d * d && out_.tag[id] == SampleTag::Triplet && out_.face[id] == fi) {
              side[k] = id;
              return false;
            }
            return d2 < 0.25 * d * d;
          });
        if (ok) {
          if (t.inside_error) std::rethrow_exception(t.inside_error);
          ok = t.inside;
        }
      }
      if (!ok) continue;
      for (int k = 0; k < 2; ++k) {
        const int fi = f_.edge_faces[e][k];
        if (side[k] >= 0) continue;
        const TripletSide& t = sides[2 * slot + k];
        if (t.describe_error) std::rethrow_exception(t.describe_error);
        side[k] = add(to_point(t.q), SampleTag::Triplet);
        out_.face[side[k]] = fi;
        out_.normal[side[k]] = t.normal;
        out_.curvature[side[k]] = t.curvature;
        face_points_[fi].push_back({side[k], {t.uv.X(), t.uv.Y()}});
      }
      Triplet tr;
      tr.s = s;
      tr.sl = side[0];
      tr.sr = side[1];
      tr.prev = i > 0 ? chain[i - 1].sample : -1;
      tr.next = i + 1 < static_cast<int>(chain.size()) ? chain[i + 1].sample : -1;
      out_.triplets.push_back(tr);
    }
  }

  const BRepAdaptor_Surface& surface(int fi) {
    auto& s = surfaces_[fi];
    if (!s) s = std::make_unique<BRepAdaptor_Surface>(TopoDS::Face(f_.faces(fi + 1)), Standard_False);
    return *s;
  }
  const BRepTopAdaptor_FClass2d& classifier(int fi) {
    auto& c = classifiers_[fi];
    if (!c) c = std::make_unique<BRepTopAdaptor_FClass2d>(TopoDS::Face(f_.faces(fi + 1)), 1e-9);
    return *c;
  }

  // Face interiors: a jittered grid in the parameter plane, fine enough in space, thinned to the
  // local spacing in space (not in parameters), which shrinks where the surface curves. Each face
  // on its own (its own random stream, kept clear of the corner, edge and triplet samples and of
  // its own samples), so that the faces can be sampled on two threads and the result does not
  // depend on which thread took which face. Samples of two faces never crowd each other: away
  // from their common edge's samples, they are farther apart than the spacing anyway, unless
  // the faces meet at less than 60 degrees, where their normals already keep them apart.
  void sample_faces() {
    const int nf = f_.faces.Extent();
    out_.faces.resize(nf);
    std::vector<FaceInterior> interiors(nf);
    // A face that the last pass at this spacing sampled, and that nothing near changed since,
    // keeps its samples (refining thin walls resamples the solid; most faces are not near them).
    const std::vector<FixedSample> fixed = fixed_samples();
    const bool same_spacing = state_.last_spacing == field_.uniform() && state_.last_interiors.size() == static_cast<size_t>(nf);
    state_.kept_faces = 0;
    std::vector<int> order;
    std::vector<double> cost(nf);
    for (int fi = 0; fi < nf; ++fi) {
      const bool refine = field_.on_face(fi) < sp_.face;
      if (same_spacing && !refine && same_near(fixed, state_.last_fixed, state_.last_interiors[fi])) {
        interiors[fi] = state_.last_interiors[fi];
        ++state_.kept_faces;
        continue;
      }
      order.push_back(fi);
      const FacePlan& plan = face_plan(fi);
      cost[fi] = static_cast<double>(plan.lattice.nu) * static_cast<double>(plan.lattice.nv);
    }
    // Largest faces first, so that the two threads end together.
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] > cost[b]; });
    const int todo = static_cast<int>(order.size());
    std::atomic<int> next{0}, done{0};
    std::atomic<bool> stop{false};
    const auto work = [&](bool reports) {
      // Only this thread reports (the callback may hold Python's lock); the other polls `stop`.
      const std::function<void(double)> row =
          reports ? std::function<void(double)>([&](double f) { report_faces(done + f, todo); })
                  : std::function<void(double)>([&](double) {
                      if (stop) throw Cancelled();
                    });
      try {
        for (int k; !stop && (k = next++) < todo;) {
          const int fi = order[k];
          try {
            interiors[fi] = sample_face(fi, row);
          } catch (const Standard_Failure& err) {
            throw GeometryError("face " + std::to_string(fi + 1) + ": cannot sample: " + err.GetMessageString());
          }
          ++done;
        }
      } catch (...) {
        stop = true;
        throw;
      }
    };
    if (todo < 2) {
      work(true);
    } else {
      std::future<void> other = std::async(std::launch::async, [&] { work(false); });
      try {
        work(true);
        // The user can still cancel while the other thread finishes its last face.
        while (other.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready) report_faces(done, todo);
      } catch (...) {
        stop = true;
        other.wait();
        throw;
      }
      other.get();
    }
    // Cached as sampled: the mirrors depend on other faces' samples.
    std::vector<FaceInterior> sampled;
    if (field_.is_uniform()) sampled = interiors;
    mirror_walls(interiors);
    // The interiors after the samples placed so far, face by face, written in place: nothing
    // asks the crowding grid after them, so they are not put in it (with the growing arrays, that
    // took 56 ms of this loop's 68 ms at 250k samples, on one core; 24 to 35 ms now).
    std::size_t id = out_.points.size();
    std::size_t total = id;
    for (const FaceInterior& in : interiors) total += in.point.size();
    grow_to(total, SampleTag::Face);
    for (int fi = 0; fi < nf; ++fi) {
      const FaceInterior& in = interiors[fi];
      auto& points = face_points_[fi];
      points.reserve(points.size() + in.point.size());
      for (size_t k = 0; k < in.point.size(); ++k, ++id) {
        out_.points[id] = in.point[k];
        out_.face[id] = fi;
        out_.normal[id] = in.normal[k];
        out_.curvature[id] = in.curvature[k];
        points.push_back({static_cast<int>(id), in.uv[k]});
      }
    }
    if (field_.is_uniform()) {
      state_.last_spacing = field_.uniform();
      state_.last_fixed = fixed;
      state_.last_interiors = std::move(sampled);
    }
  }

  // Thin walls in mirrored pairs (mirror_thin_walls.h): walls thinner than 2 kMirrorBelow spacings.
  void mirror_walls(std::vector<FaceInterior>& interiors) {
    state_.mirrored = 0;
    if (!state_.mirror) return;
    constexpr double kMirrorBelow = 2.0;
    for (auto& b : state_.boundaries)
      if (!b) b = std::make_unique<BoundaryDistance>(state_.solid);
    std::vector<PlacedSample> placed(out_.points.size());
    for (std::size_t i = 0; i < placed.size(); ++i) placed[i] = {out_.points[i], out_.normal[i], exclusion_[i]};
    BoundaryDistance* boundaries[2] = {state_.boundaries[0].get(), state_.boundaries[1].get()};
    const MirrorStats ms = mirror_thin_walls(interiors, field_, placed, boundaries, kMirrorBelow, 1e-7 * field_.uniform());
    state_.mirrored = ms.mirrored;
  }

  // The samples placed so far, as the face interiors' crowding test sees them, sorted.
  std::vector<FixedSample> fixed_samples() const {
    std::vector<FixedSample> out(out_.points.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = {out_.points[i], out_.normal[i], exclusion_[i]};
    std::sort(out.begin(), out.end());
    return out;
  }

  // Whether the fixed samples within a spacing of where the face's candidates asked (every
  // crowding test looks at most that far) are the same in both lists.
  bool same_near(const std::vector<FixedSample>& a, const std::vector<FixedSample>& b, const FaceInterior& face) const {
    const double reach = sp_.face;
    const Point3 lo{face.probed_lo[0] - reach, face.probed_lo[1] - reach, face.probed_lo[2] - reach};
    const Point3 hi{face.probed_hi[0] + reach, face.probed_hi[1] + reach, face.probed_hi[2] + reach};
    auto near = [&](const std::vector<FixedSample>& list) {
      std::vector<const FixedSample*> out;
      const auto first = std::lower_bound(list.begin(), list.end(), lo[0],
                                          [](const FixedSample& s, double x) { return s.point[0] < x; });
      for (auto it = first; it != list.end() && it->point[0] <= hi[0]; ++it)
        if (it->point[1] >= lo[1] && it->point[1] <= hi[1] && it->point[2] >= lo[2] && it->point[2] <= hi[2])
          out.push_back(&*it);
      return out;
    };
    const auto na = near(a), nb = near(b);
    if (na.size() != nb.size()) return false;
    for (size_t k = 0; k < na.size(); ++k)
      if (!(*na[k] == *nb[k])) return false;
    return true;
  }

  void report_faces(double faces_done, int nf) { report(progress_, "sampling", 0.2 + 0.8 * faces_done / std::max(1, nf)); }

  const FacePlan& face_plan(int fi) {
    if (plans_[fi]) return *plans_[fi];
    FacePlan plan;
    const BRepAdaptor_Surface& surf = surface(fi);
    const std::array<double, 4> b = uv_bounds_of(f_, fi);
    const double u0 = b[0], u1 = b[1], v0 = b[2], v1 = b[3];
    const bool planar = surf.GetType() == GeomAbs_Plane;
    // Probe the metric and curvature.
    constexpr int kProbe = 12;
    double su_max = 0, sv_max = 0, su_sum = 0, sv_sum = 0, k_max = 0;
    BRepLProp_SLProps props(surf, 2, 1e-9);
    for (int i = 0; i <= kProbe; ++i)
      for (int j = 0; j <= kProbe; ++j) {
        const double u = u0 + (u1 - u0) * i / kProbe, v = v0 + (v1 - v0) * j / kProbe;
        gp_Pnt p;
        gp_Vec su, sv;
        surf.D1(u, v, p, su, sv);
        su_max = std::max(su_max, su.Magnitude());
        sv_max = std::max(sv_max, sv.Magnitude());
        su_sum += su.Magnitude();
        sv_sum += sv.Magnitude();
        if (!planar) {
          props.SetParameters(u, v);
          if (props.IsCurvatureDefined())
            k_max = std::max({k_max, std::abs(props.MaxCurvature()), std::abs(props.MinCurvature())});
        }
      }
    const double np = (kProbe + 1.0) * (kProbe + 1.0);
    plan.u_scale = std::max(su_sum / np, 1e-300);
    plan.v_scale = std::max(sv_sum / np, 1e-300);
    const double r_min = sp_.face_at(k_max);
    // Candidate step: half the smallest local spacing, in space.
    const double step = 0.5 * r_min;
    long nu = std::max(1L, static_cast<long>(std::ceil((u1 - u0) * su_max / step)));
    long nvv = std::max(1L, static_cast<long>(std::ceil((v1 - v0) * sv_max / step)));
    constexpr double kMaxCandidates = 8e6;
    if (static_cast<double>(nu) * nvv > kMaxCandidates) {
      const double shrink = std::sqrt(kMaxCandidates / (static_cast<double>(nu) * nvv));
      nu = std::max(1L, static_cast<long>(nu * shrink));
      nvv = std::max(1L, static_cast<long>(nvv * shrink));
    }
    plan.planar = planar;
    plan.spacing = r_min;
    plan.u0 = u0, plan.u1 = u1, plan.v0 = v0, plan.v1 = v1;
    plan.lattice = {u0, v0, (u1 - u0) / nu, (v1 - v0) / nvv, nu, nvv};
    return *(plans_[fi] = plan);
  }

  // The face's point-in-face answers over its lattice (kept from the triplets to the face's own
  // sampling).
  LatticeClassifier& lattice(int fi) {
    auto& l = lattices_[fi];
    if (!l) l = std::make_unique<LatticeClassifier>(classifier(fi), surface(fi), face_plan(fi).lattice);
    return *l;
  }

  // Exactly classifier(fi).Perform(uv) == TopAbs_IN.
  bool inside_face(int fi, const gp_Pnt2d& uv) {
    const LatticeClassifier::Answer a = lattice(fi).classify(uv);
    if (a != LatticeClassifier::Answer::Ask) return a == LatticeClassifier::Answer::In;
    return inside_near_boundary(fi, uv);
  }

  // The same for a point that the lattice leaves to Perform (Ask): the wires' polygons answer,
  // and Perform itself within a polygon's tolerance.
  bool inside_near_boundary(int fi, const gp_Pnt2d& uv) {
    const LatticeClassifier::Answer a = lattice(fi).exact(uv);
    if (a != LatticeClassifier::Answer::Ask) return a == LatticeClassifier::Answer::In;
    return classifier(fi).Perform(uv) == TopAbs_IN;
  }

  // A candidate on face fi: kept unless a corner, edge or triplet sample or one of the face's
  // own lies within the local spacing (the field's `h`, smaller where the surface curves) or
  // the face's classifier says outside.
  void try_face_candidate(int fi, double u, double v, LatticeClassifier::Answer where, double h,
                          BRepLProp_SLProps& props, FaceInterior& in, PointGrid& own) {
    const TopoDS_Face& face = TopoDS::Face(f_.faces(fi + 1));
    const BRepAdaptor_Surface& surf = surface(fi);
    gp_Pnt p;
    gp_Vec su, sv;
    surf.D1(u, v, p, su, sv);
    gp_Vec n = su.Crossed(sv);
    if (n.Magnitude() < 1e-300) return;  // singular point: the vertex sample covers it
    double r = h, k = 0;
    if (!face_plan(fi).planar) {
      props.SetParameters(u, v);
      if (props.IsCurvatureDefined()) {
        k = std::max(std::abs(props.MaxCurvature()), std::abs(props.MinCurvature()));
        r = sp_.face_at(k, h);
      }
    }
    const Point3 c = to_point(p);
    n.Normalize();
    if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
    const Point3 nc = to_point(n);
    for (int a = 0; a < 3; ++a) {
      in.probed_lo[a] = std::min(in.probed_lo[a], c[a]);
      in.probed_hi[a] = std::max(in.probed_hi[a], c[a]);
    }
    // The cheap tests first: most candidates fall within reach of a sample already placed. A
    // sample on a wall facing this one (a thin plate's other side, or across a narrow face) is
    // no neighbour: each wall needs its own samples for the sheet between them.
    if (own.any_near(c, r, [&](int id) { return distance2(in.point[id], c) < r * r && !opposite(in.normal[id], nc); }))
      return;
    // Every sample whose exclusion can reach c (a convex edge's is 1.05 triplet legs, more than
    // the edge spacing).
    const bool crowded = grid_.any_near(c, std::max({r, sp_.edge, max_exclusion_}), [&](int id) {
      const double ex = std::max(r, exclusion_[id]);
      return distance2(out_.points[id], c) < ex * ex && !opposite(out_.normal[id], nc);
    });
    if (crowded) return;
    if (where == LatticeClassifier::Answer::Ask && !inside_near_boundary(fi, gp_Pnt2d(u, v))) return;
    own.insert(c, static_cast<int>(in.point.size()));
    in.point.push_back(c);
    in.normal.push_back(nc);
    in.curvature.push_back(static_cast<float>(k));
    in.uv.push_back({u, v});
  }

  // `row(f)` is called before each lattice row, f the fraction of the face done: one face can
  // take seconds (bench/cancel_latency.py), and a cancel must not wait.
  FaceInterior sample_face(int fi, const std::function<void(double)>& row) {
    FaceInterior in;
    PointGrid own(field_.on_face(fi) < sp_.face ? field_.uniform()
                                                : std::max(field_.uniform(), kCellsPerRadius * face_plan(fi).spacing));
    // The face's own random stream: its samples do not depend on the order faces are sampled in.
    std::mt19937_64 rng(12345 + 0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(fi));
    std::uniform_real_distribution<double> jitter(-0.35, 0.35);
    const BRepAdaptor_Surface& surf = surface(fi);
    const FacePlan& plan = face_plan(fi);
    const long nu = plan.lattice.nu, nvv = plan.lattice.nv;
    const double u0 = plan.lattice.u0, v0 = plan.lattice.v0, du = plan.lattice.du, dv = plan.lattice.dv;
    LatticeClassifier& inside = lattice(fi);
    BRepLProp_SLProps props(surf, 2, 1e-9);
    // Where walls are thin, a lattice cell coarser than the local spacing is cut into m x m.
    const bool refine = field_.on_face(fi) < sp_.face;
    for (long i = 0; i < nu; ++i) {
      row(static_cast<double>(i) / nu);
      for (long j = 0; j < nvv; ++j) {
        const double u = u0 + du * (i + 0.5 + jitter(rng)), v = v0 + dv * (j + 0.5 + jitter(rng));
        const LatticeClassifier::Answer where = inside.classify(i, j, gp_Pnt2d(u, v));
        if (where == LatticeClassifier::Answer::Out) continue;
        if (!refine) {
          try_face_candidate(fi, u, v, where, sp_.face, props, in, own);
          continue;
        }
        const double h = field_.at(to_point(surf.Value(u, v)));
        const int m = std::min(8, static_cast<int>(std::ceil(plan.spacing / h - 1e-9)));
        if (m <= 1) {
          try_face_candidate(fi, u, v, where, h, props, in, own);
          continue;
        }
        for (int a = 0; a < m; ++a)
          for (int b = 0; b < m; ++b) {
            const double us = u0 + du * (i + (a + 0.5 + jitter(rng)) / m);
            const double vs = v0 + dv * (j + (b + 0.5 + jitter(rng)) / m);
            const LatticeClassifier::Answer there = inside.classify(i, j, gp_Pnt2d(us, vs));
            if (there != LatticeClassifier::Answer::Out) try_face_candidate(fi, us, vs, there, h, props, in, own);
          }
      }
    }
    lattices_[fi].reset();
    return in;
  }

  SolidSampler::State& state_;
  const Features& f_;
  SampleSpacing sp_;
  const SpacingField& field_;
  Progress progress_;
  Samples out_;
  PointGrid grid_;
  std::vector<double> exclusion_;
  double max_exclusion_ = 0.0;  ///< the largest of exclusion_
  std::vector<int> corner_sample_;
  std::vector<double> ball_radius_;
  std::vector<double> edge_length_;
  std::vector<std::vector<ChainPoint>> chains_;
  std::vector<EdgePoint> edge_points_;
  std::unordered_map<int, std::vector<std::pair<int, std::array<double, 2>>>> face_points_;
  // The solid's per-face state (kept between passes), and the lattices of this pass.
  std::vector<std::unique_ptr<BRepAdaptor_Surface>>& surfaces_;
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>>& classifiers_;
  std::vector<std::optional<FacePlan>>& plans_;
  std::vector<std::unique_ptr<LatticeClassifier>> lattices_;
};

// Face fi's points in its parameter plane: boundary chains (seams twice, degenerate edges as
// copies of their vertex) with their segments, then the interior and triplet samples.
void build_domain(const FaceDomainBuilder::Data& d, int fi, FaceDomain& dom) {
  const Features& f = *d.features;
  const TopoDS_Face& face = TopoDS::Face(f.faces(fi + 1));
  const TopoDS_Face fwd = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  const auto& [u_scale, v_scale, u0, u1, v0, v1] = d.plans[fi];
  dom.u_scale = u_scale;
  dom.v_scale = v_scale;
  const double tol = 1e-6 * std::max({u1 - u0, v1 - v0, 1e-12});
  // Chains of adjacent edges meet at a corner: one local point per (sample, uv). A sample has
  // several only on seams and degenerate edges, where its uv differ by much more than tol.
  std::unordered_map<int, std::vector<int>> copies;
  auto local = [&](int sample, double u, double v) {
    auto& list = copies[sample];
    for (int k : list)
      if (std::abs(dom.uv[k][0] - u) < tol && std::abs(dom.uv[k][1] - v) < tol) return k;
    dom.sample.push_back(sample);
    dom.uv.push_back({u, v});
    list.push_back(static_cast<int>(dom.sample.size() - 1));
    return list.back();
  };
  for (TopExp_Explorer ex(fwd, TopAbs_EDGE); ex.More(); ex.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(ex.Current());
    const int e = f.edges.FindIndex(edge) - 1;
    double a = 0, b = 0;
    Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, fwd, a, b);
    if (pc.IsNull()) continue;
    const auto& chain = d.chains[e];
    std::vector<int> ids;
    if (BRep_Tool::Degenerated(edge)) {
      // A pole or apex: one 3D point, a segment in the parameter plane.
      if (chain.empty()) continue;
      constexpr int kCopies = 16;
      for (int i = 0; i <= kCopies; ++i) {
        const gp_Pnt2d uv = pc->Value(a + (b - a) * i / kCopies);
        ids.push_back(local(chain.front().sample, uv.X(), uv.Y()));
      }
    } else {
      for (const ChainPoint& cp : chain) {
        const gp_Pnt2d uv = pc->Value(cp.t);
        ids.push_back(local(cp.sample, uv.X(), uv.Y()));
      }
    }
    for (size_t i = 0; i + 1 < ids.size(); ++i)
      if (ids[i] != ids[i + 1]) dom.boundary.push_back({ids[i], ids[i + 1]});
  }
  const auto points = d.face_points.find(fi);
  if (points == d.face_points.end()) return;
  for (const auto& [sample, uv] : points->second) {
    dom.sample.push_back(sample);
    dom.uv.push_back(uv);
  }
}

}  // namespace

FaceDomainBuilder::FaceDomainBuilder() = default;
FaceDomainBuilder::~FaceDomainBuilder() = default;
FaceDomainBuilder::FaceDomainBuilder(FaceDomainBuilder&&) noexcept = default;
FaceDomainBuilder& FaceDomainBuilder::operator=(FaceDomainBuilder&&) noexcept = default;

void FaceDomainBuilder::build(Samples& s) {
  if (!data_) return;
  const std::unique_ptr<Data> d = std::move(data_);
  try {
    for (std::size_t fi = 0; fi < s.faces.size() && fi < d->plans.size(); ++fi)
      build_domain(*d, static_cast<int>(fi), s.faces[fi]);
  } catch (const Standard_Failure& err) {
    throw GeometryError(std::string("sampling failed: ") + err.GetMessageString());
  }
}

FaceSetup::FaceSetup() = default;
FaceSetup::~FaceSetup() = default;
FaceSetup::FaceSetup(FaceSetup&&) noexcept = default;
FaceSetup& FaceSetup::operator=(FaceSetup&&) noexcept = default;

FaceSetup FaceSetup::make(const TopoDS_Solid& solid, const std::atomic<bool>* stop) {
  FaceSetup out;
  out.data_ = std::make_unique<Data>();
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(solid, TopAbs_FACE, faces);
  const int nf = faces.Extent();
  out.data_->surfaces.resize(nf);
  out.data_->classifiers.resize(nf);
  for (int fi = 0; fi < nf && !(stop && *stop); ++fi) {
    // As Sampler::surface and Sampler::classifier make them.
    const TopoDS_Face& face = TopoDS::Face(faces(fi + 1));
    try {
      out.data_->surfaces[fi] = std::make_unique<BRepAdaptor_Surface>(face, Standard_False);
      out.data_->classifiers[fi] = std::make_unique<BRepTopAdaptor_FClass2d>(face, 1e-9);
    } catch (...) {
      out.data_->surfaces[fi].reset();
      out.data_->classifiers[fi].reset();
    }
  }
  return out;
}

SolidSampler::SolidSampler(const TopoDS_Solid& solid, const Features& features, FaceSetup faces)
    : state_(std::make_unique<State>()) {
  state_->solid = solid;
  state_->features = features;
  if (faces.data_ && static_cast<int>(faces.data_->classifiers.size()) == features.faces.Extent()) {
    state_->surfaces = std::move(faces.data_->surfaces);
    state_->classifiers = std::move(faces.data_->classifiers);
  }
}

SolidSampler::~SolidSampler() = default;

int SolidSampler::kept_faces() const { return state_->kept_faces; }

void SolidSampler::mirror_thin_walls(bool on) { state_->mirror = on; }
bool SolidSampler::mirrors_thin_walls() const { return state_->mirror; }
std::size_t SolidSampler::mirrored() const { return state_->mirrored; }

std::vector<double> SolidSampler::edge_wall_radii(const Samples& samples, double r_max) {
  for (auto& b : state_->boundaries)
    if (!b) b = std::make_unique<BoundaryDistance>(state_->solid);
  BoundaryDistance* boundaries[2] = {state_->boundaries[0].get(), state_->boundaries[1].get()};
  try {
    return cadmedial::edge_wall_radii(samples, boundaries, r_max, 1e-7 * r_max);
  } catch (const Standard_Failure& err) {
    throw GeometryError(std::string("measuring thin walls failed: ") + err.GetMessageString());
  }
}

Samples SolidSampler::sample(const SpacingField& field, const Progress& progress) {
  FaceDomainBuilder domains;
  Samples s = sample(field, domains, progress);
  domains.build(s);
  return s;
}

Samples SolidSampler::sample(const SpacingField& field, FaceDomainBuilder& domains, const Progress& progress) {
  if (!(field.uniform() > 0) || !std::isfinite(field.uniform())) throw InvalidInput("spacing must be a positive number");
  auto data = std::make_unique<FaceDomainBuilder::Data>();
  try {
    Samples s = Sampler(*state_, field, progress).run(*data);
    domains.data_ = std::move(data);
    return s;
  } catch (const Standard_Failure& err) {
    throw GeometryError(std::string("sampling failed: ") + err.GetMessageString());
  }
}

Samples sample_solid(const TopoDS_Solid& solid, const Features& features, double spacing, const Progress& progress) {
  if (!(spacing > 0) || !std::isfinite(spacing)) throw InvalidInput("spacing must be a positive number");
  return sample_solid(solid, features, SpacingField(spacing), progress);
}

Samples sample_solid(const TopoDS_Solid& solid, const Features& features, const SpacingField& field,
                     const Progress& progress) {
  return SolidSampler(solid, features).sample(field, progress);
}

SolidMeasure measure_solid(const TopoDS_Solid& solid, const Features& features) {
  SolidMeasure m;
  // Each face's and each sharp edge's own numbers first, the two cores taking the next in turn (the
  // faces' Gauss integrals were half the set-up on B-spline-rich parts: NIST CTC 02, 0.12 s on
  // one core); then summed in order, as one pass did.
  const int nf = features.faces.Extent(), ne = features.edges.Extent();
  m.faces.assign(nf, {0.0, 0.0, false});
  // A fault inside OpenCASCADE on either thread becomes a Standard_Failure (compute_medial_axis
  // turns it into a GeometryError), as on the calling thread.
  internal::on_two_cores_each(static_cast<std::size_t>(nf), [&](std::size_t k) {
    OCC_CATCH_SIGNALS
    const int fi = static_cast<int>(k) + 1;
    const TopoDS_Face& face = TopoDS::Face(features.faces(fi));
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props);
    // Mean over a probe grid of the largest principal curvature.
    BRepAdaptor_Surface surf(face, Standard_False);
    double kappa = 0;
    if (surf.GetType() != GeomAbs_Plane) {
      const std::array<double, 4> b = uv_bounds_of(features, fi - 1);
      const double u0 = b[0], u1 = b[1], v0 = b[2], v1 = b[3];
      BRepLProp_SLProps sl(surf, 2, 1e-9);
      int n = 0;
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
          sl.SetParameters(u0 + (u1 - u0) * (i + 0.5) / 6, v0 + (v1 - v0) * (j + 0.5) / 6);
          if (!sl.IsCurvatureDefined()) continue;
          kappa += std::max(std::abs(sl.MaxCurvature()), std::abs(sl.MinCurvature()));
          ++n;
        }
      if (n > 0) kappa /= n;
    }
    m.faces[k] = {props.Mass(), kappa, false};
  });
  for (const SolidMeasure::Piece& f : m.faces) m.area += f.size;
  std::vector<SolidMeasure::Piece> edges(ne, {0.0, 0.0, false});
  internal::on_two_cores_each(static_cast<std::size_t>(ne), [&](std::size_t e) {
    OCC_CATCH_SIGNALS
    const EdgeKind k = features.edge_kind[e];
    if (k != EdgeKind::Convex && k != EdgeKind::Concave && k != EdgeKind::Mixed) return;
    const BRepAdaptor_Curve curve(TopoDS::Edge(features.edges(static_cast<int>(e) + 1)));
    double kappa = 0;
    for (int i = 0; i <= 8; ++i) {
      gp_Pnt p;
      gp_Vec d1, d2;
      curve.D2(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / 8.0, p, d1, d2);
      const double n1 = d1.Magnitude();
      if (n1 > 1e-300) kappa = std::max(kappa, d1.Crossed(d2).Magnitude() / (n1 * n1 * n1));
    }
    edges[e] = {GCPnts_AbscissaPoint::Length(curve), kappa, k != EdgeKind::Concave};
    edges[e].edge = static_cast<int>(e);
  });
  for (int e = 0; e < ne; ++e) {
    if (edges[e].edge < 0) continue;
    const double len = edges[e].size;
    const EdgeKind k = features.edge_kind[e];
    m.sharp_edge_length += len;
    if (k != EdgeKind::Concave) m.convex_edge_length += len;
    m.sharp_edges.push_back(edges[e]);
    for (int f : features.edge_faces[e])
      if (f >= 0 && f < static_cast<int>(m.faces.size()))
        (k == EdgeKind::Concave ? m.faces[f].concave_edges : m.faces[f].convex_edges) += len;
  }
  return m;
}

namespace {

// Thinning keeps face samples at least r apart, which packs about one per kAreaPerSample r^2.
constexpr double kAreaPerSample = 1.47;

// The samples of a face's interior at spacing r (as curvature leaves it) with triplet legs
// `triplet` (sample_solid's rule; estimate_samples).
double face_samples(const SolidMeasure::Piece& f, double r, double triplet) {
  // Thinning keeps samples at least r apart, which packs about one per 1.47 r^2 (a 100 mm cube at
  // spacing 1 gets 39,168 face samples on the 57,600 mm^2 away from its edges). None lie within
  // 1.05 triplet legs and r / 2 of a convex edge (its triplets are there) or about r / 2 of a
  // concave one: those strips are taken off each face at its own density. (Taken off at the
  // uniform density, as before, a small curved face between convex edges was estimated at 260
  // samples where it got 29, on the Y-rod mount at spacing 3.4.)
  const double strips = f.convex_edges * (1.05 * triplet + 0.5 * r) + f.concave_edges * 0.5 * r;
  return std::max(0.0, f.size - strips) / (kAreaPerSample * r * r);
}

// Adds the samples of a sharp edge and, on a convex one, of its triplets at spacing sp to n.
void add_edge_samples(const SolidMeasure::Piece& e, const SampleSpacing& sp, double& n) {
  double h = sp.edge;
  if (e.curvature > 0) h = std::max(std::min(h, sp.max_turn_rad / e.curvature), 0.25 * sp.min_face);
  n += e.size / h;
  // A convex edge's samples come with two triplet points, which keep half a leg apart (a curved
  // edge's samples can be closer).
  if (e.convex) n += 2.0 * e.size / std::max(h, 0.5 * sp.triplet);
}

}  // namespace

double estimate_samples(const SolidMeasure& m, double spacing) {
  const SampleSpacing sp = sample_spacing(spacing);
  double faces = 0, edges = 0;
  for (const auto& f : m.faces) faces += face_samples(f, sp.face_at(f.curvature), sp.triplet);
  for (const auto& e : m.sharp_edges) add_edge_samples(e, sp, edges);
  return faces + edges;
}

double estimate_samples(const SolidMeasure& m, const Features& features, const SpacingField& field,
                        const Samples& first) {
  // The finest a face is sampled: its candidates come every half spacing, a lattice cell cut at
  // most 8 x 8, and thinning at r keeps one per kAreaPerSample r^2: at most 16^2 / 1.47 per
  // spacing^2.
  const double finest = 16.0 / std::sqrt(kAreaPerSample);
  const SampleSpacing sp = sample_spacing(field.uniform());
  const std::size_t nf = m.faces.size(), ne = features.edge_kind.size();
  double corners = 0, faces = 0;
  // Per face: its interior samples in `first`, what they stand for, and the local spacing at the
  // samples on and around it (its interior, its triplets, its edges' samples).
  std::vector<int> interior(nf, 0), near_count(nf, 0);
  std::vector<double> stand_for(nf, 0.0), near_sum(nf, 0.0);
  auto near = [&](int f, double h) {
    if (f < 0 || f >= static_cast<int>(nf)) return;
    near_sum[f] += h;
    ++near_count[f];
  };
  // Per edge: its samples in `first`, the chords between them (in order along it), the last one.
  std::vector<int> on_edge(ne, 0), last(ne, -1);
  std::vector<double> chords(ne, 0.0);
  for (std::size_t i = 0; i < first.size(); ++i) {
    const SampleTag tag = first.tag[i];
    const double h = field.at(first.points[i]);
    if (tag == SampleTag::Corner || tag == SampleTag::Ball) {
      corners += 1;
    } else if (tag == SampleTag::Face) {
      const double own = sp.face_at(first.curvature[i]);
      const double ratio = own / std::min(own, h);
      const double n = std::min(finest * finest, ratio * ratio);
      const int f = first.face[i];
      if (f < 0 || f >= static_cast<int>(nf)) {
        faces += n;
        continue;
      }
      ++interior[f];
      stand_for[f] += n;
      near(f, h);
    } else if (tag == SampleTag::Triplet) {
      near(first.face[i], h);
    } else if (tag == SampleTag::Edge) {
      const int e = first.edge[i];
      if (e < 0 || e >= static_cast<int>(ne)) continue;
      ++on_edge[e];
      if (last[e] >= 0) chords[e] += std::sqrt(distance2(first.points[i], first.points[last[e]]));
      last[e] = static_cast<int>(i);
      const auto& [a, b] = features.edge_faces[e];
      near(a, h);
      if (b != a) near(b, h);
    }
  }
  // A face with a few interior samples or none is narrow or small at the uniform spacing: they
  // stand for too little where the strips along its edges, which have no interior samples,
  // narrow at the finer spacing. By its area then, at the mean spacing around it.
  constexpr int kFewSamples = 8;
  for (std::size_t f = 0; f < nf; ++f) {
    if (interior[f] >= kFewSamples) {
      faces += stand_for[f];
      continue;
    }
    const double k = m.faces[f].curvature;
    const double around = near_count[f] > 0 ? near_sum[f] / near_count[f] : field.on_face(static_cast<int>(f));
    const double local = std::max(around, sp.face_at(k) / finest);
    const double r = sp.face_at(k, local);  // as try_face_candidate
    faces += std::max(stand_for[f], face_samples(m.faces[f], r, 0.5 * local));
  }
  // The sampler spaces an edge evenly by the smallest spacing on it: a sharp edge by its length
  // (with its triplets), any other by its samples in `first` and their gap (finer than the
  // spacing where the edge curves).
  double edges = 0;
  std::vector<char> sharp(ne, 0);
  for (const auto& e : m.sharp_edges) {
    if (e.edge < 0 || e.edge >= static_cast<int>(ne)) continue;
    sharp[e.edge] = 1;
    add_edge_samples(e, sample_spacing(field.on_edge(e.edge)), edges);
  }
  for (std::size_t e = 0; e < ne; ++e) {
    if (sharp[e] || on_edge[e] < 2) continue;
    const double gap = chords[e] / (on_edge[e] - 1), length = gap * (on_edge[e] + 1);
    const double h = std::min(gap, sample_spacing(field.on_edge(static_cast<int>(e))).face);
    edges += std::max<double>(on_edge[e], length / h - 1);
  }
  return corners + faces + edges;
}

}  // namespace cadmedial
