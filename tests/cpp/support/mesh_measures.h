// Measures on a MedialMesh: distance to its faces and 1-D edges, connected pieces, Euler
// characteristic. The 1-D edges are part of the axis: every measure includes them.
// CGAL lives only in mesh_measures.cpp (OpenCASCADE's Handle macro breaks CGAL headers).
#pragma once

#include <memory>
#include <vector>

#include "core/types.h"
#include "support/vec3.h"

namespace cadmedial::test {

/// Point-to-axis distance of a medial mesh: its polygons fanned into triangles and its 1-D edges
/// as segments, in CGAL AABB trees. Triangles of (near) zero area are left out; a polygon reduced
/// to them still has its vertices and edges in other polygons, or is not a surface.
class MeshDistance {
 public:
  /// Faces and edges of solid `solid` only, or all when solid < 0. `scale` is the size of the
  /// solid (bounding-box diagonal): triangles of area below (1e-12 scale)^2 are left out.
  MeshDistance(const MedialMesh& mesh, double scale, int solid = -1);
  ~MeshDistance();
  MeshDistance(const MeshDistance&) = delete;
  MeshDistance& operator=(const MeshDistance&) = delete;

  /// Distance from p to the nearest triangle, segment or isolated vertex; +infinity for an empty
  /// mesh.
  double distance(const Vec3& p) const;
  std::size_t num_triangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Vertex representatives after welding: vertices closer than 1e-12 * scale are one vertex (an
/// engine may emit the same Voronoi vertex once per facet, and exact duplicates must not split a
/// piece or inflate V). `scale` is the size of the solid (its bounding-box diagonal), not of the
/// mesh: one stray vertex far away must not make the weld radius coarse. Returns #V: the index of
/// each vertex's representative (the smallest index in its cluster).
std::vector<int> weld_vertices(const MedialMesh& mesh, double scale);

/// Connected pieces (welded with weld_vertices(mesh, scale)) of the faces and 1-D edges of solid
/// `solid` (all when < 0): they are connected when they share a (welded) vertex, so an edge joins
/// the pieces at its ends. Vertices that neither uses count as a piece each when solid < 0.
/// Returns the number of pieces and, in face_piece (#F, -1 for faces of other solids), each
/// face's piece.
int connected_pieces(const MedialMesh& mesh, double scale, int solid = -1, std::vector<int>* face_piece = nullptr);

/// Euler characteristic V - E + F of the cell complex of solid `solid` (all when < 0), after
/// welding: V counts welded vertices used by faces or 1-D edges (and, when solid < 0, those used by
/// neither), E unique undirected edges of the polygons and 1-D edges together (a 1-D edge that is
/// also a polygon's side counts once; one welded to a point is just its vertex), F distinct
/// polygons (same vertex set = same polygon). A polygon whose welded boundary has fewer than 3
/// distinct vertices contributes its edge but no face. *degenerate, when given, receives the
/// number of such polygons (the figure is only meaningful if that is 0 or they are harmless).
long euler_characteristic(const MedialMesh& mesh, double scale, int solid = -1, int* degenerate = nullptr);

/// Bounding-box diagonal of the mesh's vertices.
double mesh_bbox_diagonal(const MedialMesh& mesh);

}  // namespace cadmedial::test
