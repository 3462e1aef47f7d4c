#include "support/revolved_medial_axis.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "support/random.h"

namespace cadmedial::test {

RevolvedMedialAxis RevolvedMedialAxis::cylinder(double R, double H) {
  RevolvedMedialAxis a;
  a.kind_ = Kind::Cylinder;
  a.R_ = R;
  a.H_ = H;
  if (H >= 2 * R) {
    a.segments_ = {{Vec2{R, 0}, Vec2{0, R}}, {Vec2{R, H}, Vec2{0, H - R}}, {Vec2{0, R}, Vec2{0, H - R}}};
  } else {
    const double m = R - H / 2;
    a.segments_ = {{Vec2{R, 0}, Vec2{m, H / 2}}, {Vec2{R, H}, Vec2{m, H / 2}}, {Vec2{0, H / 2}, Vec2{m, H / 2}}};
  }
  return a;
}

RevolvedMedialAxis RevolvedMedialAxis::sphere(double R) {
  RevolvedMedialAxis a;
  a.kind_ = Kind::Sphere;
  a.R_ = R;
  a.segments_ = {{Vec2{0, 0}, Vec2{0, 0}}};
  return a;
}

RevolvedMedialAxis RevolvedMedialAxis::torus(double R, double r) {
  RevolvedMedialAxis a;
  a.kind_ = Kind::Torus;
  a.R_ = R;
  a.r_ = r;
  a.segments_ = {{Vec2{R, 0}, Vec2{R, 0}}};
  return a;
}

double RevolvedMedialAxis::distance(const Vec3& x) const {
  const Vec3 p{std::hypot(x[0], x[1]), x[2], 0};
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : segments_)
    best = std::min(best, point_segment_distance(p, Vec3{s[0][0], s[0][1], 0}, Vec3{s[1][0], s[1][1], 0}));
  return best;
}

double RevolvedMedialAxis::boundary_distance(const Vec3& x) const {
  const double rho = std::hypot(x[0], x[1]);
  switch (kind_) {
    case Kind::Cylinder:
      return std::min({R_ - rho, x[2], H_ - x[2]});
    case Kind::Sphere:
      return R_ - norm(x);
    case Kind::Torus:
      return r_ - std::hypot(rho - R_, x[2]);
  }
  return 0;
}

std::vector<Vec3> RevolvedMedialAxis::sample(int count, std::uint32_t seed) const {
  Random rng(seed);
  // Swept area of a segment: length * 2 pi * mean rho (Pappus); points weigh 1.
  std::vector<double> weight;
  for (const auto& s : segments_) {
    const double len = std::hypot(s[1][0] - s[0][0], s[1][1] - s[0][1]);
    weight.push_back(len > 0 ? len * M_PI * (s[0][0] + s[1][0]) : 0.0);
  }
  double total = 0;
  for (double w : weight) total += w;
  if (total == 0) std::fill(weight.begin(), weight.end(), 1.0), total = weight.size();
  // A segment on the axis (rho = 0 throughout) sweeps no area but is part of the axis: give it a
  // share by length so that it is sampled too.
  for (std::size_t k = 0; k < segments_.size(); ++k)
    if (weight[k] == 0 && segments_[k][0] != segments_[k][1]) {
      weight[k] = 0.2 * total;
      total += weight[k];
    }
  std::vector<Vec3> points;
  for (int n = 0; n < count; ++n) {
    double pick = rng.uniform() * total;
    std::size_t k = 0;
    while (k + 1 < segments_.size() && pick >= weight[k]) pick -= weight[k++];
    const auto& s = segments_[k];
    const double t = rng.uniform(), phi = rng.uniform(0, 2 * M_PI);
    const double rho = s[0][0] + t * (s[1][0] - s[0][0]), z = s[0][1] + t * (s[1][1] - s[0][1]);
    points.push_back({rho * std::cos(phi), rho * std::sin(phi), z});
  }
  return points;
}

}  // namespace cadmedial::test
