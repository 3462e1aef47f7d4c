// Internal to medial/: the finite Delaunay cells numbered and copied into flat arrays.
#pragma once

#include <vector>

#include "delaunay_3.h"

namespace cadmedial::internal {

/// Numbers the finite cells of dt (each cell's info().id) in the order of their earliest-inserted
/// sample, so that cells close in space are close in memory, and fills mc's cell arrays: samples,
/// neighbours, circumcentres and radii. `rank[s]` is sample s's position in the insertion order.
void number_cells(const Delaunay& dt, const std::vector<int>& rank, MedialComplex& mc);

}  // namespace cadmedial::internal
