// Internal to medial/: the finite Delaunay cells numbered and copied into flat arrays.
#pragma once

#include <vector>

#include "delaunay_3.h"

namespace cadmedial::internal {

/// Numbers the finite cells of dt (each cell's info().id) in the order of their earliest-inserted
/// sample, so that cells close in space are close in memory, and fills mc's cell samples and
/// neighbours (the circumcentres and radii are sized, not computed), on two threads. `rank[s]` is
/// sample s's position in the insertion order.
void number_cells(const Delaunay& dt, const std::vector<int>& rank, MedialComplex& mc);

/// mc's circumcentres and radii of the cells with ids in [begin, end), from their samples' points
/// (the triangulated samples). Writes only those two arrays' entries: it may run beside
/// select_facets and on other ranges.
void cell_centers(const std::vector<Point3>& points, MedialComplex& mc, std::size_t begin, std::size_t end);

}  // namespace cadmedial::internal
