// Internal to medial/: the topology repair of the inner axis. The Voronoi facets inside the solid
// form a 2-complex with the solid's homotopy type; the selected ones alone need not (pinholes,
// fins around a 1-D part of the axis). Collapsing every filler facet that can be collapsed, and
// never a selected one, keeps the homotopy type and leaves the selection plus what it needs.
// The completion triangles (4.2.2, 4.2.3) are then attached only where they keep it too.
#pragma once

#include <vector>

#include "delaunay_3.h"
#include "medial_axis.h"

namespace cadmedial::internal {

/// Of `faces` (face indices of mc, all inside), those left after elementary collapses of filler
/// faces through free edges. Edges left bare where no face remains are counted in
/// st.bare_edges after their own collapse (a 1-D part of the axis the faces do not carry).
std::vector<int> collapse_fillers(const MedialComplex& mc, const std::vector<int>& faces, MedialAxisStats& st);

/// `base` plus the triangles of `candidates` (completion faces) that attach to it without
/// changing its homotopy type, tried until none attaches; the others are counted in
/// st.unattached_faces.
std::vector<int> attach_by_expansion(const MedialComplex& mc, const std::vector<int>& base,
                                     const std::vector<int>& candidates, MedialAxisStats& st);

/// V - E + F of these faces of mc, vertices and edges shared by corner index.
long euler_characteristic(const MedialComplex& mc, const std::vector<int>& faces);

}  // namespace cadmedial::internal
