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
  const double reach = spacing + (spacing - smallest_) / gradation;
  grid_ = PointGrid(reach);
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
}

double SpacingField::at(const Point3& x) const {
  if (points_.empty()) return spacing_;
  double h = spacing_;
  const double reach = spacing_ + (spacing_ - smallest_) / gradation_;
  grid_.any_near(x, reach, [&](int k) {
    if (local_[k] >= h) return false;
    const double d = std::sqrt(distance2(points_[k], x));
    h = std::min(h, local_[k] + gradation_ * std::max(0.0, d - spacing_));
    return false;
  });
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
