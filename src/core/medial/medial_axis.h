// The medial stages of CAD_MEDIAL after sampling: Delaunay (CGAL, exact predicates), Angle/Ratio
// selection against the umbrellas (3, 4.2.6), ProcConvexEdges (4.2.2), ProcNonconcaveCorners
// (4.2.3) and the inner medial axis (4.2.5). CGAL types stay inside medial/*.cpp.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <future>
#include <vector>

#include "../progress.h"
#include "../sampling/samples.h"
#include "../types.h"
#include "reconstruct_faces.h"

namespace cadmedial {

/// Exact inside test for a batch of points: 1 inside the solid, 0 outside (on the boundary counts
/// as inside). Supplied by the caller, who holds the B-rep.
using InsideTest = std::function<std::vector<std::uint8_t>(const std::vector<Point3>&)>;

struct MedialAxisStats {
  Timings timings;                   ///< delaunay, selection, completion, inner
  /// Voronoi facets passing Angle or Ratio (before separation), but for those whose vertices all
  /// lie surely outside (mark_far_outside, mark_voted_outside)
  std::size_t selected_facets = 0;
  std::size_t edge_triangles = 0;
  std::size_t corner_triangles = 0;
  std::size_t fan_triangles = 0;     ///< cones closing breaks in a completed sample's rim
  std::size_t exact_inside_tests = 0;
  /// selected facets built and not kept: outside the solid or in stray pieces (those with a vertex
  /// surely outside are not built)
  std::size_t dropped_faces = 0;
  std::size_t components = 0;        ///< pieces of the inner axis before stray ones are dropped
  std::size_t specks = 0;            ///< pieces without a Voronoi face (fan or edge specks), not in components
  std::size_t kept_components = 0;   ///< pieces of the output: the largest and those reaching the boundary
  std::size_t filler_faces = 0;      ///< unselected Voronoi facets kept for the topology
  std::size_t unattached_faces = 0;  ///< completion triangles left out: they would close a loop
  std::size_t bare_edges = 0;        ///< output edges: 1-D parts of the axis that no face carries
  long euler_characteristic = 0;     ///< V - E + F of the output faces
  std::size_t welded_vertices = 0;   ///< output vertices within 1e-9 of the diagonal of another, merged
};

/// The inner medial axis of one solid from its samples and umbrellas. Faces get `solid_index`.
MedialMesh medial_axis(const Samples& samples, const Umbrellas& umbrellas, const MedialParams& params,
                       const InsideTest& inside, int solid_index, MedialAxisStats* stats = nullptr,
                       const Progress& progress = {});

/// The same with the umbrellas still being computed on another thread: the Delaunay triangulation
/// does not need them, so compute_medial_axis reconstructs the faces meanwhile (2 cores). When
/// that thread sets `give_up` (the samples must change), this throws Cancelled soon: during the
/// triangulation, or once the umbrellas are ready.
MedialMesh medial_axis(const Samples& samples, std::shared_future<Umbrellas> umbrellas, const MedialParams& params,
                       const InsideTest& inside, int solid_index, MedialAxisStats* stats = nullptr,
                       const Progress& progress = {}, const std::atomic<bool>* give_up = nullptr);

/// How bare_delaunay_seconds orders the points: as CGAL's range constructor does (its spatial
/// sort, Hilbert curve with the median policy), or with the middle policy, as the pipeline does.
enum class BareOrder { CgalDefault, MiddlePolicy };

/// Seconds for CGAL's Delaunay triangulation of these points alone (the benchmark's yardstick),
/// the spatial sort included.
double bare_delaunay_seconds(const std::vector<Point3>& points, BareOrder order = BareOrder::CgalDefault);

}  // namespace cadmedial
