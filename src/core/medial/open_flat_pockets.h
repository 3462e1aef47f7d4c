// Closed pockets of zero volume in a medial mesh, and their opening.
#pragma once

#include <cstddef>

#include "../types.h"

namespace cadmedial {

/// Removes one face per independent closed pocket of zero volume from a solid's medial mesh;
/// returns how many it removed (the Euler characteristic drops by as many: no vertex or edge
/// goes).
///
/// A solid without cavities has a medial axis without voids (the two are homotopy equivalent).
/// Where samples lie in exactly symmetric rings (both sides of a plate, a cylinder, a fillet),
/// Voronoi vertices fall into one plane and can close 2-cycles that enclose nothing: two layers of
/// faces in one plane. The faces that elementary collapses through free sides cannot remove are
/// grouped by shared sides; in each flat group (all its vertices within 1e-6 of its extent of a
/// plane), the faces whose sides (mod 2) are a sum of earlier faces' go, one per independent
/// 2-cycle: the first homology is unchanged. Polygons with a repeated side or under 3 sides are
/// never removed. A pocket whose group also holds faces off its plane is not opened.
std::size_t open_flat_pockets(MedialMesh& mesh);

}  // namespace cadmedial
