#include "support/polytope_medial_axis.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "support/random.h"

namespace cadmedial::test {

namespace {

// Sutherland-Hodgman: keeps the part of a convex polygon with a.x <= b.
std::vector<Vec3> clip(const std::vector<Vec3>& polygon, const Vec3& a, double b) {
  std::vector<Vec3> out;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& p = polygon[k];
    const Vec3& q = polygon[(k + 1) % n];
    const double fp = dot(a, p) - b, fq = dot(a, q) - b;
    if (fp <= 0) out.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) out.push_back(p + (fp / (fp - fq)) * (q - p));
  }
  return out;
}

}  // namespace

PolytopeMedialAxis::PolytopeMedialAxis(const ConvexPolytope& polytope) : polytope_(polytope) {
  const auto& planes = polytope.planes;
  const int n = static_cast<int>(planes.size());
  const Vec3 lo = polytope.bbox_min(), hi = polytope.bbox_max();
  const Vec3 centre = 0.5 * (lo + hi);
  const double half = 2.0 * norm(hi - lo);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      // Bisector plane w.x = c with w = n_j - n_i, c = d_j - d_i.
      const Vec3 w = planes[j].n - planes[i].n;
      const double c = planes[j].d - planes[i].d;
      const Vec3 unit = normalized(w);
      const Vec3 origin = centre + ((c - dot(w, centre)) / dot(w, w)) * w;
      Vec3 u = cross(unit, Vec3{1, 0, 0});
      if (norm(u) < 0.5) u = cross(unit, Vec3{0, 1, 0});
      u = normalized(u);
      const Vec3 v = cross(unit, u);
      std::vector<Vec3> polygon{origin + half * u + half * v, origin - half * u + half * v,
                                origin - half * u - half * v, origin + half * u - half * v};
      for (int k = 0; k < n && !polygon.empty(); ++k)
        if (k != i && k != j)  // d_i <= d_k  <=>  (n_k - n_i).x <= d_k - d_i
          polygon = clip(polygon, planes[k].n - planes[i].n, planes[k].d - planes[i].d);
      if (!polygon.empty()) polygon = clip(polygon, planes[i].n, planes[i].d);  // d_i >= 0
      if (!polygon.empty()) polygons_.push_back(polygon);
    }
}

double point_convex_polygon_distance(const Vec3& p, const std::vector<Vec3>& polygon) {
  const std::size_t n = polygon.size();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k)
    best = std::min(best, point_segment_distance(p, polygon[k], polygon[(k + 1) % n]));
  if (n < 3) return best;
  // Normal by Newell's method; if the projection falls inside, the plane distance is the answer.
  Vec3 normal{0, 0, 0};
  for (std::size_t k = 0; k < n; ++k) normal = normal + cross(polygon[k], polygon[(k + 1) % n]);
  const double area2 = norm(normal);
  if (area2 <= 1e-24) return best;
  normal = (1.0 / area2) * normal;
  const double h = dot(p - polygon[0], normal);
  const Vec3 foot = p - h * normal;
  for (std::size_t k = 0; k < n; ++k)
    if (dot(cross(polygon[(k + 1) % n] - polygon[k], foot - polygon[k]), normal) < 0) return best;
  return std::min(best, std::abs(h));
}

double PolytopeMedialAxis::distance(const Vec3& x) const {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& polygon : polygons_) best = std::min(best, point_convex_polygon_distance(x, polygon));
  return best;
}

double PolytopeMedialAxis::gap(const Vec3& x) const {
  double first = std::numeric_limits<double>::infinity(), second = first;
  for (int i = 0; i < static_cast<int>(polytope_.planes.size()); ++i) {
    const double d = polytope_.plane_distance(i, x);
    if (d < first) {
      second = first;
      first = d;
    } else if (d < second) {
      second = d;
    }
  }
  return second - first;
}

Vec3 PolytopeMedialAxis::project(const Vec3& x, double* t_out) const {
  const auto& planes = polytope_.planes;
  int i = 0;
  for (int k = 1; k < static_cast<int>(planes.size()); ++k)
    if (polytope_.plane_distance(k, x) < polytope_.plane_distance(i, x)) i = k;
  double t = std::numeric_limits<double>::infinity();
  for (int j = 0; j < static_cast<int>(planes.size()); ++j) {
    const double c = dot(planes[i].n, planes[j].n);
    if (j == i || c >= 1.0 - 1e-12) continue;
    t = std::min(t, (polytope_.plane_distance(j, x) - polytope_.plane_distance(i, x)) / (1.0 - c));
  }
  if (t_out) *t_out = t;
  return x - t * planes[i].n;
}

std::vector<Vec3> PolytopeMedialAxis::sample(int count, std::uint32_t seed) const {
  Random rng(seed);
  const Vec3 lo = polytope_.bbox_min(), hi = polytope_.bbox_max();
  std::vector<Vec3> points;
  while (static_cast<int>(points.size()) < count) {
    const Vec3 x{rng.uniform(lo[0], hi[0]), rng.uniform(lo[1], hi[1]), rng.uniform(lo[2], hi[2])};
    if (polytope_.boundary_distance(x) > 0) points.push_back(project(x));
  }
  return points;
}

}  // namespace cadmedial::test
