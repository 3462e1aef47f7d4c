// The test solids whose inner medial axis is known exactly (convex polytopes, solids of revolution),
// each with its sample spacing and the tolerances that spacing gives.
//
// Tolerances. Write h for the sample spacing and delta for the covering radius of the boundary
// sample (every boundary point has a sample within delta). Any reasonable sampling at spacing h has
// delta <= h (hexagonal grid h/sqrt 3, square grid h/sqrt 2, maximal Poisson disc h); we take
// delta = h.
//  * Radius. Samples lie on the boundary, so the radius r(v) (distance to the nearest sample) is at
//    least the distance D(v) to the boundary; the nearest boundary point has a sample within delta,
//    so r(v) <= D(v) + delta. Hence D <= r <= D + h.
//  * Polytope axis. A point x of the Voronoi facet dual to a Delaunay edge pq is the centre of a
//    sample-free ball of radius r = |x - p| = |x - q| <= D(x) + delta. If p lies on facet plane i and
//    q on plane j != i, then d_i(x) <= r and d_j(x) <= r, so the second smallest plane distance is
//    at most D(x) + delta: gap(x) <= delta. By PolytopeMedialAxis::project, the distance from x to the
//    exact axis is at most gap / (1 - c), c = max n_i.n_j. So every vertex of such a facet is within
//    h / (1 - c) of the axis (box: c = 0, tolerance h). Facets dual to pq on one plane are never
//    selected: the Angle condition fails (pq lies in the tangent plane) and so does the Ratio
//    condition (an empty ball through p and q meets the plane in a sample-free disc, so
//    |pq| <= 2 delta, while umbrella triangles have circumradius about h / sqrt 3: ratio < 8).
//    Completion triangles (4.2.2, 4.2.3) add samples on convex edges and corners: on the axis.
//    Coverage: crossing the axis sheet S_ij along its normal, the nearest sample switches from plane
//    i's side to plane j's within a segment of half length delta / |n_i - n_j| <= delta / (1 - c), so
//    a Voronoi facet dual to such a pq passes within that distance of every axis point.
//  * Axis of a curved wall (cylinder's axis segment, sphere's centre, torus's circle). Take the
//    sample-free ball at x touching samples p, q on the wall, at angles +-phi from the direction of
//    x's nearest wall point, x at distance s from the axis set: in the cylinder's cross section,
//    |x - p|^2 = R^2 + s^2 - 2 R s cos phi <= (R - s + delta)^2 gives s (1 - cos phi) <= delta (1 + delta / 2R)
//    (the same holds for the sphere and, in the meridian plane, for the torus tube). Facets that
//    the Angle/Ratio conditions select near such an axis are dual to pq on "opposite sides" of it;
//    we assume they subtend at least 120 degrees at x (phi >= 60), which gives s <= 2 delta (1 + delta / 2R).
//    Tolerance 2.2 h. This rests on the stated assumption (not proved by the paper); the failure message
//    reports p95 and max so that a fat tail can be told from a wholesale error.
//  * Features. Consecutive edge samples are at most h apart and completion triangles join them
//    (4.2.2), so every point of a convex edge is within h / 2 of the output; corners are samples and
//    vertices of corner triangles (4.2.3). Tolerance h.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "support/vec3.h"

namespace cadmedial::test {

struct ExactCase {
  std::string name;
  std::function<TopoDS_Shape()> make_shape;
  double spacing = 0;                                        ///< h
  double axis_tolerance = 0;                                 ///< see above
  std::function<double(const Vec3&)> axis_distance;          ///< exact distance to the inner medial axis
  std::function<std::vector<Vec3>(int, std::uint32_t)> axis_sample;  ///< points on the exact axis
  std::function<double(const Vec3&)> boundary_distance;      ///< exact inside, negative outside
  std::vector<Vec3> convex_edge_points;                      ///< every <= h/2 along every convex edge
  std::vector<Vec3> corners;                                 ///< non-concave corners
  long euler = 1;                                            ///< of the solid
  double bbox_diagonal = 0;
};

/// Box 10x8x6, thin plate 20x10x1, wedge (triangular prism), three random polytopes, cylinder
/// (H > 2R), disc (H < 2R), sphere, torus.
const std::vector<ExactCase>& exact_cases();

}  // namespace cadmedial::test
