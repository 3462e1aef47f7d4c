// Internal to medial/: the completion of the medial axis at convex edges (4.2.2) and at
// non-concave corners (4.2.3).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "../sampling/samples.h"
#include "delaunay_3.h"
#include "medial_axis.h"
#include "select_facets.h"

namespace cadmedial::internal {

/// Reads mc's cells (numbered, centres set) and the triangulation's vertex handles (null for a
/// sample that coincides with another).
void complete_convex_edges(const std::vector<Vertex>& handle, const Samples& samples, MedialComplex& mc,
                           MedialAxisStats& st);
void complete_corners(const Delaunay& dt, const std::vector<Vertex>& handle, const Samples& samples,
                      const Selection& sel, MedialComplex& mc, MedialAxisStats& st);
/// mc's star_start and star_cells: the Voronoi vertices (incident cells, by id) of each sample
/// the completion recorded in mc.star_sample. On two cores.
void star_cells(MedialComplex& mc, std::size_t samples);
/// Cone triangles that make each completed sample's rim one path (after separation: `faces`
/// are the inner faces, `inside` the cell labels), as corners of edge-completion faces for mc,
/// in order. Reads mc only: it may run beside collapse_fillers.
std::vector<std::array<int, 3>> fan_completions(const MedialComplex& mc, const std::vector<int>& faces,
                                                const std::vector<std::uint8_t>& inside);

}  // namespace cadmedial::internal
