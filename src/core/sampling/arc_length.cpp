#include "arc_length.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Adaptor3d_Curve.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace cadmedial {

namespace {

// 8-point Gauss-Legendre on [-1, 1]: the positive nodes and their weights.
constexpr std::array<double, 4> kNode = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                         0.9602898564975363};
constexpr std::array<double, 4> kWeight = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                           0.1012285362903763};
constexpr int kSeeds = 16;     // pieces over [t0, t1] before any split, besides the curve's own spans
constexpr int kMaxDepth = 24;  // halvings of a seed (a cusp, where the speed vanishes, converges slowly)
constexpr double kRelative = 1e-10;
constexpr std::size_t kMaxPieces = 100000;  // past this (a speed that never settles), pieces are taken as they are

}  // namespace

ArcLength::ArcLength(const Adaptor3d_Curve& curve, double t0, double t1)
    : curve_(curve), closed_form_(curve.GetType() == GeomAbs_Line || curve.GetType() == GeomAbs_Circle) {
  if (closed_form_ || !(t1 > t0)) {
    end_ = {t0, std::max(t0, t1)};
    before_ = {0.0, closed_form_ ? GCPnts_AbscissaPoint::Length(curve, t0, end_[1]) : 0.0};
    return;
  }
  // Seeds: where OpenCASCADE breaks C3 (a cubic B-spline's knots; none on a periodic B-spline
  // trimmed off its base period: the halving below copes), each span cut into its share of kSeeds.
  std::vector<double> cuts = {t0};
  const int spans = curve.NbIntervals(GeomAbs_C3);
  TColStd_Array1OfReal bounds(1, spans + 1);
  curve.Intervals(bounds, GeomAbs_C3);
  std::vector<double> breaks;
  for (int k = bounds.Lower(); k <= bounds.Upper(); ++k)
    if (bounds(k) > t0 && bounds(k) < t1) breaks.push_back(bounds(k));
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  breaks.push_back(t1);
  for (double b : breaks) {
    const double a = cuts.back();
    const int n = std::max(1, static_cast<int>(std::ceil(kSeeds * (b - a) / (t1 - t0))));
    for (int i = 1; i < n; ++i) cuts.push_back(a + (b - a) * i / n);
    cuts.push_back(b);
  }
  std::vector<double> seed(cuts.size() - 1);
  double rough = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) rough += seed[i] = gauss(cuts[i], cuts[i + 1]);
  tolerance_ = kRelative * rough;
  end_ = {t0};
  before_ = {0.0};
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) add_pieces(cuts[i], cuts[i + 1], seed[i], 0);
}

double ArcLength::speed(double t) const {
  gp_Pnt p;
  gp_Vec d1;
  curve_.D1(t, p, d1);
  return d1.Magnitude();
}

double ArcLength::gauss(double a, double b) const {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double sum = 0;
  for (std::size_t k = 0; k < kNode.size(); ++k)
    sum += kWeight[k] * (speed(mid - half * kNode[k]) + speed(mid + half * kNode[k]));
  return half * sum;
}

void ArcLength::add_pieces(double a, double b, double whole, int depth) {
  const double m = 0.5 * (a + b), left = gauss(a, m), right = gauss(m, b);
  if (depth < kMaxDepth && end_.size() < kMaxPieces && std::abs(left + right - whole) > tolerance_) {
    add_pieces(a, m, left, depth + 1);
    add_pieces(m, b, right, depth + 1);
    return;
  }
  // Kept as two pieces: one Gauss rule over part of a half is then as good as over the half.
  end_.push_back(m);
  before_.push_back(before_.back() + left);
  end_.push_back(b);
  before_.push_back(before_.back() + right);
}

double ArcLength::length_to(double t) const {
  t = std::clamp(t, end_.front(), end_.back());
  const std::size_t i = std::min<std::size_t>(
      std::upper_bound(end_.begin(), end_.end(), t) - end_.begin() - 1, end_.size() - 2);
  return before_[i] + gauss(end_[i], t);
}

double ArcLength::parameter_at(double s) const {
  if (s <= 0) return end_.front();
  if (s >= before_.back()) return end_.back();
  const std::size_t i = std::min<std::size_t>(
      std::upper_bound(before_.begin(), before_.end(), s) - before_.begin() - 1, end_.size() - 2);
  const double a = end_[i], piece = before_[i + 1] - before_[i], r = s - before_[i];
  // Newton on gauss(a, t) = r, kept inside the piece by bisection.
  double lo = a, hi = end_[i + 1];
  double t = piece > 0 ? a + (hi - a) * (r / piece) : 0.5 * (lo + hi);
  for (int it = 0; it < 60; ++it) {
    const double f = gauss(a, t) - r;
    if (std::abs(f) <= 0.01 * tolerance_) break;
    (f > 0 ? hi : lo) = t;
    const double v = speed(t);
    double next = v > 0 ? t - f / v : lo;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == t) break;
    t = next;
  }
  return t;
}

double ArcLength::length(double a, double b) const {
  if (closed_form_) return GCPnts_AbscissaPoint::Length(curve_, a, b);
  return length_to(b) - length_to(a);
}

double ArcLength::parameter(double ds, double from) const {
  if (closed_form_) return std::clamp(GCPnts_AbscissaPoint(curve_, ds, from).Parameter(), end_.front(), end_.back());
  return parameter_at(length_to(from) + ds);
}

}  // namespace cadmedial
