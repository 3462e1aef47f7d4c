// Vertices of a medial mesh closer than a distance made one: near-coincident Voronoi vertices
// (nearly cospherical samples) survive the merge of coincident cells, and a topology counted on
// them holds only combinatorially (welded, a row of touching cubes changed its Euler
// characteristic). No CGAL: plain mesh data.
#pragma once

#include <cstddef>

#include "../types.h"

namespace cadmedial {

struct WeldStats {
  std::size_t merged_vertices = 0;  ///< vertices that went into another
  std::size_t dropped_faces = 0;    ///< faces left with fewer than 3 distinct vertices, or repeated
  std::size_t dropped_edges = 0;    ///< edges left with one vertex, repeated, or on a face's side
};

/// Merges every vertex within `eps` of another (transitively; the merged vertex keeps the first's
/// position and the smallest radius of the group), drops the faces and edges that degenerate, and
/// the vertices no face or edge uses any more. Face order, kinds and solids are kept.
WeldStats weld_vertices(MedialMesh& mesh, double eps);

}  // namespace cadmedial
