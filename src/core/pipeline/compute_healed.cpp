// compute_medial_axis: the pipeline on the shape as given, and again on its healed solids when
// BRepCheck refuses one.
//
// Why a second run rather than healing first: BRepCheck_Analyzer is most of the set-up's time
// (NIST CTC 02: 0.3 s), so the pipeline runs it on its second core beside the first triangulation
// (compute_medial_axis.cpp). Valid parts, nearly all of them, keep that overlap; a part it refuses
// pays for the first try, then extract_solids checks and heals every solid before sampling, and
// the pipeline starts again on what it gives.
#include <chrono>
#include <string>
#include <vector>

#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include "../io/read_shape.h"
#include "compute_as_given.h"
#include "compute_medial_axis.h"

namespace cadmedial {

ComputeResult compute_medial_axis(const TopoDS_Shape& shape, const ComputeParams& params, const Progress& progress) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  try {
    return compute_as_given(shape, params, progress);
  } catch (const FailedBRepCheck&) {
    // healed below
  }
  std::vector<std::string> skipped, warnings;
  // Throws, as without healing, when no solid is left valid.
  const std::vector<TopoDS_Solid> solids = extract_solids(shape, &skipped, &warnings);
  BRep_Builder builder;
  TopoDS_Compound healed;
  builder.MakeCompound(healed);
  for (const TopoDS_Solid& solid : solids) builder.Add(healed, solid);
  const double first_try = std::chrono::duration<double>(Clock::now() - start).count();

  ComputeResult result = compute_as_given(healed, params, progress);
  ComputeStats& stats = result.stats;
  // The healing's words first: the solids' own warnings follow, numbered as the result is.
  warnings.insert(warnings.end(), stats.warnings.begin(), stats.warnings.end());
  stats.warnings = std::move(warnings);
  skipped.insert(skipped.end(), stats.skipped.begin(), stats.skipped.end());
  stats.skipped = std::move(skipped);
  // The try that BRepCheck stopped and the healing are this run's time too.
  for (auto& [stage, seconds] : stats.timings)
    if (stage == "total") seconds += first_try;
  stats.timings.insert(stats.timings.end() - (stats.timings.empty() ? 0 : 1), {"healing", first_try});
  return result;
}

}  // namespace cadmedial
