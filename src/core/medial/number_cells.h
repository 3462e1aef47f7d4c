// Internal to medial/: the finite Delaunay cells numbered and copied into flat arrays.
#pragma once

#include <vector>

#include "delaunay_3.h"

namespace cadmedial::internal {

/// Numbers the finite cells of dt (each cell's info().id) in the order of their earliest-inserted
/// sample, so that cells close in space are close in memory, and fills mc's cell samples and
/// neighbours (the circumcentres and radii are sized, not computed). `rank[s]` is sample s's
/// position in the insertion order. Returns the cells by id.
std::vector<Cell> number_cells(const Delaunay& dt, const std::vector<int>& rank, MedialComplex& mc);

/// mc's circumcentres and radii of the cells by id. Writes only those two arrays: it may run while
/// select_facets adds faces.
void cell_centers(const std::vector<Cell>& cells, MedialComplex& mc);

}  // namespace cadmedial::internal
