// The exact distance from a point to a solid's boundary (its B-rep faces and edges), for the
// medial radii (a ball's radius is its centre's distance to the boundary, not to the samples) and
// the local feature size that the sampling follows.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <TopoDS_Solid.hxx>

#include "../types.h"

namespace cadmedial {

/// The nearest boundary point of a solid. One instance per thread: it keeps OpenCASCADE's
/// projectors (with their caches) between calls; it only reads the solid.
class BoundaryDistance {
 public:
  explicit BoundaryDistance(const TopoDS_Solid& solid);
  ~BoundaryDistance();
  BoundaryDistance(const BoundaryDistance&) = delete;
  BoundaryDistance& operator=(const BoundaryDistance&) = delete;

  struct Nearest {
    double distance = 0;      ///< to the boundary
    Point3 point{0, 0, 0};    ///< the nearest boundary point
    int face = -1;            ///< the face whose interior it lies in, or -1 (on an edge)
    int edge = -1;            ///< the edge it lies on, or -1 (in a face)
    /// +1 the query point is outside the solid (it lies on the outer side of the face at the
    /// nearest point), -1 inside, 0 not known (the nearest point is on an edge).
    int side = 0;
    std::array<double, 2> uv{0, 0};  ///< on the face (face >= 0): the point's parameters
    Point3 normal{0, 0, 0};          ///< on the face: its outer unit normal there
  };

  /// The nearest boundary point to p, given `bound`, an upper bound of the distance (the
  /// distance to a boundary sample, say): only faces and edges whose boxes come within it are
  /// asked. When nothing lies within `bound`, distance is `bound` and face and edge are -1.
  Nearest nearest(const Point3& p, double bound);

  /// The exterior normal of face `face` at `point` (a point on it), unit; zero where the surface
  /// has none.
  Point3 normal(int face, const Point3& point);

  std::size_t num_faces() const;
  /// The faces' index in the solid's map of faces (TopExp::MapShapes order, from 0), as
  /// Samples::face numbers them.
  int face_index(int face) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Exact radii of a medial mesh's vertices: each vertex's distance to the boundary of `solid`
/// (vertices of mesh.solid / edge_solid == solid_index only). A vertex outside the solid is moved
/// to its nearest boundary point (radius 0). Returns what changed. Two threads.
struct ExactRadiiStats {
  std::size_t vertices = 0;      ///< vertices measured
  std::size_t corrected = 0;     ///< whose radius shrank by more than 1e-9 of the diagonal
  std::size_t moved_inside = 0;  ///< outside the solid, moved to the boundary
  double max_excess = 0;         ///< largest (Voronoi radius - exact distance), model units
  double mean_excess = 0;        ///< its mean over the vertices
};
ExactRadiiStats exact_radii(const TopoDS_Solid& solid, int solid_index, double diag, MedialMesh& mesh);

}  // namespace cadmedial
