// The exact inner medial axis of a convex polytope {x : n_i.x <= d_i}.
//
// Inside, the distance to the boundary is D(x) = min_i d_i(x), d_i(x) = d_i - n_i.x: the ball of
// radius D(x) lies in every half-space and touches the nearest plane at a point of its facet. A point
// is on the medial axis iff the minimum is attained by two planes (two distinct touching points;
// distinct facets of a convex polytope have distinct normals). So the axis is the union, over plane
// pairs (i, j), of the convex polygons
//     S_ij = {x : d_i(x) = d_j(x),  d_i(x) <= d_k(x) for all k,  d_i(x) >= 0},
// which we build by clipping a large square in the bisector plane (n_j - n_i).x = d_j - d_i.
// The closure (convex edges, where d_i = d_j = 0, and corners) is included by d_i >= 0.
#pragma once

#include <cstdint>
#include <vector>

#include "support/convex_polytope.h"
#include "support/vec3.h"

namespace cadmedial::test {

class PolytopeMedialAxis {
 public:
  explicit PolytopeMedialAxis(const ConvexPolytope& polytope);

  /// The sheets S_ij that are not empty (some degenerate to segments or points: still on the axis).
  const std::vector<std::vector<Vec3>>& polygons() const { return polygons_; }

  /// Exact Euclidean distance from x to the medial axis (min over the sheets).
  double distance(const Vec3& x) const;

  /// d_(2)(x) - d_(1)(x): second smallest minus smallest plane distance; 0 exactly on the axis.
  /// It is 2-Lipschitz (order statistics of 1-Lipschitz functions are 1-Lipschitz), so
  /// distance(x) >= gap(x) / 2.
  double gap(const Vec3& x) const;

  /// For an interior x with nearest plane i, walks along the inward normal -n_i until a second plane
  /// ties: along x - t n_i, d_i grows by t and d_j by t n_i.n_j, so d_j - d_i closes at rate
  /// 1 - n_i.n_j and the first tie is t* = min_{j : n_i.n_j < 1} (d_j(x) - d_i(x)) / (1 - n_i.n_j).
  /// Plane i stays nearest for t <= t*, so m = x - t* n_i has two nearest planes: m is on the axis
  /// and distance(x) <= t*. Since t* <= gap / (1 - n_i.n_b) (b = second nearest),
  /// distance(x) <= gap(x) / (1 - max_ij n_i.n_j). Returns m; *t receives t*.
  Vec3 project(const Vec3& x, double* t = nullptr) const;

  /// `count` points on the axis: project() of seeded uniform random interior points.
  std::vector<Vec3> sample(int count, std::uint32_t seed) const;

 private:
  const ConvexPolytope& polytope_;
  std::vector<std::vector<Vec3>> polygons_;
};

/// Distance from p to a convex planar polygon (any number of vertices >= 1; degenerate allowed).
double point_convex_polygon_distance(const Vec3& p, const std::vector<Vec3>& polygon);

}  // namespace cadmedial::test
