#include "spacing_field.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "../two_cores.h"

namespace cadmedial {

SpacingField::SpacingField(double spacing, const std::vector<Point3>& points, const std::vector<double>& local,
                           double gradation)
    : spacing_(spacing), gradation_(gradation), grid_(spacing) {
  if (points.empty()) return;
  smallest_ = *std::min_element(local.begin(), local.end());
  // A point's spacing holds within one (uniform) spacing of it, the first pass's sample spacing,
  // and reaches the uniform spacing (spacing - local) / gradation farther: at most this far.
  reach_ = reach();
  grid_ = PointGrid(reach_);
  // Smallest first; a point within 10 % of what the kept points already give is left out (the
  // field is then at most 10 % coarser there), which keeps the queries short on large thin walls.
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return local[a] < local[b]; });
  for (int k : order) {
    if (at(points[k]) <= 1.1 * local[k]) continue;
    grid_.insert(points[k], static_cast<int>(points_.size()));
    points_.push_back(points[k]);
    local_.push_back(local[k]);
  }
  index_cells();
}

void SpacingField::index_cells() {
  if (points_.empty()) return;
  std::array<int64_t, 3> hi{0, 0, 0};
  for (int a = 0; a < 3; ++a) lo_[a] = hi[a] = cell_of(points_[0][a]);
  for (const Point3& p : points_)
    for (int a = 0; a < 3; ++a) lo_[a] = std::min(lo_[a], cell_of(p[a])), hi[a] = std::max(hi[a], cell_of(p[a]));
  double cells = 1;
  for (int a = 0; a < 3; ++a) cells *= static_cast<double>(hi[a] - lo_[a] + 1);
  // A box far larger than the points need (a few far-apart thin walls): keep the hash grid.
  if (!(cells <= 4.0 * static_cast<double>(points_.size()) + 65536.0)) return;
  for (int a = 0; a < 3; ++a) size_[a] = hi[a] - lo_[a] + 1;
  const auto index = [&](const Point3& p) {
    return static_cast<size_t>(((cell_of(p[0]) - lo_[0]) * size_[1] + (cell_of(p[1]) - lo_[1])) * size_[2] +
                               (cell_of(p[2]) - lo_[2]));
  };
  cell_start_.assign(static_cast<size_t>(cells) + 1, 0);
  for (const Point3& p : points_) ++cell_start_[index(p) + 1];
  for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  items_.resize(points_.size());
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (size_t k = 0; k < points_.size(); ++k) items_[static_cast<size_t>(fill[index(points_[k])]++)] = {points_[k], local_[k]};
}

double SpacingField::at(const Point3& x) const {
  if (points_.empty()) return spacing_;
  // Not a point on the part: no point of the field is near it.
  if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) return spacing_;
  double h = spacing_;
  const auto lower = [&](const Point3& p, double local) {
    const double d = std::sqrt(distance2(p, x));
    h = std::min(h, local + gradation_ * std::max(0.0, d - spacing_));
  };
  if (cell_start_.empty()) {
    grid_.any_near(x, reach_, [&](int k) {
      if (local_[k] < h) lower(points_[k], local_[k]);
      return false;
    });
    return h;
  }
  // The cells grid_.any_near(x, reach_) visits (cells as large as the reach: the block of one
  // around x's cell, within the rounding margin of x -/+ reach), here in the dense box. A cell's
  // points come smallest local first: once one cannot lower h, the rest cannot either.
  for (int a = 0; a < 3; ++a) {
    const double c = std::floor(x[a] / reach_);
    if (!(c >= static_cast<double>(lo_[a] - 1) && c <= static_cast<double>(lo_[a] + size_[a]))) return spacing_;
  }
  const double margin = reach_ + 1e-12 * (reach_ + std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2]));
  int64_t from[3], to[3];
  for (int a = 0; a < 3; ++a) {
    const int64_t c = cell_of(x[a]);
    from[a] = std::max({cell_of(x[a] - margin), c - 1, lo_[a]}) - lo_[a];
    to[a] = std::min({cell_of(x[a] + margin), c + 1, lo_[a] + size_[a] - 1}) - lo_[a];
  }
  for (int64_t i = from[0]; i <= to[0]; ++i)
    for (int64_t j = from[1]; j <= to[1]; ++j)
      for (int64_t k = from[2]; k <= to[2]; ++k) {
        const size_t c = static_cast<size_t>((i * size_[1] + j) * size_[2] + k);
        for (int e = cell_start_[c]; e < cell_start_[c + 1] && items_[static_cast<size_t>(e)].local < h; ++e)
          lower(items_[static_cast<size_t>(e)].point, items_[static_cast<size_t>(e)].local);
      }
  return h;
}

void SpacingField::measure_on(const Samples& s, const std::vector<std::array<int, 2>>& edge_faces) {
  face_.assign(s.faces.size(), spacing_);
  edge_.assign(edge_faces.size(), spacing_);
  if (points_.empty()) return;
  // Half the samples on each of two cores, each with its own minima (the queries were a third of
  // the refinement's field time on NIST CTC 02 at 66k samples); the smaller of the two counts.
  std::vector<double> face2 = face_, edge2 = edge_;
  internal::on_two_halves(s.size(), [&](int part, std::size_t begin, std::size_t end) {
    std::vector<double>& face = part ? face2 : face_;
    std::vector<double>& edge = part ? edge2 : edge_;
    for (std::size_t i = begin; i < end; ++i) {
      const double h = at(s.points[i]);
      if (!(h < spacing_)) continue;
      if (s.face[i] >= 0 && s.face[i] < static_cast<int>(face.size())) face[s.face[i]] = std::min(face[s.face[i]], h);
      const int e = s.edge[i];
      if (e < 0 || e >= static_cast<int>(edge.size())) continue;
      edge[e] = std::min(edge[e], h);
      for (int f : edge_faces[e])
        if (f >= 0 && f < static_cast<int>(face.size())) face[f] = std::min(face[f], h);
    }
  });
  for (std::size_t f = 0; f < face_.size(); ++f) face_[f] = std::min(face_[f], face2[f]);
  for (std::size_t e = 0; e < edge_.size(); ++e) edge_[e] = std::min(edge_[e], edge2[e]);
}

SpacingField thin_wall_spacing(const Samples& first, const std::vector<double>& radii, double spacing,
                               double per_radius, double max_refine, double gradation) {
  std::vector<Point3> points;
  std::vector<double> local;
  const double floor = spacing / max_refine;
  for (std::size_t i = 0; i < first.size(); ++i) {
    const double h = per_radius * radii[i];
    if (!(h < spacing)) continue;
    points.push_back(first.points[i]);
    local.push_back(std::max(floor, h));
  }
  if (points.empty()) return SpacingField(spacing);
  return SpacingField(spacing, points, local, gradation);
}

}  // namespace cadmedial
