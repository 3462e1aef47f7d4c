// Each test below is OpenCASCADE 7.6.3's CSLib_Class2d.cxx expression for expression (the same
// roundings: this file is compiled without floating-point contraction, see CMakeLists.txt).
#include "polygon_classifier.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace cadmedial {

namespace {

// CSLib_Class2d.cxx's Transform2d.
double transform2d(double u, double umin, double umaxmumin) { return umaxmumin > 1e-10 ? (u - umin) / umaxmumin : u; }

}  // namespace

PolygonClassifier::PolygonClassifier(StoredPolygon polygon) : p_(std::move(polygon)) {
  if (p_.x.size() != p_.y.size()) throw std::invalid_argument("PolygonClassifier: x and y differ in length");
  const int n = p_.n();
  if (n <= 0) return;
  double y1 = p_.y[0];
  y0_ = p_.y[0];
  bool finite = true;
  for (double y : p_.y) y0_ = std::min(y0_, y), y1 = std::max(y1, y), finite = finite && std::isfinite(y);
  // About two edges a band; one band when the polygon has no height or a coordinate that is not
  // finite (a NaN would fall in no band of its edges).
  bands_ = finite ? std::clamp(n / 2, 1, 1 << 16) : 1;
  band_height_ = (y1 - y0_) / bands_;
  if (!(band_height_ > 0) || !std::isfinite(band_height_)) bands_ = 1, band_height_ = 1;
  // Each edge in every band its y range meets. band_of is monotone in y, so an edge whose range
  // holds a height is in that height's band.
  auto range = [&](int i) {
    return std::pair<int, int>(band_of(std::min(p_.y[i], p_.y[i + 1])), band_of(std::max(p_.y[i], p_.y[i + 1])));
  };
  // Many edges that span many bands (a comb's teeth) would fill bands x edges: fewer bands then,
  // so that the lists hold at most about 8 entries an edge.
  for (;;) {
    std::int64_t entries = 0;
    for (int i = 0; i < n; ++i) {
      const auto [b0, b1] = range(i);
      entries += b1 - b0 + 1;
    }
    if (bands_ == 1 || entries <= 8 * static_cast<std::int64_t>(n)) break;
    bands_ = std::max(1, static_cast<int>(static_cast<double>(bands_) * 8.0 * n / static_cast<double>(entries)));
    band_height_ = (y1 - y0_) / bands_;
  }
  std::vector<int> count(static_cast<size_t>(bands_) + 1, 0);
  for (int i = 0; i < n; ++i) {
    const auto [b0, b1] = range(i);
    for (int b = b0; b <= b1; ++b) ++count[static_cast<size_t>(b) + 1];
  }
  start_.assign(static_cast<size_t>(bands_) + 1, 0);
  for (int b = 0; b < bands_; ++b) start_[b + 1] = start_[b] + count[static_cast<size_t>(b) + 1];
  edges_.resize(static_cast<size_t>(start_.back()));
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int i = 0; i < n; ++i) {
    const auto [b0, b1] = range(i);
    for (int b = b0; b <= b1; ++b) edges_[static_cast<size_t>(fill[b]++)] = i;
  }
}

int PolygonClassifier::band_of(double y) const {
  const double t = (y - y0_) / band_height_;
  if (!(t >= 0)) return 0;
  if (t >= bands_) return bands_ - 1;
  return static_cast<int>(t);
}

// Whether edge i counts in InternalSiDans's crossing number: its ends on both sides of the
// horizontal line through the point (SH != NH), and the crossing to the right of the point.
bool PolygonClassifier::crosses(int i, double px, double py) const {
  const double x = p_.x[i] - px, y = p_.y[i] - py;
  const double nx = p_.x[i + 1] - px, ny = p_.y[i + 1] - py;
  if ((y < 0.) == (ny < 0.)) return false;
  if (x > 0. && nx > 0.) return true;
  if (x > 0.0 || nx > 0.) return (x - y * (nx - x) / (ny - y)) > 0.;
  return false;
}

int PolygonClassifier::internal_si_dans(double px, double py) const {
  int nbc = 0;
  if (start_.empty()) return 0;  // no polygon (SiDans answers "on" before asking)
  if (!std::isfinite(px) || !std::isfinite(py)) {
    for (int i = 0; i < p_.n(); ++i) nbc += crosses(i, px, py);
    return nbc & 1;
  }
  // Only an edge whose y range holds py can have its ends on both sides of it.
  const int b = band_of(py);
  for (int k = start_[b]; k < start_[b + 1]; ++k) nbc += crosses(edges_[k], px, py);
  return nbc & 1;
}

int PolygonClassifier::internal_si_dans_ou_on(double px, double py) const {
  if (start_.empty()) return 0;
  const double tolu = p_.tolu, tolv = p_.tolv;
  // "On": the edge's end within the tolerance box of the point, or the edge's height at px
  // within tolv of py.
  const auto on = [&](int i) {
    const double nx = p_.x[i + 1] - px, ny = p_.y[i + 1] - py;
    if (nx < tolu && nx > -tolu && ny < tolv && ny > -tolv) return true;
    const double dx = p_.x[i + 1] - p_.x[i];
    if ((p_.x[i] - px) * nx < 0.) {
      const double cur = p_.y[i + 1] - (p_.y[i + 1] - p_.y[i]) / dx * nx;
      const double delta = cur - py;
      if (delta >= -tolv && delta <= tolv) return true;
    }
    return false;
  };
  if (!std::isfinite(px) || !std::isfinite(py) || !std::isfinite(tolv)) {
    for (int i = 0; i < p_.n(); ++i)
      if (on(i)) return -1;
    return internal_si_dans(px, py);
  }
  // Both tests need the edge's y range within tolv of py: the end's height, or a height between
  // its ends (to rounding, which the margin covers).
  const double margin = 1e-9 * (std::abs(py) + std::abs(y0_) + std::abs(y0_ + band_height_ * bands_) + tolv) + 1e-300;
  const int b0 = band_of(py - tolv - margin), b1 = band_of(py + tolv + margin);
  for (int b = b0; b <= b1; ++b)
    for (int k = start_[b]; k < start_[b + 1]; ++k)
      if (on(edges_[k])) return -1;
  return internal_si_dans(px, py);
}

int PolygonClassifier::si_dans(double u, double v) const {
  if (p_.n() <= 0) return 0;
  double x = u, y = v;
  const double atolu = p_.tolu * (p_.umax - p_.umin), atolv = p_.tolv * (p_.vmax - p_.vmin);
  if (p_.umin < p_.umax && p_.vmin < p_.vmax) {
    if ((x < (p_.umin - atolu)) || (x > (p_.umax + atolu)) || (y < (p_.vmin - atolv)) || (y > (p_.vmax + atolv)))
      return -1;
    x = transform2d(x, p_.umin, p_.umax - p_.umin);
    y = transform2d(y, p_.vmin, p_.vmax - p_.vmin);
  }
  const int res = internal_si_dans_ou_on(x, y);
  if (res == -1) return 0;
  if (p_.tolu != 0 || p_.tolv != 0) {
    if (res != internal_si_dans(x - p_.tolu, y - p_.tolv)) return 0;
    if (res != internal_si_dans(x + p_.tolu, y - p_.tolv)) return 0;
    if (res != internal_si_dans(x - p_.tolu, y + p_.tolv)) return 0;
    if (res != internal_si_dans(x + p_.tolu, y + p_.tolv)) return 0;
  }
  return res ? 1 : -1;
}

}  // namespace cadmedial
