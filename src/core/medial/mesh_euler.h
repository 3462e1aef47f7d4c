// The Euler characteristic of a medial mesh, counted on its shared vertices and sides. No CGAL.
#pragma once

#include "../types.h"

namespace cadmedial {

/// V - E + F of a mesh, vertices and edges shared by index (isolated vertices count).
long euler_characteristic(const MedialMesh& mesh);

}  // namespace cadmedial
