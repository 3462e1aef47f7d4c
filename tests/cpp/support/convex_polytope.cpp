#include "support/convex_polytope.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "support/random.h"

namespace cadmedial::test {

double ConvexPolytope::boundary_distance(const Vec3& x) const {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(planes.size()); ++i) best = std::min(best, plane_distance(i, x));
  return best;
}

double ConvexPolytope::max_normal_cosine() const {
  double c = -1.0;
  for (std::size_t i = 0; i < planes.size(); ++i)
    for (std::size_t j = i + 1; j < planes.size(); ++j) c = std::max(c, dot(planes[i].n, planes[j].n));
  return c;
}

Vec3 ConvexPolytope::bbox_min() const {
  Vec3 m = vertices.at(0);
  for (const Vec3& v : vertices)
    for (int k = 0; k < 3; ++k) m[k] = std::min(m[k], v[k]);
  return m;
}

Vec3 ConvexPolytope::bbox_max() const {
  Vec3 m = vertices.at(0);
  for (const Vec3& v : vertices)
    for (int k = 0; k < 3; ++k) m[k] = std::max(m[k], v[k]);
  return m;
}

double ConvexPolytope::min_edge_length() const {
  double m = std::numeric_limits<double>::infinity();
  for (const auto& e : edges) m = std::min(m, norm(vertices[e[0]] - vertices[e[1]]));
  return m;
}

namespace {

// Solves the 3x3 system n_a.x = d_a (rows) by Cramer's rule; false when nearly singular.
bool intersect_planes(const HalfSpace& a, const HalfSpace& b, const HalfSpace& c, Vec3& x) {
  const Vec3 bc = cross(b.n, c.n), ca = cross(c.n, a.n), ab = cross(a.n, b.n);
  const double det = dot(a.n, bc);
  if (std::abs(det) < 1e-9) return false;
  x = (1.0 / det) * (a.d * bc + b.d * ca + c.d * ab);
  return true;
}

// Every direction has a plane facing it: the intersection is bounded. Checked on a dense Fibonacci
// set of directions with a margin (a bounded polytope with well-spread normals passes easily).
bool is_bounded(const std::vector<HalfSpace>& planes) {
  const int n = 4000;
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / n, r = std::sqrt(1.0 - z * z), phi = k * 2.399963229728653;
    const Vec3 u{r * std::cos(phi), r * std::sin(phi), z};
    double best = -1.0;
    for (const auto& p : planes) best = std::max(best, dot(p.n, u));
    if (best < 0.05) return false;
  }
  return true;
}

}  // namespace

ConvexPolytope polytope_from_halfspaces(const std::vector<HalfSpace>& input) {
  if (!is_bounded(input)) throw std::runtime_error("polytope_from_halfspaces: unbounded");
  double scale = 0.0;
  for (const auto& p : input) scale = std::max(scale, std::abs(p.d));
  const double eps = 1e-9 * std::max(scale, 1.0);

  // Vertices: feasible intersections of plane triples, merged when they coincide.
  std::vector<Vec3> vertices;
  const int n = static_cast<int>(input.size());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      for (int c = b + 1; c < n; ++c) {
        Vec3 x;
        if (!intersect_planes(input[a], input[b], input[c], x)) continue;
        bool feasible = true;
        for (const auto& p : input) feasible = feasible && dot(p.n, x) <= p.d + eps;
        if (!feasible) continue;
        bool known = false;
        for (const Vec3& v : vertices) known = known || norm(v - x) <= 100 * eps;
        if (!known) vertices.push_back(x);
      }
  if (vertices.size() < 4) throw std::runtime_error("polytope_from_halfspaces: empty or flat");

  ConvexPolytope poly;
  poly.vertices = vertices;
  for (const auto& p : input) {
    std::vector<int> on;
    for (int v = 0; v < static_cast<int>(vertices.size()); ++v)
      if (std::abs(dot(p.n, vertices[v]) - p.d) <= 100 * eps) on.push_back(v);
    if (on.size() < 3) continue;  // redundant, or touches only an edge or a vertex
    // Counter-clockwise seen from outside (from +n): sort by angle in the basis (u, n x u).
    Vec3 centre{0, 0, 0};
    for (int v : on) centre = centre + (1.0 / on.size()) * vertices[v];
    const Vec3 u = normalized(vertices[on[0]] - centre), w = cross(p.n, u);
    std::sort(on.begin(), on.end(), [&](int i, int j) {
      const Vec3 a = vertices[i] - centre, b = vertices[j] - centre;
      return std::atan2(dot(a, w), dot(a, u)) < std::atan2(dot(b, w), dot(b, u));
    });
    poly.planes.push_back(p);
    poly.facet_vertices.push_back(on);
  }
  for (int v = 0; v < static_cast<int>(vertices.size()); ++v) {
    int count = 0;
    for (const auto& f : poly.facet_vertices) count += std::count(f.begin(), f.end(), v) ? 1 : 0;
    if (count != 3)
      throw std::runtime_error("polytope_from_halfspaces: vertex on " + std::to_string(count) + " facets");
  }
  for (const auto& f : poly.facet_vertices)
    for (std::size_t k = 0; k < f.size(); ++k) {
      const int a = f[k], b = f[(k + 1) % f.size()];
      if (a < b) poly.edges.push_back({a, b});  // each edge is seen once in each direction
    }
  return poly;
}

ConvexPolytope box_polytope(double a, double b, double c) {
  return polytope_from_halfspaces({{{1, 0, 0}, a}, {{-1, 0, 0}, 0}, {{0, 1, 0}, b},
                                   {{0, -1, 0}, 0}, {{0, 0, 1}, c}, {{0, 0, -1}, 0}});
}

ConvexPolytope prism_polytope(const std::vector<std::array<double, 2>>& polygon, double height) {
  std::vector<HalfSpace> planes{{{0, 0, 1}, height}, {{0, 0, -1}, 0}};
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const auto& p = polygon[k];
    const auto& q = polygon[(k + 1) % polygon.size()];
    // Outward normal of a counter-clockwise polygon's edge pq: (dy, -dx).
    const Vec3 nrm = normalized(Vec3{q[1] - p[1], -(q[0] - p[0]), 0.0});
    planes.push_back({nrm, nrm[0] * p[0] + nrm[1] * p[1]});
  }
  return polytope_from_halfspaces(planes);
}

ConvexPolytope random_polytope(std::uint32_t seed, int num_planes, double radius,
                               double min_normal_angle_deg, double min_edge) {
  Random rng(seed);
  const double max_cos = std::cos(min_normal_angle_deg * M_PI / 180.0);
  for (int attempt = 0; attempt < 10000; ++attempt) {
    std::vector<HalfSpace> planes;
    for (int tries = 0; tries < 1000 && static_cast<int>(planes.size()) < num_planes; ++tries) {
      const Vec3 n = rng.unit_vector();
      bool spread = true;
      for (const auto& p : planes) spread = spread && dot(p.n, n) <= max_cos;
      if (spread) planes.push_back({n, radius * rng.uniform(0.8, 1.2)});
    }
    if (static_cast<int>(planes.size()) < num_planes || !is_bounded(planes)) continue;
    try {
      ConvexPolytope poly = polytope_from_halfspaces(planes);
      if (static_cast<int>(poly.planes.size()) == num_planes && poly.min_edge_length() >= min_edge)
        return poly;
    } catch (const std::runtime_error&) {
      // degenerate draw: try the next one
    }
  }
  throw std::runtime_error("random_polytope: no valid polytope for seed " + std::to_string(seed));
}

}  // namespace cadmedial::test
