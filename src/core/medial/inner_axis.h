// Internal to medial/: the inner medial axis (4.2.5): coincident Voronoi vertices merged, each
// labelled inside or outside the solid, and the faces inside kept.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "../progress.h"
#include "../sampling/samples.h"
#include "delaunay_3.h"
#include "geometry_3.h"
#include "medial_axis.h"
#include "reconstruct_faces.h"

namespace cadmedial::internal {

/// The distance within which coincident_cells merges two neighbours' centres: 1e-9 of the
/// samples' box diagonal.
inline double coincident_eps(const std::vector<Point3>& points) {
  const auto [lo, hi] = bounding_box(points);
  return 1e-9 * norm(sub(hi, lo));
}

/// Per cell id of mc, the cell it merges into: the first of the cells joined to it through
/// neighbours with the same circumcentre (exactly cospherical samples, or the same doubles), or
/// with centres within eps where no other neighbour's lies within 1000 eps. Reads only mc's
/// centres, samples and neighbours: it may run beside the completion.
std::vector<int> coincident_cells(const MedialComplex& mc, const std::vector<Point3>& points, double eps);
/// Merges the cells by `rep` (coincident_cells) in mc's faces, centres and stars.
void merge_coincident_cells(MedialComplex& mc, std::vector<int> rep, const Progress& progress);
/// 1 inside, 0 outside, per cell id of mc. Vertices just outside that would cut a hole in the
/// sheet at a sharp convex edge are labelled inside and moved just inside (fill_sheet_holes).
std::vector<std::uint8_t> label_inside(MedialComplex& mc, const Samples& samples, const Umbrellas& umbrellas,
                                       const InsideTest& inside, MedialAxisStats& st, const Progress& progress);
/// The faces whose Voronoi vertices are all inside, with the topology of the inner Voronoi complex,
/// in the pieces kept, as a mesh; segments where facets degenerated to one. Sets the stats of
/// the faces kept and dropped, not the Euler characteristic.
MedialMesh extract_inner(MedialComplex& mc, const std::vector<std::uint8_t>& inside, const Samples& samples,
                         int solid_index, MedialAxisStats& st, const Progress& progress);

}  // namespace cadmedial::internal
