// The whole CAD_MEDIAL pipeline on a shape: solids -> features -> samples -> Delaunay -> medial mesh.
// No geometry of its own: it chains the stages, times them and checks parameters.
#pragma once

#include <string>
#include <optional>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "../progress.h"
#include "../sampling/samples.h"
#include "../compact/simplify_axis.h"
#include "../exact/snap_to_axis.h"
#include "../types.h"

namespace cadmedial {

/// Per-solid figures.
struct SolidStats {
  std::size_t samples = 0;
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t convex_edges = 0;
  std::size_t concave_edges = 0;
  std::size_t smooth_edges = 0;
  std::size_t nonconcave_corners = 0;
  /// selected faces outside the solid or in stray pieces, but for those with a vertex surely
  /// outside (beyond the samples' box, or by its samples' votes alone), which are not built
  std::size_t dropped_faces = 0;
  std::size_t components = 0;      ///< pieces of the inner axis before stray ones were dropped
  std::size_t specks = 0;          ///< pieces without a Voronoi face (not in components), dropped
  std::size_t pieces = 0;          ///< pieces of the output (the stray ones floating inside dropped)
  /// The axis has the solid's topology as far as the counts tell: one piece before the stray ones
  /// were dropped, the solid's Euler characteristic (1-D edges counted).
  bool topology_right = false;
  std::size_t filler_faces = 0;    ///< unselected Voronoi facets kept for the axis's topology
  std::size_t edges = 0;           ///< output edges: 1-D parts of the axis that no face carries
  std::size_t unattached_faces = 0;  ///< completion triangles left out because they would close a loop
  long euler_characteristic = 0;   ///< V - E + F of the output; the solid's when the topology is right
  long solid_euler_characteristic = 0;  ///< the solid's, counted on its B-rep (features/solid_euler.h)
  /// The uniform spacing of the sampling the output comes from: ComputeStats::spacing, or finer
  /// after `refinements` (SamplingParams::refine_topology)
  double spacing = 0.0;
  int refinements = 0;  ///< times the solid was sampled again because its axis's topology was wrong
  /// faces removed to open closed pockets of zero volume (open_flat_pockets), one per pocket
  std::size_t opened_pockets = 0;
  /// Thickness of the thinnest wall the samples show (thinnest_wall), if under 2 spacings, else
  /// infinity.
  double thinnest_wall = 0.0;
  /// The face sample where it was found (meaningless when thinnest_wall is infinite).
  Point3 thinnest_wall_at{0, 0, 0};
  std::size_t exact_inside_tests = 0;  ///< Voronoi vertices the B-rep classifier had to settle
  /// How far the Voronoi radii (distances to the nearest sample) were off the exact ones (the
  /// distance to the B-rep), which the output carries: the largest and mean excess, model units,
  /// and the vertices whose radius shrank (exact/boundary_distance.h).
  double radius_max_excess = 0.0;
  double radius_mean_excess = 0.0;
  std::size_t radii_corrected = 0;
  std::size_t vertices_moved_inside = 0;
  std::size_t mirrored_samples = 0;  ///< face samples placed as mirrors across thin walls
  /// Share of the samples on sharp convex edges (faces turning by more than 10 degrees) within a
  /// spacing of the axis, and the edges reached along less than 98 % of their length (a warning
  /// names them): convex_edge_reach.h
  double convex_edges_reached = 1.0;
  std::size_t short_convex_edges = 0;
  std::size_t welded_vertices = 0;  ///< output vertices closer than 1e-9 of the diagonal to another, merged
};

struct ComputeStats {
  double spacing = 0.0;           ///< the sample spacing the parameters give (model units); see SolidStats::spacing
  std::size_t samples = 0;
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t edges = 0;          ///< 1-D edges of the output mesh (MedialMesh::edges)
  std::vector<SolidStats> solids;
  Timings timings;                ///< per stage, plus "total"; includes "delaunay"
  /// What the user should know about the result (e.g. walls too thin for the spacing), one
  /// sentence each.
  std::vector<std::string> warnings;
  /// What the shape held beside its solids and the engine left out (extract_solids' `skipped`:
  /// open construction surfaces, loose edges), one phrase each.
  std::vector<std::string> skipped;
  double peak_rss_mb = 0.0;
  double diagonal = 0.0;          ///< of the solids' bounding box
  /// With CompactParams::tolerance > 0: the compact mesh's figures (the full mesh's counts, the
  /// largest error, the topology before and after).
  std::optional<SimplifyStats> simplify;
  /// With it: how the vertices were moved onto the exact axis first (snap_to_axis.h), over the solids.
  std::optional<SnapStats> snap;
};

struct ComputeResult {
  MedialMesh mesh;
  ComputeStats stats;
};

/// Checks parameters; throws InvalidInput naming the field (theta, rho, spacing, samples).
void check_params(const ComputeParams& params);

/// The sample spacing that params give for these solids (explicit spacing, or the one that
/// compute_medial_axis settles on for the target count) and the number of samples it yields:
/// it samples the solids as compute_medial_axis does, so the preview is exact.
struct SamplingPlan {
  double spacing = 0.0;
  std::size_t estimated_samples = 0;
};
SamplingPlan plan_sampling(const TopoDS_Shape& shape, const SamplingParams& params);

/// Each solid's boundary samples as compute_medial_axis takes them (the same spacing, calibration
/// and thin-wall refinement), e.g. for a benchmark's yardstick.
std::vector<Samples> sample_shape(const TopoDS_Shape& shape, const SamplingParams& params);

/// Computes the inner medial axis of every solid of `shape`, each on its own; face_solid holds the
/// solid's index. Throws InvalidInput (bad shape or parameters), GeometryError, or Cancelled.
ComputeResult compute_medial_axis(const TopoDS_Shape& shape, const ComputeParams& params,
                                  const Progress& progress = {});

/// JSON object with samples, vertices, faces, edges, spacing, timings {stage: seconds}, peak_rss_mb,
/// warnings, skipped, solids.
std::string stats_to_json(const ComputeStats& stats);

/// Peak resident set size of this process so far, MiB.
double peak_rss_mb();

}  // namespace cadmedial
