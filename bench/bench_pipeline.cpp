// Speed of the pipeline per stage beside CGAL's bare Delaunay triangulation of the same samples,
// in the same run (the machine is shared and noisy: only ratios within one run mean much).
//
//   bench_pipeline INPUT [--samples N1,N2,...] [--repeat K] [--json FILE] [--uniform] [--release-memory]
//
// For each target count the spacing is calibrated by sampling until the count is within 3 %; then
// compute_medial_axis runs at that spacing, as the program does, and the bare Delaunay after it,
// K times in turn (default 3): each is reported at its fastest (the stages from the fastest
// compute), so that another process's burst spoils one try, not the row. With --uniform, thin walls
// are not sampled again more densely (the program's --uniform): the cost of that refinement shows
// against a run without it. The yardstick is CGAL's range insert, as it comes (Hilbert sort with
// the median policy); the pipeline sorts with the middle policy, a few per cent faster on most
// parts, so the last column divides by a bare triangulation sorted that way too.
//
// Like the program, the benchmark keeps freed memory for reuse (keep_freed_memory): with glibc's
// defaults each compute re-faulted most of its pages while the bare triangulation, which frees and
// takes back blocks of the same sizes, re-faulted none. --release-memory keeps glibc's defaults.
// The page faults of the fastest tries are printed beside their times.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "core/errors.h"
#include "core/features/classify_features.h"
#include "core/io/read_shape.h"
#include "core/medial/medial_axis.h"
#include "core/medial/reconstruct_faces.h"
#include "core/pipeline/compute_medial_axis.h"
#include "core/pipeline/exact_inside_test.h"
#include "core/process_memory.h"
#include "core/sampling/sample_solid.h"

using namespace cadmedial;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

long minor_faults() {
  struct rusage u {};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

struct Row {
  std::size_t target = 0, samples = 0, vertices = 0, faces = 0;
  double spacing = 0, bare_delaunay = 0;
  double bare_middle = 0;  ///< the bare Delaunay with the pipeline's spatial sort (the middle policy)
  /// The median over the tries of total / bare within each try: the two run back to back, so a
  /// slow spell of the shared machine spoils both alike (the fastest of each can come from
  /// different spells).
  double median_try_ratio = 0;
  long faults = 0, bare_faults = 0;  ///< page faults of the fastest compute and bare triangulation
  Timings timings;  ///< compute_medial_axis's stages and total
};

double stage(const Timings& t, const std::string& name) {
  for (const auto& [n, s] : t)
    if (n == name) return s;
  return 0;
}

// The whole pipeline as the program runs it (compute_medial_axis at a given spacing, stages
// overlapping where they do), then CGAL's bare Delaunay of the same samples.
Row run(const TopoDS_Solid& solid, std::size_t target, double spacing0, int repeat, bool uniform) {
  Row row;
  row.target = target;
  const Features features = classify_features(solid);
  // Calibrate the spacing on the sample count (not timed: a user gives the spacing directly).
  double h = spacing0;
  for (int pass = 0; pass < 6; ++pass) {
    const double miss = static_cast<double>(sample_solid(solid, features, h).size()) / static_cast<double>(target);
    if (std::abs(miss - 1.0) < 0.03) break;
    h *= std::sqrt(miss);
  }
  ComputeParams params;
  params.sampling.spacing = h;
  params.sampling.adapt_to_walls = !uniform;
  row.spacing = h;
  // The same samples again (sampling is deterministic; thin walls refined as the pipeline does),
  // for the yardstick.
  const std::vector<Point3> points = sample_shape(solid, params.sampling).front().points;
  double best = -1;
  std::vector<double> ratios;
  for (int k = 0; k < repeat; ++k) {
    long f0 = minor_faults();
    const ComputeResult result = compute_medial_axis(solid, params);
    const long faults = minor_faults() - f0;
    const double total = stage(result.stats.timings, "total");
    if (best < 0 || total < best) {
      best = total;
      row.timings = result.stats.timings;
      row.samples = result.stats.samples;
      row.vertices = result.mesh.num_vertices();
      row.faces = result.mesh.num_faces();
      row.faults = faults;
    }
    f0 = minor_faults();
    const double bare = bare_delaunay_seconds(points);
    if (k == 0 || bare < row.bare_delaunay) row.bare_faults = minor_faults() - f0;
    row.bare_delaunay = k == 0 ? bare : std::min(row.bare_delaunay, bare);
    const double middle = bare_delaunay_seconds(points, BareOrder::MiddlePolicy);
    row.bare_middle = k == 0 ? middle : std::min(row.bare_middle, middle);
    ratios.push_back(total / bare);
  }
  std::sort(ratios.begin(), ratios.end());
  const std::size_t n = ratios.size();
  row.median_try_ratio = n % 2 ? ratios[n / 2] : 0.5 * (ratios[n / 2 - 1] + ratios[n / 2]);
  return row;
}

std::vector<std::size_t> parse_counts(const std::string& text) {
  std::vector<std::size_t> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(static_cast<std::size_t>(std::stod(item)));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_pipeline INPUT [--samples N1,N2,...] [--repeat K] [--json FILE] [--uniform] "
                         "[--release-memory]\n");
    return 2;
  }
  const std::string input = argv[1];
  std::vector<std::size_t> counts{10000, 66686, 250000};
  std::string json_path;
  int repeat = 3;
  bool uniform = false, release = false;
  for (int i = 2; i < argc; ++i) {
    const std::string opt = argv[i];
    if (opt == "--uniform" || opt == "--release-memory") {
      (opt == "--uniform" ? uniform : release) = true;
      continue;
    }
    if (i + 1 >= argc) break;
    if (opt == "--samples") counts = parse_counts(argv[i + 1]);
    else if (opt == "--json") json_path = argv[i + 1];
    else if (opt == "--repeat") repeat = std::max(1, std::atoi(argv[i + 1]));
    ++i;
  }
  if (!release) keep_freed_memory();
  try {
    const std::vector<TopoDS_Solid> solids = extract_solids(read_shape_file(input));
    const TopoDS_Solid& solid = solids.front();
    // "reconstruction" runs on a second thread during "delaunay"; "total" is the wall-clock time of
    // the whole compute (stages plus checks and the output's canonical order).
    // "per try" is the median of total / bare within each try (Row::median_try_ratio).
    std::printf("| target | samples | spacing | setup | features | sampling | reconstruction | delaunay | selection | completion | inner | total | bare Delaunay | total / bare | per try | after sampling / bare | bare, middle policy | total / bare, middle | page faults, compute / bare |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    std::ostringstream json;
    json << "[";
    for (size_t k = 0; k < counts.size(); ++k) {
      SamplingParams sp;
      sp.target_samples = counts[k];
      const double h0 = plan_sampling(solid, sp).spacing;
      const Row r = run(solid, counts[k], h0, repeat, uniform);
      const Timings& t = r.timings;
      const double total = stage(t, "total");
      const double medial = total - stage(t, "setup") - stage(t, "features") - stage(t, "sampling");
      std::printf("| %zu | %zu | %.4g | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f | %.2f | %.2f | %.3f | %.2f | %ld / %ld |\n",
                  r.target, r.samples, r.spacing, stage(t, "setup"), stage(t, "features"), stage(t, "sampling"),
                  stage(t, "reconstruction"), stage(t, "delaunay"), stage(t, "selection"), stage(t, "completion"),
                  stage(t, "inner"), total, r.bare_delaunay, total / r.bare_delaunay, r.median_try_ratio,
                  medial / r.bare_delaunay, r.bare_middle, total / r.bare_middle, r.faults, r.bare_faults);
      std::fflush(stdout);
      json << (k ? ",\n " : "\n ") << "{\"target\": " << r.target << ", \"samples\": " << r.samples
           << ", \"spacing\": " << r.spacing << ", \"vertices\": " << r.vertices << ", \"faces\": " << r.faces;
      for (const auto& [n, s] : t) json << ", \"" << n << "\": " << s;
      json << ", \"bare_delaunay\": " << r.bare_delaunay << ", \"bare_delaunay_middle\": " << r.bare_middle
           << ", \"median_try_ratio\": " << r.median_try_ratio << ", \"page_faults\": " << r.faults
           << ", \"bare_page_faults\": " << r.bare_faults << "}";
    }
    json << "\n]\n";
    if (!json_path.empty()) std::ofstream(json_path) << json.str();
    std::printf("\npeak RSS %.0f MiB%s\n", peak_rss_mb(), release ? " (glibc's memory defaults)" : "");
  } catch (const Error& e) {
    std::fprintf(stderr, "bench_pipeline: %s\n", e.what());
    return 2;
  }
  return 0;
}
