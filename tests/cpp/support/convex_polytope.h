// Convex polytopes given exactly by their facet planes n_i.x <= d_i (|n_i| = 1): box, prism and
// seeded random polytopes, with their vertices and facets found by exact-enough enumeration.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "support/vec3.h"

namespace cadmedial::test {

/// The half-space n.x <= d, |n| = 1.
struct HalfSpace {
  Vec3 n;
  double d;
};

struct ConvexPolytope {
  std::vector<HalfSpace> planes;                ///< #P, each supports a 2D facet (no redundant plane)
  std::vector<Vec3> vertices;                   ///< #V
  std::vector<std::vector<int>> facet_vertices; ///< #P: vertex indices, counter-clockwise seen from outside
  std::vector<std::array<int, 2>> edges;        ///< #E: vertex index pairs (two facets share each)

  /// Signed distance to plane i: d_i - n_i.x (positive inside).
  double plane_distance(int i, const Vec3& x) const { return planes[i].d - dot(planes[i].n, x); }
  /// Distance from an interior point to the boundary, min_i (d_i - n_i.x); negative outside
  /// (then it is minus the largest violation, not the true exterior distance).
  double boundary_distance(const Vec3& x) const;
  /// max n_i.n_j over distinct planes: the flattest dihedral angle enters the tolerances as 1/(1-c).
  double max_normal_cosine() const;
  Vec3 bbox_min() const;
  Vec3 bbox_max() const;
  double bbox_diagonal() const { return norm(bbox_max() - bbox_min()); }
  double min_edge_length() const;
};

/// Vertices, facets and edges of the intersection of the half-spaces. Redundant planes are dropped.
/// Throws std::runtime_error when the intersection is unbounded, empty, or has a vertex on more than
/// three planes (the tests want simple polytopes; boxes and prisms are simple).
ConvexPolytope polytope_from_halfspaces(const std::vector<HalfSpace>& planes);

/// [0,a] x [0,b] x [0,c], the box BRepPrimAPI_MakeBox(a, b, c) makes.
ConvexPolytope box_polytope(double a, double b, double c);

/// The prism polygon x [0, height] over a convex counter-clockwise polygon in the xy plane.
ConvexPolytope prism_polytope(const std::vector<std::array<double, 2>>& polygon, double height);

/// A random simple polytope: planes tangent-ish to a sphere of `radius` (offsets radius*(1 +- 0.2))
/// with random normals at least `min_normal_angle_deg` apart; redrawn (deterministically from
/// `seed`) until it is bounded and every edge is at least `min_edge` long.
ConvexPolytope random_polytope(std::uint32_t seed, int num_planes, double radius,
                               double min_normal_angle_deg, double min_edge);

}  // namespace cadmedial::test
