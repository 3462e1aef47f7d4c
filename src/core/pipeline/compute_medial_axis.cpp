#include "compute_medial_axis.h"
#include "convex_edge_reach.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <atomic>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include <Bnd_Box.hxx>
#include <BRepBndLib.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>

#include "../errors.h"
#include "../exact/boundary_distance.h"
#include "../exact/snap_to_axis.h"
#include "../features/classify_features.h"
#include "../features/solid_euler.h"
#include "../io/read_shape.h"
#include "../medial/medial_axis.h"
#include "../medial/mesh_euler.h"
#include "../medial/weld_vertices.h"
#include "../medial/open_flat_pockets.h"
#include "../medial/reconstruct_faces.h"
#include "../sampling/sample_solid.h"
#include "../sampling/spacing_field.h"
#include "../sampling/edge_walls.h"
#include "../sampling/thin_walls.h"
#include "../two_cores.h"
#include "compute_as_given.h"
#include "exact_inside_test.h"

namespace cadmedial {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// More samples than this would need more memory than a workstation has: the whole pipeline
// peaks near 2 KiB per sample (bench_pipeline: 462 MiB at 250,000 samples); refuse before trying.
constexpr double kMaxSamples = 1.0e7;
constexpr double kMinSamples = 100;

struct Measure {
  std::vector<SolidMeasure> solids;
  double diag = 0;
};

Measure measure(const std::vector<TopoDS_Solid>& solids, const std::vector<Features>& features) {
  Measure m;
  Bnd_Box box;
  for (size_t i = 0; i < solids.size(); ++i) {
    m.solids.push_back(measure_solid(solids[i], features[i]));
    BRepBndLib::Add(solids[i], box);
  }
  if (!box.IsVoid()) m.diag = std::sqrt(box.SquareExtent());
  return m;
}

double estimate_samples(const Measure& m, double h) {
  double n = 0;
  for (const SolidMeasure& s : m.solids) n += estimate_samples(s, h);
  return n;
}

// The estimate falls as the spacing grows: bisect on log h.
double spacing_for(const Measure& m, double n) {
  if (m.diag <= 0) return 1.0;
  double lo = m.diag * 1e-7, hi = m.diag;
  for (int i = 0; i < 60; ++i) {
    const double mid = std::sqrt(lo * hi);
    (estimate_samples(m, mid) > n ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

SamplingPlan plan(const Measure& m, const SamplingParams& params) {
  SamplingPlan p;
  if (params.spacing > 0) {
    p.spacing = params.spacing;
  } else {
    const double n = params.target_samples > 0 ? static_cast<double>(params.target_samples)
                                               : static_cast<double>(SamplingParams::default_target_samples);
    p.spacing = spacing_for(m, n);
  }
  const double est = estimate_samples(m, p.spacing);
  if (est > kMaxSamples) {
    throw InvalidInput("spacing " + message_number(p.spacing) + " would need about " +
                       std::to_string(static_cast<long long>(est)) + " samples, more than the limit of " +
                       std::to_string(static_cast<long long>(kMaxSamples)) + "; use --spacing " +
                       message_number(spacing_for(m, kMaxSamples)) + " or more");
  }
  // Fewer samples than this cannot carry a medial axis (a box needs its corners, edges and a
  // few points per face): a spacing near the part's size is a mistake, not a coarse answer.
  if (est < kMinSamples)
    throw InvalidInput("spacing " + message_number(p.spacing) + " is too coarse for this part (about " +
                       message_number(std::round(est)) + " samples); use --spacing " + message_number(spacing_for(m, 10 * kMinSamples)) +
                       " or less");
  p.estimated_samples = static_cast<std::size_t>(std::llround(est));
  return p;
}

void add_timing(Timings& timings, const std::string& stage, double s) {
  for (auto& [name, value] : timings)
    if (name == stage) {
      value += s;
      return;
    }
  timings.push_back({stage, s});
}

}  // namespace

void check_params(const ComputeParams& params) {
  const double h = params.sampling.spacing;
  if (!std::isfinite(h) || h < 0) throw InvalidInput("spacing must be a positive finite number, got " + message_number(h));
  if (h > 0 && params.sampling.target_samples > 0) throw InvalidInput("give either spacing or samples, not both");
  if (params.sampling.target_samples > static_cast<std::size_t>(kMaxSamples))
    throw InvalidInput("samples must be at most " + std::to_string(static_cast<long long>(kMaxSamples)));
  const double f = params.sampling.min_feature;
  if (!std::isfinite(f) || f < 0)
    throw InvalidInput("the minimum feature size must be a positive finite number, got " + message_number(f));
  if (params.sampling.target_samples > 0 && params.sampling.target_samples < 100)
    throw InvalidInput("samples must be at least 100, got " + std::to_string(params.sampling.target_samples));
  const double theta = params.medial.theta_deg;
  if (!std::isfinite(theta) || theta <= 0 || theta >= 90)
    throw InvalidInput("theta must be in (0, 90) degrees, got " + message_number(theta));
  const double tol = params.compact.tolerance;
  if (!std::isfinite(tol) || tol < 0)
    throw InvalidInput("the simplification tolerance must be a finite number >= 0, got " + message_number(tol));
  if (params.compact.relative && tol >= 1)
    throw InvalidInput("the simplification tolerance as a share of the diagonal must be below 1 (100 %), got " +
                       message_number(tol));
  const double rho = params.medial.rho;
  if (!std::isfinite(rho) || rho <= 0) throw InvalidInput("rho must be a positive finite number, got " + message_number(rho));
}

namespace {

// Thin walls (adaptive sampling): the local spacing per unit of the wall's half thickness (the
// radius), at most kMaxRefinement times finer than the spacing (16 times the samples per area),
// growing back with slope kGradation away from the wall.
constexpr double kSpacingPerRadius = 0.5;
constexpr double kMaxRefinement = 4.0;
// Finer than that, up to kDeepestRefinement, when the sampling takes at most kSampleBudget times
// the uniform sampling's count (tried only when estimate_samples says it will: a sampling over
// budget is thrown away).
constexpr double kDeepestRefinement = 256.0;
constexpr double kSampleBudget = 3.0;
// How far from its edges a mirrored thin wall is sampled finer, in spacings.
constexpr double kJunctionReach = 2.0;
constexpr double kGradation = 0.5;

struct SolidSampling {
  Samples samples;
  SpacingField field{1.0};  ///< uniform, or finer at thin walls
  /// The samples' face domains, until built (the pipeline builds them beside the triangulation).
  FaceDomainBuilder domains;
  /// The thinnest wall, when the first pass's answer is final (nothing was refined).
  std::optional<ThinWall> thin;
  /// The thin-wall check of the uniform sampling is still to run (compute_medial_axis runs it
  /// beside the triangulation).
  bool walls_pending = false;
  /// After a refinement: half the thickness of the thinnest wall the uniform pass found.
  double first_thinnest = std::numeric_limits<double>::infinity();
};

// Per sample of a uniform sampling, half the thickness of a wall thinner than the spacing: on
// faces from the samples (thin_walls.h; wedges of more than about 18 degrees are sampled finer
// near their edge too: tail_turbine's 43-degree edges had holes in the sheet there), and exactly
// at the rims (edge_walls.h), where the sheet forks to two edges a wall's thickness apart: a chip
// resistor's terminal caps, 1.4 spacings thick, had half their edges unreached, and the sample
// estimate had missed them. The mirrored faces (mirror_thin_walls.h) carry a sheet at any
// spacing, but not its junctions: without the faces' radii the Y-rod at 15,000 samples had one
// loop too many and NIST FTC 11 four.
// Walls under SamplingParams::min_feature count as that thick: the refinement goes no finer than
// the minimum feature needs.
std::vector<double> radii_of_thin_walls(const Samples& samples, const Features& features, double spacing,
                                        double min_feature, SolidSampler& sampler, const Progress& progress,
                                        int threads) {
  std::vector<double> radii =
      wall_radii(samples, spacing, convex_face_pairs(features), kSharpWedgeDot, progress, threads);
  // Mirrored faces carry the wall's sheet: only its rims and junctions need the finer samples.
  if (sampler.mirrors_thin_walls()) keep_near_edges(samples, kJunctionReach * spacing, radii);
  const std::vector<double> rims = sampler.edge_wall_radii(samples, spacing);
  const double floor = 0.5 * min_feature;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    radii[i] = std::min(radii[i], rims[i]);
    // Raised to the floor, a wall as thick as two spacings is not thin at all (as wall_radii reads it).
    if (radii[i] < floor) radii[i] = floor < spacing ? floor : std::numeric_limits<double>::infinity();
  }
  return radii;
}

// Whether radii_of_thin_walls finds any (run beside the triangulation, on one thread).
bool has_thin_walls(const Samples& samples, const Features& features, double spacing, double min_feature,
                    SolidSampler& sampler, const Progress& progress) {
  for (double r : radii_of_thin_walls(samples, features, spacing, min_feature, sampler, progress, 1))
    if (r < spacing) return true;
  return false;
}

// The spacing there (uniform when no wall is thinner than the spacing), measured on the faces and
// edges that the sampler refines.
SpacingField thin_wall_field(const Samples& samples, const Features& features, double spacing,
                             const std::vector<double>& radii, double max_refinement) {
  SpacingField field = thin_wall_spacing(samples, radii, spacing, kSpacingPerRadius, max_refinement, kGradation);
  if (!field.is_uniform()) field.measure_on(samples, features.edge_faces);
  return field;
}

// No wall thinner than the spacing: the uniform sampling is final, and so is its thinnest wall.
void keep_uniform(SolidSampling& s, double spacing) {
  s.field = SpacingField(spacing);
  s.thin = ThinWall{};
  s.walls_pending = false;
}

// The sharpest convex wedge of the sampled solid: the smallest dot product of the two faces'
// normals over the convex edge samples (they carry both), and where (1 when there is none).
struct SharpestWedge {
  double dot = 1.0;
  Point3 at{0, 0, 0};
  double degrees() const { return 180.0 - std::acos(std::clamp(dot, -1.0, 1.0)) * 180.0 / 3.14159265358979323846; }
};

SharpestWedge sharpest_wedge(const Samples& samples) {
  SharpestWedge w;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples.edge_convex[i] != 1) continue;
    const double d = samples.normals_dot(i);
    if (d < w.dot) w.dot = d, w.at = samples.points[i];
  }
  return w;
}

// Whether a convex edge of the sampled solid is sharper than kSharpWedgeDot. Near such a wedge
// the thin-wall check finds the wedge itself thin; sampled finer than a quarter there, the sheet
// that bisects it got holes: PocketTest's 14-degree wedge, Euler 2 / 1 / -2 / -2 at 12k / 20k /
// 30k / 50k samples, where a quarter gave 1 at each.
bool has_sharp_wedge(const Samples& samples) { return sharpest_wedge(samples).dot < kSharpWedgeDot; }

// The solid sampled again, finer where its uniform sampling s.samples shows walls thinner than
// the spacing (radii: radii_of_thin_walls); or, when none is, kept. Down to kMaxRefinement times
// finer, then, where the thinnest wall needs finer still and the samples stay within budget,
// down to what it needs (at most kDeepestRefinement), unless the solid has a sharp wedge (above).
// NIST FTC 06's raised letters, 0.8 to 3 mm wide at spacing 11.7, need 16 to 32: Euler -21 at 4
// times, -12 at 8, -9 (the solid's) at 16 and 32, with 32,067 / 38,575 / 44,936 / 47,616
// samples. A solid whose walls are thin over a large area stays at 4 times: the shelf took
// 280,849 samples there and 918,767 at 16.
void resample_for(SolidSampling& s, const Features& features, const SolidMeasure& measure, double spacing,
                  const std::vector<double>& radii, SolidSampler& sampler, const Progress& progress) {
  double thinnest = spacing;
  for (double r : radii) thinnest = std::min(thinnest, r);
  const double needed = std::min(kDeepestRefinement, spacing / (kSpacingPerRadius * thinnest));
  const double first = static_cast<double>(s.samples.size());
  s.first_thinnest = thinnest;
  // Whether a field is uniform does not depend on how fine it may go: the finer one, when it is
  // tried, is made first, and the other only when it is needed.
  if (needed > kMaxRefinement && !has_sharp_wedge(s.samples)) {
    SpacingField finer = thin_wall_field(s.samples, features, spacing, radii, needed);
    if (finer.is_uniform()) return keep_uniform(s, finer.uniform());
    s.walls_pending = false;
    // The estimate is within 15 % of the count on the parts of ../shared/data/models where it is
    // near the budget (bench/README.md). The one before (a quarter to nine tenths of the count)
    // had NIST CTC 02 at 66k samples sample 210,185 points in 1.9 s and throw them away.
    if (estimate_samples(measure, features, finer, s.samples) <= kSampleBudget * first) {
      FaceDomainBuilder domains;
      Samples more = sampler.sample(finer, domains, progress);
      if (static_cast<double>(more.size()) <= kSampleBudget * first) {
        s.samples = std::move(more);
        s.domains = std::move(domains);
        s.field = std::move(finer);
        return;
      }
    }
  }
  SpacingField field = thin_wall_field(s.samples, features, spacing, radii, kMaxRefinement);
  if (field.is_uniform()) return keep_uniform(s, field.uniform());
  s.walls_pending = false;
  s.samples = sampler.sample(field, s.domains, progress);
  s.field = std::move(field);
}

// Runs a sampling step of solid i of n: a failure names the solid when there are several
// ("solid 2: edge 1: cannot sample: ...").
template <class Step>
void naming_solid(std::size_t i, std::size_t n, Step&& step) {
  try {
    step();
  } catch (const GeometryError& err) {
    if (n < 2) throw;
    throw GeometryError("solid " + std::to_string(i + 1) + ": " + err.what());
  }
}

// A uniform sampling of a solid at `spacing`; with `walls_pending`, its thin-wall check is left to
// the pipeline, which runs it beside the triangulation.
SolidSampling sample_uniformly(SolidSampler& sampler, double spacing, bool walls_pending, const Progress& progress) {
  SolidSampling s;
  s.samples = sampler.sample(SpacingField(spacing), s.domains, progress);
  s.field = SpacingField(spacing);
  s.walls_pending = walls_pending;
  return s;
}

// With a target count, the plan's estimate ignores the extra samples that curved faces take:
// sample, and rescale the spacing by the square root of the miss until within 15 % (3 passes).
// Then where walls are thinner than the spacing allows, sample the solid again with a finer
// local spacing there (the target count is the uniform passes'); or, with `defer_walls`, leave
// that check to the caller (walls_pending).
std::vector<SolidSampling> sample_solids(std::vector<std::unique_ptr<SolidSampler>>& samplers,
                                         const std::vector<Features>& features, const Measure& m,
                                         const SamplingParams& params,
                                         double& spacing, bool defer_walls, const Progress& progress) {
  std::vector<SolidSampling> out;
  const int passes = params.spacing > 0 ? 1 : 3;
  const double target = params.target_samples > 0 ? static_cast<double>(params.target_samples)
                                                   : static_cast<double>(SamplingParams::default_target_samples);
  // One sampler per solid for all passes: what a pass leaves unchanged is not redone.
  for (int pass = 0; pass < passes; ++pass) {
    out.clear();
    double total = 0;
    for (size_t i = 0; i < samplers.size(); ++i) {
      naming_solid(i, samplers.size(),
                   [&] { out.push_back(sample_uniformly(*samplers[i], spacing, false, progress)); });
      total += static_cast<double>(out.back().samples.size());
    }
    const double miss = total / target;
    if (passes == 1 || std::abs(miss - 1.0) < 0.15 || pass + 1 == passes) break;
    spacing *= std::sqrt(miss);
  }
  if (!params.adapt_to_walls) return out;  // the worker finds the thinnest wall for the warning
  for (size_t i = 0; i < samplers.size(); ++i) {
    SolidSampling& s = out[i];
    s.walls_pending = true;
    if (defer_walls) continue;
    naming_solid(i, samplers.size(), [&] {
      const std::vector<double> radii = radii_of_thin_walls(s.samples, features[i], spacing, params.min_feature, *samplers[i], progress, 2);
      resample_for(s, features[i], m.solids[i], spacing, radii, *samplers[i], progress);
    });
  }
  return out;
}

std::vector<std::unique_ptr<SolidSampler>> samplers_for(const std::vector<TopoDS_Solid>& solids,
                                                        const std::vector<Features>& features,
                                                        const SamplingParams& params,
                                                        std::vector<FaceSetup> faces = {}) {
  std::vector<std::unique_ptr<SolidSampler>> samplers;
  for (size_t i = 0; i < solids.size(); ++i) {
    samplers.push_back(std::make_unique<SolidSampler>(solids[i], features[i],
                                                      i < faces.size() ? std::move(faces[i]) : FaceSetup()));
    samplers.back()->mirror_thin_walls(params.adapt_to_walls);
  }
  return samplers;
}

// A convex edge sharper than the thin-wall sampling adapts to (kSharpWedgeDot): the sheet that
// bisects it is undersampled near the edge, and nothing else in the result would say so. A
// triangle prism with a 10-degree corner gives Euler 1 / 0 / 0 at 10k / 20k / 40k samples; one
// with a 15-degree corner is right at each (fill_sheet_holes), but by a repair, not the sampling.
void warn_of_sharp_wedge(const Samples& samples, int solid, int solids, std::vector<std::string>& warnings) {
  const SharpestWedge w = sharpest_wedge(samples);
  if (!(w.dot < kSharpWedgeDot)) return;
  std::ostringstream msg;
  msg.precision(3);
  if (solids > 1) msg << "solid " << solid + 1 << ": ";
  msg << "a convex edge near (" << w.at[0] << ", " << w.at[1] << ", " << w.at[2] << ") is a " << w.degrees()
      << "-degree wedge, sharper than the " << SharpestWedge{kSharpWedgeDot}.degrees()
      << " degrees the sampling adapts to; the axis near it may have holes or loose pieces";
  warnings.push_back(msg.str());
}

// What `failure` says.
std::string failure_message(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const Standard_Failure& e) {
    return std::string("OpenCASCADE: ") + e.GetMessageString();
  } catch (const std::bad_alloc&) {
    return "out of memory";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown error";
  }
}

// Whether a solid's axis has the solid's topology, as far as the counts tell: its Euler
// characteristic (the inner medial axis is homotopy equivalent to the solid) and one piece. The
// inner stage keeps the largest piece and those that reach the boundary: a sheet that broke off
// (a thin rib's, where the samples across it are too few) is lost without changing the Euler
// characteristic, so the stray pieces count too. (Not counting them, six ribs 0.6 thick at
// spacing 1.2 were not refined: 210 stray pieces, 3.5 % of the axis's faces.) Specks without a
// Voronoi face (a sharp wedge's crossing fans, loose 1-D edges) are not pieces (MedialAxisStats).
bool topology_is_right(const MedialAxisStats& ms, const SolidStats& ss) {
  return ms.euler_characteristic == ss.solid_euler_characteristic && ms.components <= 1;
}

// SamplingParams::refine_topology: each try samples the solid at its spacing over the square root
// of kTopologySampleFactor (about that many times the samples), at most kTopologyRefinements
// times, and not past kMaxRefinedSamples. On the parts of ../shared/data/models whose axis is
// wrong at the default 20,000 samples, NIST FTC 08 and boxed_sphere are right after one try, NIST
// CTC 02 and 03 and Schenkel after two; brlcad's c.stp is not (bench/README.md).
constexpr double kTopologySampleFactor = 2.5;
constexpr int kTopologyRefinements = 2;
constexpr double kMaxRefinedSamples = 1.0e6;  // about 2 GiB at the pipeline's 2 KiB per sample

// Whether a solid whose axis came out of `samples` samples is worth sampling again, finer.
bool worth_refining(const ComputeParams& params, const SolidStats& ss, const MedialAxisStats& ms, std::size_t samples) {
  return params.sampling.refine_topology && !params.medial.plain_medial && !topology_is_right(ms, ss) &&
         ss.refinements < kTopologyRefinements &&
         static_cast<double>(samples) * kTopologySampleFactor <= kMaxRefinedSamples;
}

// The output's topology is not the solid's: a sheet has holes or extra loops, or pieces of the
// axis were lost, where the samples are too sparse. The thin-wall warning may say where; this
// says that it happened (axom's boxed_sphere has no wall under two spacings, and a wrong axis).
void warn_of_topology(const MedialAxisStats& ms, const SolidStats& ss, int solid, int solids,
                      std::vector<std::string>& warnings) {
  if (topology_is_right(ms, ss)) return;
  std::ostringstream msg;
  msg.precision(3);
  if (solids > 1) msg << "solid " << solid + 1 << ": ";
  if (ms.euler_characteristic != ss.solid_euler_characteristic)
    msg << "the medial axis's Euler characteristic is " << ms.euler_characteristic << " where the solid's is "
        << ss.solid_euler_characteristic << ": the axis has holes or extra loops";
  else
    msg << "parts of the medial axis are missing";
  if (ms.components > 1) msg << " (it came in " << ms.components << " pieces; stray ones were dropped)";
  if (ss.refinements > 0)
    msg << ", even sampled " << ss.refinements << (ss.refinements == 1 ? " time" : " times")
        << " finer (down to spacing " << ss.spacing << ")";
  msg << "; more samples (a smaller spacing) usually mend it";
  warnings.push_back(msg.str());
}

// Facing walls closer than two (local) spacings: the Voronoi sheet between them is only as good as
// the samples across the wall (hardening.md: a rib narrower than h leaves holes in its sheet), and
// nothing else in the result would say so. After the refinement, those are the walls thinner than
// the finest it may go, or that the first pass missed.
// Walls under the minimum feature size the user gave were left unresolved on purpose: the warning
// says that, with the place.
void warn_of_thin_walls(const ThinWall& w, const SpacingField& field, double min_feature, int solid, int solids,
                        SolidStats& ss, std::vector<std::string>& warnings) {
  ss.thinnest_wall = 2.0 * w.radius;
  ss.thinnest_wall_at = w.at;
  const double local = field.at(w.at);
  const bool below_minimum = 2.0 * w.radius < min_feature;
  if (!(w.radius < local) && !below_minimum) return;
  const bool adapted = !field.is_uniform();
  std::ostringstream msg;
  msg.precision(3);
  if (solids > 1) msg << "solid " << solid + 1 << ": ";
  if (below_minimum) {
    msg << "walls down to " << 2.0 * w.radius << " thick (near (" << w.at[0] << ", " << w.at[1] << ", " << w.at[2]
        << ")) are thinner than the minimum feature size given (" << min_feature
        << ") and were sampled only as finely as it needs; the axis between them may have holes or extra loops";
    warnings.push_back(msg.str());
    return;
  }
  msg << "walls down to " << 2.0 * w.radius << " thick (near (" << w.at[0] << ", " << w.at[1] << ", " << w.at[2]
      << ")) are thinner than two sample spacings (" << 2.0 * local
      << (adapted ? ", the finest the sampling adapts to" : "")
      << "); the axis between them may have holes or extra loops: a spacing of "
      << w.radius * (adapted ? kSpacingPerRadius * kMaxRefinement : 1.0) << " or less resolves them";
  warnings.push_back(msg.str());
}

// Convex edges the axis does not reach along 98 % of their length (issue 32, item 4): where the
// walls beside an edge are about a spacing thick the completion may leave it short, and the
// topology counts do not show it. The three least reached are named, with a place.
void warn_of_short_edges(const EdgeReach& reach, int solid, int solids, std::vector<std::string>& warnings) {
  if (reach.short_edges.empty()) return;
  std::ostringstream msg;
  msg.precision(3);
  if (solids > 1) msg << "solid " << solid + 1 << ": ";
  const std::size_t named = std::min<std::size_t>(3, reach.short_edges.size());
  const bool one = reach.short_edges.size() == 1;
  msg << (one ? "a convex edge is" : std::to_string(reach.short_edges.size()) + " convex edges are")
      << " reached by the axis along less than " << 100.0 * EdgeReach::kReachedShare << " % of "
      << (one ? "its" : "their") << " length: ";
  for (std::size_t k = 0; k < named; ++k) {
    const ShortEdge& e = reach.short_edges[k];
    msg << (k ? "; " : "") << "edge " << e.edge + 1 << " along " << std::lround(100.0 * e.reached) << " % (not near ("
        << e.at[0] << ", " << e.at[1] << ", " << e.at[2] << "))";
  }
  if (reach.short_edges.size() > named) msg << "; and " << reach.short_edges.size() - named << " more";
  msg << "; the part beside " << (one ? "it" : "them")
      << " is finer than the sampling there (thin walls, a sharp wedge): a smaller spacing usually reaches "
      << (one ? "it" : "them");
  warnings.push_back(msg.str());
}

// The solids sampled as compute_medial_axis samples them, with the spacing it settles on.
std::vector<SolidSampling> sample_as_computed(const TopoDS_Shape& shape, const SamplingParams& params,
                                              SamplingPlan& sp) {
  ComputeParams p;
  p.sampling = params;
  check_params(p);
  try {
    const std::vector<TopoDS_Solid> solids = extract_solids(shape);
    std::vector<Features> features;
    for (const TopoDS_Solid& solid : solids) features.push_back(classify_features(solid));
    const Measure m = measure(solids, features);
    sp = plan(m, params);
    std::vector<std::unique_ptr<SolidSampler>> samplers = samplers_for(solids, features, params);
    std::vector<SolidSampling> sampled = sample_solids(samplers, features, m, params, sp.spacing, false, {});
    sp.estimated_samples = 0;
    for (std::size_t i = 0; i < sampled.size(); ++i) {
      naming_solid(i, sampled.size(), [&] { sampled[i].domains.build(sampled[i].samples); });
      sp.estimated_samples += sampled[i].samples.size();
    }
    return sampled;
  } catch (const Standard_Failure& err) {
    throw GeometryError(std::string("cannot sample the shape: ") + err.GetMessageString());
  }
}

// What stays the same when a solid is sampled again.
struct SolidJob {
  int index, count;  ///< the solid's, and how many the shape has
  const Features& features;
  const SolidMeasure& measure;
  SolidSampler& sampler;
  const MedialParams& medial;
  double min_feature;  ///< SamplingParams::min_feature
  /// The exact B-rep settles the Voronoi vertices that the sample normals leave in doubt; its
  /// classifiers are made ready on the worker (prepare_inside).
  const InsideTest& inside;
  const std::function<void()>& prepare_inside;
};

// A solid's medial axis from one sampling, and what the worker beside it measured.
struct SolidAxis {
  MedialMesh mesh;
  MedialAxisStats ms;
  ThinWall thin;
  double check_seconds = 0, reconstruction_seconds = 0, walls_seconds = 0;
};

// The medial axis of one solid from `sampling` at `spacing`. The worker runs the checks in
// `to_check` (and clears it) once its umbrellas are made; `timings` gets the "sampling" of a
// finer pass at thin walls.
SolidAxis axis_of(const SolidJob& job, SolidSampling& sampling, double spacing, std::vector<DeferredCheck>& to_check,
                  Timings& timings, const Progress& sub) {
  const int i = job.index, n = job.count;
  const Samples& samples = sampling.samples;
  SolidAxis out;
  MedialMesh& mesh = out.mesh;
  MedialAxisStats& ms = out.ms;
  ThinWall& thin = out.thin;
  double &check_seconds = out.check_seconds, &reconstruction_seconds = out.reconstruction_seconds,
         &walls_seconds = out.walls_seconds;
  // The face-by-face reconstruction, then the thin-wall check, run on a second thread while
  // CGAL triangulates (they need only the samples; the selection waits for them); their time
  // overlaps "delaunay". The worker does not call the user's progress callback (it may hold
  // Python's lock); it checks a flag the main thread sets when it gives up (cancel, error),
  // so the future's destructor, which waits for it, does not wait long.
  report(sub, "reconstruction", 0.0);
  // Twice when the thin-wall check of the uniform sampling, which runs first on the worker,
  // finds walls to sample finer: the triangulation of the uniform samples is given up.
  for (;;) {
    std::atomic<bool> abandoned{false}, resample{false};
    const Progress worker = [&abandoned](const std::string&, double) { return !abandoned.load(); };
    // The selection starts once the triangulation is done, and then waits for the umbrellas: the
    // classifiers are left to the first points asked (on two cores) rather than make it wait.
    std::atomic<bool> triangulated{false};
    const Progress stages = [&sub, &triangulated](const std::string& stage, double f) {
      if (stage == "selection") triangulated = true;
      return sub ? sub(stage, f) : true;
    };
    // The umbrellas come first (the selection waits for them), then the solid's check, which
    // only an error or the end of this solid waits for (NIST CTC 02's takes 0.3 s, longer
    // than its triangulation at 20k samples), then the thinnest wall for the warning.
    std::promise<Umbrellas> reconstructed;
    std::shared_future<Umbrellas> umbrellas = reconstructed.get_future().share();
    // The exact inside tests ask the B-rep: on a solid its check refuses, the refusal says
    // better what is wrong than a failure there. They wait for the check.
    std::promise<void> checked;
    const std::shared_future<void> checked_first = checked.get_future().share();
    const InsideTest checked_inside = [&inside = job.inside, checked_first](const std::vector<Point3>& pts) {
      checked_first.get();
      return inside(pts);
    };
    std::atomic<bool> cancelled{false};
    std::future<void> worker_done =
        std::async(std::launch::async, [&s = sampling, &f = job.features, &sampler = job.sampler, &check_seconds, &reconstruction_seconds,
                                        &walls_seconds, &thin, &worker, spacing, min_feature = job.min_feature, &to_check,
                                        &prepare_inside = job.prepare_inside, &abandoned, &cancelled, &triangulated,
                                        &resample, &reconstructed, &checked, i, n] {
          try {
            auto start = Clock::now();
            if (s.walls_pending) {
              // Most parts have no wall this thin at their spacing: looking beside the
              // triangulation saves the check's time; where one is, the triangulation is given
              // up as soon as it is found.
              const bool thin_walls = has_thin_walls(s.samples, f, spacing, min_feature, sampler, worker);
              walls_seconds += seconds_since(start);
              if (thin_walls) {
                resample = true;
                reconstructed.set_value(Umbrellas());
                checked.set_value();
                return;  // the check waits for the finer sampling's try
              }
              keep_uniform(s, spacing);
              // Walls under the user's minimum feature size may be what made none thin: measure
              // the thinnest for its warning.
              if (min_feature > 0) s.thin.reset();
            }
            start = Clock::now();
            naming_solid(static_cast<std::size_t>(i), static_cast<std::size_t>(n), [&] { s.domains.build(s.samples); });
            Umbrellas u = reconstruct_faces(s.samples, worker);
            reconstruction_seconds = seconds_since(start);
            reconstructed.set_value(std::move(u));
          } catch (...) {
            // The check below says why, when it refuses the solid.
            reconstructed.set_exception(std::current_exception());
          }
          if (!abandoned && !triangulated) prepare_inside();
          {
            // `checked` is set on every way out (the exact inside tests wait for it).
            struct Gate {
              std::promise<void>& promise;
              bool set = false;
              ~Gate() {
                if (!set) promise.set_value();
              }
            } gate{checked};
            const auto start = Clock::now();
            try {
              // One solid at a time: a cancel waits for one BRepCheck at most.
              for (const DeferredCheck& check : to_check) {
                if (cancelled) return;
                run_deferred_checks({check});
              }
            } catch (...) {
              gate.set = true;
              checked.set_exception(std::current_exception());
              throw;
            }
            to_check.clear();  // done: a second try (after a finer sampling) skips them
            check_seconds += seconds_since(start);
          }
          if (abandoned) return;
          // One thread: the triangulation, or the stages after it, have the other core.
          thin = s.thin ? *s.thin
                        : thinnest_wall_near(s.samples, spacing, convex_face_pairs(f), s.first_thinnest, worker);
        });
    const internal::SetOnExit abandon_on_exit{abandoned};

    const auto t_try = Clock::now();
    try {
      mesh = medial_axis(samples, umbrellas, job.medial, checked_inside, i, &ms, stages, &resample);
    } catch (const Cancelled&) {
      if (!resample) {
        cancelled = true;
        abandoned = true;
        throw;
      }
    } catch (...) {
      // The solid's check, if it refuses the solid, says why better. The worker skips the
      // thinnest wall.
      abandoned = true;
      worker_done.wait();
      try {
        worker_done.get();
      } catch (const InvalidInput&) {
        throw;
      } catch (...) {
      }
      throw;
    }
    if (!resample) {
      worker_done.get();  // the check's refusal, if any
      break;
    }
    worker_done.get();
    try {
      naming_solid(i, n, [&] {
        const std::vector<double> radii = radii_of_thin_walls(samples, job.features, spacing, job.min_feature, job.sampler, sub, 2);
        resample_for(sampling, job.features, job.measure, spacing, radii, job.sampler, sub);
      });
    } catch (const Cancelled&) {
      throw;
    } catch (...) {
      run_deferred_checks(to_check);
      throw;
    }
    // As when the check ran before the triangulation: it and the finer pass are sampling.
    add_timing(timings, "sampling", seconds_since(t_try));
  }
  return out;
}

}  // namespace

SamplingPlan plan_sampling(const TopoDS_Shape& shape, const SamplingParams& params) {
  // The preview must match the compute: sample as compute_medial_axis does and count.
  SamplingPlan sp;
  sample_as_computed(shape, params, sp);
  return sp;
}

std::vector<Samples> sample_shape(const TopoDS_Shape& shape, const SamplingParams& params) {
  SamplingPlan sp;
  std::vector<Samples> out;
  for (SolidSampling& s : sample_as_computed(shape, params, sp)) out.push_back(std::move(s.samples));
  return out;
}

ComputeResult compute_as_given(const TopoDS_Shape& shape, const ComputeParams& params, const Progress& progress) {
  check_params(params);
  const auto t_total = Clock::now();
  ComputeResult result;
  ComputeStats& stats = result.stats;
  try {
    auto t0 = Clock::now();
    report(progress, "reading", 0.0);
    // BRepCheck_Analyzer, most of the set-up's time, runs on the second thread while CGAL
    // triangulates the first solid (that core is idle then); the other checks run here.
    std::vector<DeferredCheck> checks;
    const std::vector<TopoDS_Solid> solids = extract_solids(shape, &stats.skipped, checks, &stats.warnings);
    add_timing(stats.timings, "setup", seconds_since(t0));
    const int n = static_cast<int>(solids.size());

    std::vector<Features> features;
    Measure m;
    double spacing = 0;
    std::vector<SolidSampling> sampled;
    std::vector<std::unique_ptr<SolidSampler>> samplers;
    try {
      // The faces' surfaces and classifiers, which the sampling needs first, on the second core
      // meanwhile (it is idle until the sampling), as many as are ready when the plan is: the
      // sampler makes the others (NIST CTC 02's 663 faces take longer than its features).
      std::vector<FaceSetup> faces(solids.size());
      std::atomic<bool> planned{false};
      internal::on_two_cores(
          [&] {
            const internal::SetOnExit planned_on_exit{planned};
            t0 = Clock::now();
            report(progress, "features", 0.0);
            for (const TopoDS_Solid& solid : solids) features.push_back(classify_features(solid));
            add_timing(stats.timings, "features", seconds_since(t0));

            // The plan measures the solids with their features (a second classification cost as much).
            t0 = Clock::now();
            m = measure(solids, features);
            spacing = plan(m, params.sampling).spacing;
            add_timing(stats.timings, "setup", seconds_since(t0));
          },
          [&](const std::atomic<bool>&) {
            for (std::size_t i = 0; i < solids.size() && !planned; ++i) faces[i] = FaceSetup::make(solids[i], &planned);
          });

      t0 = Clock::now();
      samplers = samplers_for(solids, features, params.sampling, std::move(faces));
      sampled = sample_solids(samplers, features, m, params.sampling, spacing, true, progress);
      stats.spacing = spacing;
      add_timing(stats.timings, "sampling", seconds_since(t0));
    } catch (const Cancelled&) {
      throw;
    } catch (...) {
      // A solid that its check refuses can fail anywhere: the check's message says what is wrong.
      run_deferred_checks(checks);
      throw;
    }
    stats.diagonal = m.diag;

    for (int i = 0; i < n; ++i) {
      const TopoDS_Solid& solid = solids[i];
      // Stage fractions are per solid; spread them over the solids.
      const Progress sub = progress ? Progress([&, i](const std::string& stage, double f) {
        return progress(stage, (i + std::clamp(f, 0.0, 1.0)) / n);
      })
                                    : Progress();
      SolidStats ss;
      for (EdgeKind k : features[i].edge_kind) {
        ss.convex_edges += k == EdgeKind::Convex || k == EdgeKind::Mixed;
        ss.concave_edges += k == EdgeKind::Concave;
        ss.smooth_edges += k == EdgeKind::Smooth;
      }
      for (bool c : features[i].nonconcave_corner) ss.nonconcave_corners += c;
      ss.solid_euler_characteristic = solid_euler_characteristic(solid);
      ss.spacing = spacing;
      std::vector<DeferredCheck> to_check;
      to_check.swap(checks);  // all solids' checks with the first solid's triangulation
      const bool checks_here = !to_check.empty();
      std::function<void()> prepare_inside;
      const InsideTest inside = exact_inside_test(solid, 1e-7 * std::max(m.diag, 1e-9), prepare_inside);
      const SolidJob job{i, n, features[i], m.solids[i], *samplers[i], params.medial, params.sampling.min_feature, inside,
                         prepare_inside};
      // One try at the solid's current sampling, with its pockets opened and its times counted.
      auto try_sampling = [&] {
        SolidAxis axis = axis_of(job, sampled[i], ss.spacing, to_check, stats.timings, sub);
        // A void the solid does not have (flat pockets where samples lie in symmetric rings) shows
        // in the Euler characteristic; only then is the whole mesh's incidence worth building.
        ss.opened_pockets = 0;
        if (!params.medial.plain_medial && axis.ms.euler_characteristic != ss.solid_euler_characteristic) {
          const auto t_pockets = Clock::now();
          ss.opened_pockets = open_flat_pockets(axis.mesh);
          axis.ms.euler_characteristic -= static_cast<long>(ss.opened_pockets);
          add_timing(stats.timings, "pockets", seconds_since(t_pockets));
        }
        // Beside the kept triangulation, overlapping "delaunay" as "check" and "reconstruction" do.
        if (axis.walls_seconds > 0 && sampled[i].field.is_uniform())
          add_timing(stats.timings, "walls", axis.walls_seconds);
        if (checks_here) add_timing(stats.timings, "check", axis.check_seconds);  // 0 after the first try
        add_timing(stats.timings, "reconstruction", axis.reconstruction_seconds);
        for (const auto& [stage, s] : axis.ms.timings) add_timing(stats.timings, stage, s);
        return axis;
      };
      SolidAxis axis = try_sampling();
      while (worth_refining(params, ss, axis.ms, sampled[i].samples.size())) {
        // The whole solid finer, not only its thin walls: where the sheets break is not known,
        // and the thin-wall refinement of the finer pass follows as before. The coarser result
        // stays until the finer one is made: a failure there (OpenCASCADE on a face, memory)
        // leaves the user that one and a warning, not an error.
        t0 = Clock::now();
        report(sub, "refining", 0.0);
        SolidSampling coarser = std::move(sampled[i]);
        const SolidStats before = ss;
        ss.spacing /= std::sqrt(kTopologySampleFactor);
        ++ss.refinements;
        std::exception_ptr refinement_failed;
        try {
          naming_solid(i, n, [&] {
            sampled[i] = sample_uniformly(*samplers[i], ss.spacing, params.sampling.adapt_to_walls, sub);
          });
          add_timing(stats.timings, "sampling", seconds_since(t0));
          // The thin walls' own refinement comes on top of the uniform count worth_refining
          // foresaw: the cap holds for what was sampled.
          if (static_cast<double>(sampled[i].samples.size()) > kMaxRefinedSamples)
            throw GeometryError("it took " + std::to_string(sampled[i].samples.size()) + " samples, more than the " +
                                std::to_string(static_cast<long long>(kMaxRefinedSamples)) + " it may take");
          axis = try_sampling();
        } catch (const Cancelled&) {
          throw;
        } catch (const InvalidInput&) {
          throw;
        } catch (const std::exception&) {  // GeometryError, memory, a library's own failure
          refinement_failed = std::current_exception();
        } catch (const Standard_Failure&) {
          refinement_failed = std::current_exception();
        }
        if (refinement_failed) {
          sampled[i] = std::move(coarser);
          ss = before;
          stats.warnings.push_back((n > 1 ? "solid " + std::to_string(i + 1) + ": " : std::string()) +
                                   "sampling finer for the axis's topology failed (" +
                                   failure_message(refinement_failed) + "); the axis is that of the coarser sampling");
          break;
        }
      }
      const Samples& samples = sampled[i].samples;
      MedialMesh& mesh = axis.mesh;
      {
        // Every radius from the B-rep: the samples' distance overstates it between samples.
        const auto t_radii = Clock::now();
        const ExactRadiiStats er = exact_radii(solid, i, m.diag, mesh);
        ss.radius_max_excess = er.max_excess;
        ss.radius_mean_excess = er.mean_excess;
        ss.radii_corrected = er.corrected;
        ss.vertices_moved_inside = er.moved_inside;
        if (er.moved_inside > 0) {
          // Moved onto the boundary, a vertex may meet another there.
          weld_vertices(mesh, 1e-9 * std::max(m.diag, 1e-300));
          axis.ms.euler_characteristic = euler_characteristic(mesh);
        }
        add_timing(stats.timings, "radii", seconds_since(t_radii));
      }
      if (params.compact.tolerance > 0) {
        // The compact mesh flattens what lies on the exact axis: the Voronoi vertices are moved
        // there first (within half a spacing; snap_to_axis.h).
        const auto t_snap = Clock::now();
        const SnapStats sn = snap_to_axis(solid, i, m.diag, 0.5 * ss.spacing, mesh);
        SnapStats& all = stats.snap ? *stats.snap : stats.snap.emplace();
        all.mean_move = (all.mean_move * static_cast<double>(all.snapped) + sn.mean_move * static_cast<double>(sn.snapped)) /
                        std::max<double>(1.0, static_cast<double>(all.snapped + sn.snapped));
        all.vertices += sn.vertices;
        all.snapped += sn.snapped;
        all.max_move = std::max(all.max_move, sn.max_move);
        add_timing(stats.timings, "snap", seconds_since(t_snap));
      }
      {
        const auto t_reach = Clock::now();
        const EdgeReach reach = convex_edge_reach(samples, sampled[i].field, mesh.vertices);
        ss.convex_edges_reached = reach.reached;
        ss.short_convex_edges = reach.short_edges.size();
        warn_of_short_edges(reach, i, n, stats.warnings);
        add_timing(stats.timings, "edges_reached", seconds_since(t_reach));
      }
      const MedialAxisStats& ms = axis.ms;
      ss.samples = samples.size();
      warn_of_thin_walls(axis.thin, sampled[i].field, params.sampling.min_feature, i, n, ss, stats.warnings);
      warn_of_sharp_wedge(samples, i, n, stats.warnings);
      if (!params.medial.plain_medial) warn_of_topology(ms, ss, i, n, stats.warnings);
      ss.vertices = mesh.num_vertices();
      ss.faces = mesh.num_faces();
      ss.dropped_faces = ms.dropped_faces;
      ss.components = ms.components;
      ss.specks = ms.specks;
      ss.pieces = ms.kept_components;
      ss.topology_right = topology_is_right(ms, ss);
      ss.filler_faces = ms.filler_faces;
      ss.edges = ms.bare_edges;
      ss.unattached_faces = ms.unattached_faces;
      ss.euler_characteristic = ms.euler_characteristic;
      ss.exact_inside_tests = ms.exact_inside_tests;
      ss.welded_vertices = ms.welded_vertices;
      ss.mirrored_samples = samplers[i]->mirrored();
      stats.samples += ss.samples;
      stats.solids.push_back(ss);
      // The first solid's mesh is moved, not copied (one solid is the usual case).
      if (result.mesh.num_vertices() == 0 && result.mesh.num_faces() == 0 && result.mesh.num_edges() == 0)
        result.mesh = std::move(mesh);
      else
        result.mesh.append(mesh);
    }
  } catch (const Standard_Failure& err) {
    throw GeometryError(std::string("OpenCASCADE failed: ") + err.GetMessageString());
  } catch (const std::bad_alloc&) {
    throw GeometryError("out of memory; use a larger spacing or fewer samples");
  }
  report(progress, "output", 0.0);
  result.mesh.sort_canonically();
  if (params.compact.tolerance > 0) {
    const auto t_compact = Clock::now();
    SimplifyStats st;
    const double tol = params.compact.relative ? params.compact.tolerance * stats.diagonal : params.compact.tolerance;
    result.mesh = simplify_axis(result.mesh, tol, &st, progress);
    result.mesh.sort_canonically();
    stats.simplify = st;
    add_timing(stats.timings, "compact", seconds_since(t_compact));
    if (st.faces_after >= st.faces_before)
      stats.warnings.push_back("the compact mesh has " + std::to_string(st.faces_after) + " triangles, no fewer than the " +
                               std::to_string(st.faces_before) +
                               " polygons of the full axis: most of it is seams and borders between Voronoi slivers, "
                               "which the simplification keeps (docs/compact.md)");
  }
  stats.vertices = result.mesh.num_vertices();
  stats.faces = result.mesh.num_faces();
  stats.edges = result.mesh.num_edges();
  report(progress, "done", 1.0);
  stats.timings.push_back({"total", seconds_since(t_total)});
  stats.peak_rss_mb = peak_rss_mb();
  return result;
}

}  // namespace cadmedial
