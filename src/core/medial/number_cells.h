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

/// mc's circumcentres, radii and flat flags of the cells with ids in [begin, end), from their
/// samples' points (the triangulated samples). Writes only those arrays' entries: it may run
/// beside select_facets and on other ranges.
void cell_centers(const std::vector<Point3>& points, MedialComplex& mc, std::size_t begin, std::size_t end);

/// Cells whose four samples are coplanar to rounding (mc.flat, set by cell_centers): the centre
/// cell_centers computed may be noise along the axis of their circle, often far off, a ball
/// holding other samples (spikes of the axis: 1.4 spacings on NIST CTC 01, 4 on PocketTest). A
/// cell that is not exactly flat keeps its centre unless that is unequally far from its samples
/// or a neighbour's far sample lies inside its ball; then the centre is computed exactly. An
/// exactly flat cell has none: it takes the centre and radius of its non-flat neighbour with the
/// smallest ball. Clears mc.flat; returns how many cells moved.
std::size_t settle_flat_cells(const std::vector<Point3>& points, MedialComplex& mc);

}  // namespace cadmedial::internal
