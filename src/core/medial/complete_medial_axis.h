// Internal to medial/: the completion of the medial axis at convex edges (4.2.2) and at
// non-concave corners (4.2.3).
#pragma once

#include <cstdint>
#include <vector>

#include "../sampling/samples.h"
#include "delaunay_3.h"
#include "medial_axis.h"
#include "select_facets.h"

namespace cadmedial::internal {

void complete_convex_edges(const Delaunay& dt, const std::vector<Vertex>& handle, const Samples& samples,
                           MedialComplex& mc, MedialAxisStats& st);
void complete_corners(const Delaunay& dt, const std::vector<Vertex>& handle, const Samples& samples,
                      const Selection& sel, MedialComplex& mc, MedialAxisStats& st);
/// Cone triangles that make each completed sample's rim one path (after separation: `faces`
/// are the inner faces, `inside` the cell labels). Returns the faces added to mc.
std::vector<int> fan_completions(MedialComplex& mc, const std::vector<int>& faces,
                                 const std::vector<std::uint8_t>& inside, MedialAxisStats& st);

}  // namespace cadmedial::internal
