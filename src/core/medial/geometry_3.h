// Internal to medial/: small vector helpers on Point3.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "../types.h"

namespace cadmedial::internal {

inline Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Point3& a) { return std::sqrt(dot(a, a)); }

inline std::pair<Point3, Point3> bounding_box(const std::vector<Point3>& pts) {
  Point3 lo = pts.empty() ? Point3{0, 0, 0} : pts[0], hi = lo;
  for (const Point3& p : pts)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  return {lo, hi};
}

}  // namespace cadmedial::internal
