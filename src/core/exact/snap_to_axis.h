// The medial mesh's vertices moved onto the exact medial axis of the B-rep. A Voronoi vertex lies
// near the axis, not on it: about a plate's mid-plane the vertices zig-zag (precision p95 about
// 0.13 % of the diagonal), which no simplification below that tolerance can flatten without
// moving them. From a vertex's nearest boundary point p (inside a face), the axis point of p is
// the centre of the largest ball inside the solid tangent to the boundary at p: a shrinking ball
// (Ma, Bae, Choi, Lee 2012) along the inward normal, whose radius is exact.
#pragma once

#include <cstddef>

#include <TopoDS_Solid.hxx>

#include "../types.h"

namespace cadmedial {

struct SnapStats {
  std::size_t vertices = 0;  ///< vertices of the solid
  std::size_t snapped = 0;   ///< moved onto the axis (the others stay: see snap_to_axis)
  double max_move = 0, mean_move = 0;  ///< how far the snapped ones moved, model units
};

/// Moves the vertices of solid `solid_index` (faces' and edges' of mesh.solid / edge_solid) to
/// the axis point of their nearest boundary point, radius its exact distance. A vertex stays
/// where its nearest point is on an edge (near convex edges the axis meets the boundary), where
/// the ball would move it farther than `reach`, or where the search does not settle. Two threads.
SnapStats snap_to_axis(const TopoDS_Solid& solid, int solid_index, double diag, double reach, MedialMesh& mesh);

}  // namespace cadmedial
