#include "lattice_classifier.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <CSLib_Class2d.hxx>
#include <Standard_Version.hxx>
#include <TColStd_Array1OfReal.hxx>

namespace cadmedial {

namespace {

// OpenCASCADE keeps the classifier's polygons private. Access checking does not apply to names in
// an explicit instantiation (C++17 [temp.explicit]), so Expose<Tag, &Class::field> defines
// member(Tag{}), the pointer to that member, without editing or redefining OpenCASCADE's classes.
// A renamed or retyped field fails to compile; a changed meaning would not, hence the version check.
static_assert(OCC_VERSION_HEX >= 0x070600 && OCC_VERSION_HEX < 0x070800,
              "LatticeClassifier reads BRepTopAdaptor_FClass2d's polygons as OpenCASCADE 7.6 and 7.7 "
              "build them: check BRepTopAdaptor_FClass2d.cxx and CSLib_Class2d.cxx before allowing another version");

template <class Tag, typename Tag::type Member>
struct Expose {
  friend typename Tag::type member(Tag) { return Member; }
};

#define CADMEDIAL_EXPOSE(TAG, CLASS, TYPE, FIELD)  \
  struct TAG {                                     \
    using type = TYPE CLASS::*;                    \
    friend type member(TAG);                       \
  };                                               \
  template struct Expose<TAG, &CLASS::FIELD>;

CADMEDIAL_EXPOSE(TabClass, BRepTopAdaptor_FClass2d, BRepTopAdaptor_SeqOfPtr, TabClass)
CADMEDIAL_EXPOSE(TabOrien, BRepTopAdaptor_FClass2d, TColStd_SequenceOfInteger, TabOrien)
CADMEDIAL_EXPOSE(FaceUMin, BRepTopAdaptor_FClass2d, Standard_Real, Umin)
CADMEDIAL_EXPOSE(FaceUMax, BRepTopAdaptor_FClass2d, Standard_Real, Umax)
CADMEDIAL_EXPOSE(FaceVMin, BRepTopAdaptor_FClass2d, Standard_Real, Vmin)
CADMEDIAL_EXPOSE(FaceVMax, BRepTopAdaptor_FClass2d, Standard_Real, Vmax)
CADMEDIAL_EXPOSE(PolyX, CSLib_Class2d, NCollection_Handle<TColStd_Array1OfReal>, MyPnts2dX)
CADMEDIAL_EXPOSE(PolyY, CSLib_Class2d, NCollection_Handle<TColStd_Array1OfReal>, MyPnts2dY)
CADMEDIAL_EXPOSE(PolyN, CSLib_Class2d, Standard_Integer, N)
CADMEDIAL_EXPOSE(PolyTolU, CSLib_Class2d, Standard_Real, Tolu)
CADMEDIAL_EXPOSE(PolyTolV, CSLib_Class2d, Standard_Real, Tolv)
CADMEDIAL_EXPOSE(PolyUMin, CSLib_Class2d, Standard_Real, Umin)
CADMEDIAL_EXPOSE(PolyUMax, CSLib_Class2d, Standard_Real, Umax)
CADMEDIAL_EXPOSE(PolyVMin, CSLib_Class2d, Standard_Real, Vmin)
CADMEDIAL_EXPOSE(PolyVMax, CSLib_Class2d, Standard_Real, Vmax)

#undef CADMEDIAL_EXPOSE

// One axis of a CSLib_Class2d polygon: it stores coordinates as (x - min) / (max - min) when
// max - min > 1e-10 (else as they are), and its tolerance in the same units.
struct Axis {
  double min, range;
  bool scaled() const { return range > 1e-10; }
  double real(double stored) const { return scaled() ? stored * range + min : stored; }
  double real_length(double stored) const { return scaled() ? stored * range : stored; }
};

}  // namespace

StoredPolygon stored_polygon(const CSLib_Class2d& poly) {
  StoredPolygon p;
  const int n = poly.*member(PolyN{});
  p.umin = poly.*member(PolyUMin{});
  p.umax = poly.*member(PolyUMax{});
  p.vmin = poly.*member(PolyVMin{});
  p.vmax = poly.*member(PolyVMax{});
  if (n <= 0) return p;  // CSLib_Class2d leaves its tolerances unset then
  p.tolu = poly.*member(PolyTolU{});
  p.tolv = poly.*member(PolyTolV{});
  const TColStd_Array1OfReal& xs = *(poly.*member(PolyX{}));
  const TColStd_Array1OfReal& ys = *(poly.*member(PolyY{}));
  for (int k = 0; k <= n; ++k) p.x.push_back(xs(k)), p.y.push_back(ys(k));
  return p;
}

LatticeClassifier::LatticeClassifier(const BRepTopAdaptor_FClass2d& classifier, const BRepAdaptor_Surface& surface,
                                     const UvLattice& lattice)
    : classifier_(classifier), lat_(lattice) {
  u_periodic_ = surface.IsUPeriodic();
  v_periodic_ = surface.IsVPeriodic();
  u_period_ = u_periodic_ ? surface.UPeriod() : 0.0;
  v_period_ = v_periodic_ ? surface.VPeriod() : 0.0;
  umin_ = classifier_.*member(FaceUMin{});
  umax_ = classifier_.*member(FaceUMax{});
  vmin_ = classifier_.*member(FaceVMin{});
  vmax_ = classifier_.*member(FaceVMax{});
  const BRepTopAdaptor_SeqOfPtr& wires = classifier_.*member(TabClass{});
  // A face without extent in u or v: no cells to speak of.
  usable_ = lat_.du > 0 && lat_.dv > 0 && std::isfinite(lat_.u0 + lat_.du * lat_.nu) &&
            std::isfinite(lat_.v0 + lat_.dv * lat_.nv);
  if (usable_ && wires.Length() > 0) {
    // A wire that could not be made a polygon turns Perform into BRepClass_FaceClassifier on
    // every point (TabOrien(1) == -1); an empty polygon answers "on" everywhere.
    if ((classifier_.*member(TabOrien{}))(1) == -1) usable_ = false;
    for (int w = 1; w <= wires.Length() && usable_; ++w) {
      const auto* poly = static_cast<const CSLib_Class2d*>(wires(w));
      if (poly == nullptr || poly->*member(PolyN{}) <= 0) usable_ = false;
    }
  }
  if (!usable_) return;
  region_.assign(static_cast<size_t>(lat_.nu) * static_cast<size_t>(lat_.nv), 0);
  mark_polygons();
  label_regions();
  const TColStd_SequenceOfInteger& orientation = classifier_.*member(TabOrien{});
  for (int w = 1; w <= wires.Length(); ++w) {
    polygons_.emplace_back(stored_polygon(*static_cast<const CSLib_Class2d*>(wires(w))));
    orientation_.push_back(orientation(w));
  }
}

// Marks every cell that a polygon's tolerance box may reach: each polygon edge is cut into pieces
// no longer than a cell, and each piece's bounding box, grown by the tolerance and a margin for
// rounding, marks the cells it overlaps. That covers the edge swept by the box. Also keeps each
// polygon's grown bounding box.
void LatticeClassifier::mark_polygons() {
  const BRepTopAdaptor_SeqOfPtr& wires = classifier_.*member(TabClass{});
  const double lu0 = lat_.u0, lv0 = lat_.v0, lu1 = lat_.u0 + lat_.du * lat_.nu, lv1 = lat_.v0 + lat_.dv * lat_.nv;
  for (int w = 1; w <= wires.Length(); ++w) {
    const auto& poly = *static_cast<const CSLib_Class2d*>(wires(w));
    const Axis ax{poly.*member(PolyUMin{}), poly.*member(PolyUMax{}) - poly.*member(PolyUMin{})};
    const Axis ay{poly.*member(PolyVMin{}), poly.*member(PolyVMax{}) - poly.*member(PolyVMin{})};
    const TColStd_Array1OfReal& xs = *(poly.*member(PolyX{}));
    const TColStd_Array1OfReal& ys = *(poly.*member(PolyY{}));
    const int n = poly.*member(PolyN{});
    // Rounding in the stored (scaled) coordinates and in ours is far below these margins.
    const double scale_u = std::abs(ax.min) + std::abs(ax.range) + std::abs(lu0) + std::abs(lu1);
    const double scale_v = std::abs(ay.min) + std::abs(ay.range) + std::abs(lv0) + std::abs(lv1);
    const double pad_u = ax.real_length(poly.*member(PolyTolU{})) * (1 + 1e-6) + 1e-9 * lat_.du + 1e-12 * scale_u;
    const double pad_v = ay.real_length(poly.*member(PolyTolV{})) * (1 + 1e-6) + 1e-9 * lat_.dv + 1e-12 * scale_v;
    Box box{1e300, -1e300, 1e300, -1e300};
    // The points run 0..n with point n == point 0 (CSLib_Class2d closes the polygon).
    for (int k = 0; k < n; ++k) {
      const double xa = ax.real(xs(k)), ya = ay.real(ys(k));
      const double xb = ax.real(xs(k + 1)), yb = ay.real(ys(k + 1));
      box = {std::min(box.u0, xa), std::max(box.u1, xa), std::min(box.v0, ya), std::max(box.v1, ya)};
      // Clip the edge to the lattice grown by a cell and the margins: nothing beyond can mark.
      double t0 = 0, t1 = 1;
      const double lo[2] = {lu0 - lat_.du - pad_u, lv0 - lat_.dv - pad_v};
      const double hi[2] = {lu1 + lat_.du + pad_u, lv1 + lat_.dv + pad_v};
      const double p[2] = {xa, ya}, d[2] = {xb - xa, yb - ya};
      bool inside = true;
      for (int a = 0; a < 2 && inside; ++a) {
        if (d[a] == 0) {
          inside = p[a] >= lo[a] && p[a] <= hi[a];
          continue;
        }
        double ta = (lo[a] - p[a]) / d[a], tb = (hi[a] - p[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        inside = t0 <= t1;
      }
      if (!inside) continue;
      const double cells = std::max(std::abs(d[0]) * (t1 - t0) / lat_.du, std::abs(d[1]) * (t1 - t0) / lat_.dv);
      const long pieces = std::max(1L, static_cast<long>(std::ceil(cells)));
      for (long s = 0; s < pieces; ++s) {
        const double ta = t0 + (t1 - t0) * s / pieces, tb = t0 + (t1 - t0) * (s + 1) / pieces;
        const double x0 = xa + d[0] * ta, x1 = xa + d[0] * tb, y0 = ya + d[1] * ta, y1 = ya + d[1] * tb;
        const double ilo = std::floor((std::min(x0, x1) - pad_u - lu0) / lat_.du);
        const double ihi = std::floor((std::max(x0, x1) + pad_u - lu0) / lat_.du);
        const double jlo = std::floor((std::min(y0, y1) - pad_v - lv0) / lat_.dv);
        const double jhi = std::floor((std::max(y0, y1) + pad_v - lv0) / lat_.dv);
        if (ihi < 0 || jhi < 0 || ilo >= lat_.nu || jlo >= lat_.nv) continue;
        const long i0 = std::max(0L, static_cast<long>(ilo)), i1 = std::min(lat_.nu - 1, static_cast<long>(ihi));
        const long j0 = std::max(0L, static_cast<long>(jlo)), j1 = std::min(lat_.nv - 1, static_cast<long>(jhi));
        for (long i = i0; i <= i1; ++i)
          for (long j = j0; j <= j1; ++j) region_[static_cast<size_t>(i * lat_.nv + j)] = -1;
      }
    }
    wire_boxes_.push_back({box.u0 - pad_u, box.u1 + pad_u, box.v0 - pad_v, box.v1 + pad_v});
  }
}

// Connected regions of unmarked cells (sharing a side), numbered in scan order.
void LatticeClassifier::label_regions() {
  constexpr std::int32_t kUnlabelled = 0, kMarked = -1;
  // Unmarked cells hold 0 until labelled; labels are stored as 1 + region while filling.
  std::vector<long> stack;
  std::int32_t regions = 0;
  const long nu = lat_.nu, nv = lat_.nv;
  for (long start = 0; start < nu * nv; ++start) {
    if (region_[static_cast<size_t>(start)] != kUnlabelled) continue;
    const std::int32_t label = ++regions;
    region_[static_cast<size_t>(start)] = label;
    stack.push_back(start);
    while (!stack.empty()) {
      const long c = stack.back();
      stack.pop_back();
      const long i = c / nv, j = c % nv;
      const long next[4] = {i > 0 ? c - nv : -1, i + 1 < nu ? c + nv : -1, j > 0 ? c - 1 : -1, j + 1 < nv ? c + 1 : -1};
      for (long m : next)
        if (m >= 0 && region_[static_cast<size_t>(m)] == kUnlabelled) {
          region_[static_cast<size_t>(m)] = label;
          stack.push_back(m);
        }
    }
  }
  for (std::int32_t& r : region_)
    if (r != kMarked) --r;
  region_state_.assign(static_cast<size_t>(regions), State::Unknown);
}

// Perform(uv, Standard_False)'s loop over the wires, with TabOrien(1) != -1 (usable_): IN unless a
// wire says otherwise; a point "on" a wire (within its tolerance) is where Perform asks
// BRepClass_FaceClassifier instead: left to Perform.
LatticeClassifier::State LatticeClassifier::wires_state(const gp_Pnt2d& uv) const {
  for (size_t n = 0; n < polygons_.size(); ++n) {
    const int cur = polygons_[n].si_dans(uv.X(), uv.Y());
    if (cur == 1) {
      if (orientation_[n] == 0) return State::Out;
    } else if (cur == -1) {
      if (orientation_[n] == 1) return State::Out;
    } else {
      return State::Ask;
    }
  }
  return State::In;
}

// The first point asked for a set of points that share their state is classified as Perform
// would (no point of such a set is "on" a wire; if one were, Perform itself answers).
LatticeClassifier::State LatticeClassifier::remember(State& slot, const gp_Pnt2d& uv) {
  if (slot == State::Unknown) {
    slot = wires_state(uv);
    if (slot == State::Ask) {
      const TopAbs_State st = classifier_.Perform(uv, Standard_False);
      slot = st == TopAbs_IN ? State::In : st == TopAbs_OUT ? State::Out : State::Ask;
    }
  }
  return slot;
}

LatticeClassifier::State LatticeClassifier::polygon_state(long i, long j, const gp_Pnt2d& uv) {
  const std::int32_t r = region_[static_cast<size_t>(i * lat_.nv + j)];
  if (r < 0) return State::Ask;
  return remember(region_state_[static_cast<size_t>(r)], uv);
}

LatticeClassifier::State LatticeClassifier::polygon_state(const gp_Pnt2d& uv) {
  // Not a point to remember a state by.
  if (!std::isfinite(uv.X()) || !std::isfinite(uv.Y())) return State::Ask;
  // A point on a side between two cells may go to either: the marks leave a margin around both.
  const double fi = std::floor((uv.X() - lat_.u0) / lat_.du), fj = std::floor((uv.Y() - lat_.v0) / lat_.dv);
  if (fi >= 0 && fi < lat_.nu && fj >= 0 && fj < lat_.nv)
    return polygon_state(static_cast<long>(fi), static_cast<long>(fj), uv);
  // Outside a polygon's grown box, its test returns "outside" without looking at its edges (the
  // box test) or finds no crossing and no point within tolerance (the parity test).
  for (const Box& b : wire_boxes_)
    if (uv.X() >= b.u0 && uv.X() <= b.u1 && uv.Y() >= b.v0 && uv.Y() <= b.v1) return State::Ask;
  return remember(far_state_, uv);
}

// Perform(uv) after its first test found `first`: BRepTopAdaptor_FClass2d::Perform returns IN or
// ON at once; otherwise, on a periodic surface, it brings u (v) to the period starting at its
// Umin (Vmin) and tests the shifted copies up to Umax (Vmax) in this order.
LatticeClassifier::Answer LatticeClassifier::with_retries(const gp_Pnt2d& uv, State first, bool exact) {
  if (first == State::Ask) return Answer::Ask;
  if (first == State::In) return Answer::In;
  if (!u_periodic_ && !v_periodic_) return Answer::Out;
  double u = uv.X(), v = uv.Y(), uu = u, vv = v;
  if (u_periodic_) {
    if (uu < umin_) {
      while (uu < umin_) uu += u_period_;
    } else {
      while (uu >= umin_) uu -= u_period_;
      uu += u_period_;
    }
  }
  if (v_periodic_) {
    if (vv < vmin_) {
      while (vv < vmin_) vv += v_period_;
    } else {
      while (vv >= vmin_) vv -= v_period_;
      vv += v_period_;
    }
  }
  bool u_shifted = false, v_shifted = false;
  for (int tries = 0; tries < 1000; ++tries) {
    if (!u_shifted) {
      u = uu;
      u_shifted = true;
    } else if (u_periodic_) {
      u += u_period_;
    }
    if (u > umax_ || !u_periodic_) {
      if (!v_shifted) {
        v = vv;
        v_shifted = true;
      } else if (v_periodic_) {
        v += v_period_;
      }
      u = uu;
      if (v > vmax_ || !v_periodic_) return Answer::Out;
    }
    const State s = exact ? wires_state(gp_Pnt2d(u, v)) : polygon_state(gp_Pnt2d(u, v));
    if (s != State::Out) return s == State::In ? Answer::In : Answer::Ask;
  }
  return Answer::Ask;
}

LatticeClassifier::Answer LatticeClassifier::classify(long i, long j, const gp_Pnt2d& uv) {
  return checked(usable_ ? with_retries(uv, polygon_state(i, j, uv)) : Answer::Ask, uv);
}

LatticeClassifier::Answer LatticeClassifier::classify(const gp_Pnt2d& uv) {
  return checked(usable_ ? with_retries(uv, polygon_state(uv)) : Answer::Ask, uv);
}

LatticeClassifier::Answer LatticeClassifier::exact(const gp_Pnt2d& uv) {
  return checked(usable_ ? with_retries(uv, wires_state(uv), true) : Answer::Ask, uv);
}

// Build with CADMEDIAL_VERIFY_LATTICE_CLASSIFIER defined to check every answer against Perform
// (slow): the sampling then throws at the first disagreement.
LatticeClassifier::Answer LatticeClassifier::checked(Answer a, const gp_Pnt2d& uv) const {
#ifdef CADMEDIAL_VERIFY_LATTICE_CLASSIFIER
  if (a != Answer::Ask && (classifier_.Perform(uv) == TopAbs_IN) != (a == Answer::In))
    throw std::logic_error("LatticeClassifier disagrees with Perform at (" + std::to_string(uv.X()) + ", " +
                           std::to_string(uv.Y()) + ")");
#else
  (void)uv;
#endif
  return a;
}

}  // namespace cadmedial
