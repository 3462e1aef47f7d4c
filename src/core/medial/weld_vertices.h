// Sides of a medial mesh shorter than a distance collapsed: near-coincident Voronoi vertices
// (nearly cospherical samples) survive the merge of coincident cells as clusters joined by
// sides of almost no length. No CGAL: plain mesh data.
#pragma once

#include <cstddef>

#include "../types.h"

namespace cadmedial {

struct WeldStats {
  std::size_t merged_vertices = 0;  ///< vertices that went into another
  std::size_t dropped_faces = 0;    ///< faces left with fewer than 3 distinct vertices, or repeated
  std::size_t dropped_edges = 0;    ///< edges left with one vertex, repeated, or on a face's side
};

/// Merges the two ends of every side or edge shorter than `eps` (transitively; the merged vertex
/// keeps the first's position and the smallest radius of the group), drops the faces and edges that degenerate, and
/// the vertices no face or edge uses any more. A face that collapses to a segment stays as an
/// edge (unless another face has that side), one that collapses to a point as a lone vertex: the
/// topology is kept. Face order, kinds and solids are kept.
WeldStats weld_vertices(MedialMesh& mesh, double eps);

}  // namespace cadmedial
