// Internal to medial/: the topology repair of the inner axis. The Voronoi cells inside the solid
// (vertices, edges and facets whose corners are all inside) form a complex with the solid's
// homotopy type; the selected facets alone need not (pinholes, fins around a 1-D part of the
// axis). Collapsing every filler facet that can be collapsed, and never a selected one, then every
// bare Voronoi edge with a free end, keeps the homotopy type and leaves the selection plus what it
// needs. The completion triangles (4.2.2, 4.2.3) are then attached only where they keep it too.
#pragma once

#include <array>
#include <vector>

#include "mesh_euler.h"
#include "delaunay_3.h"
#include "medial_axis.h"

namespace cadmedial::internal {

/// Part of the complex: faces of mc (by index) and segments between corners of mc.
struct AxisCells {
  std::vector<int> faces;
  std::vector<std::array<int, 2>> edges;
};

/// What is left of `faces` (faces of mc, all inside) and `segments` (degenerate facets: corners
/// and filler flag) after elementary collapses of filler faces through free sides and of filler
/// edges no face holds through free ends. The edges left are the 1-D part of the axis.
AxisCells collapse_fillers(const MedialComplex& mc, const std::vector<int>& faces,
                           const std::vector<std::array<int, 3>>& segments, MedialAxisStats& st);

/// `base` plus the triangles of `candidates` (completion faces) that attach to it without
/// changing its homotopy type, tried until none attaches; the others are counted in
/// st.unattached_faces.
AxisCells attach_by_expansion(const MedialComplex& mc, AxisCells base, const std::vector<int>& candidates,
                              MedialAxisStats& st);

}  // namespace cadmedial::internal
