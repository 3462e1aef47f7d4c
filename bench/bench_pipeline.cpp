// Speed of the pipeline per stage beside CGAL's bare Delaunay triangulation of the same samples,
// in the same run (the machine is shared and noisy: only ratios within one run mean much).
//
//   bench_pipeline INPUT [--samples N1,N2,...] [--json FILE]
//
// For each target count the spacing is calibrated by sampling until the count is within 3 %.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>


#include "core/errors.h"
#include "core/features/classify_features.h"
#include "core/io/read_shape.h"
#include "core/medial/medial_axis.h"
#include "core/medial/reconstruct_faces.h"
#include "core/pipeline/compute_medial_axis.h"
#include "core/pipeline/exact_inside_test.h"
#include "core/sampling/sample_solid.h"

using namespace cadmedial;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Row {
  std::size_t target = 0, samples = 0, vertices = 0, faces = 0;
  double spacing = 0, features = 0, sampling = 0, reconstruction = 0, bare_delaunay = 0, total = 0;
  Timings medial;
};

double stage(const Timings& t, const std::string& name) {
  for (const auto& [n, s] : t)
    if (n == name) return s;
  return 0;
}

Row run(const TopoDS_Solid& solid, std::size_t target, double spacing0) {
  Row row;
  row.target = target;
  auto t0 = Clock::now();
  const Features features = classify_features(solid);
  row.features = since(t0);
  // Calibrate the spacing on the sample count (not timed: a user gives the spacing directly).
  double h = spacing0;
  Samples samples;
  for (int pass = 0; pass < 6; ++pass) {
    samples = sample_solid(solid, features, h);
    const double miss = static_cast<double>(samples.size()) / static_cast<double>(target);
    if (std::abs(miss - 1.0) < 0.03) break;
    h *= std::sqrt(miss);
  }
  t0 = Clock::now();
  samples = sample_solid(solid, features, h);
  row.sampling = since(t0);
  row.spacing = h;
  row.samples = samples.size();
  t0 = Clock::now();
  const Umbrellas umbrellas = reconstruct_faces(samples);
  row.reconstruction = since(t0);
  const InsideTest inside = exact_inside_test(solid, 1e-7);
  MedialAxisStats ms;
  const MedialMesh mesh = medial_axis(samples, umbrellas, MedialParams{}, inside, 0, &ms);
  row.medial = ms.timings;
  row.vertices = mesh.num_vertices();
  row.faces = mesh.num_faces();
  row.bare_delaunay = bare_delaunay_seconds(samples.points);
  row.total = row.features + row.sampling + row.reconstruction;
  for (const auto& [n, s] : row.medial) row.total += s;
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
    std::fprintf(stderr, "usage: bench_pipeline INPUT [--samples N1,N2,...] [--json FILE]\n");
    return 2;
  }
  const std::string input = argv[1];
  std::vector<std::size_t> counts{10000, 66686, 250000};
  std::string json_path;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string opt = argv[i];
    if (opt == "--samples") counts = parse_counts(argv[i + 1]);
    else if (opt == "--json") json_path = argv[i + 1];
  }
  try {
    const std::vector<TopoDS_Solid> solids = extract_solids(read_shape_file(input));
    const TopoDS_Solid& solid = solids.front();
    std::printf("| target | samples | spacing | features | sampling | reconstruction | delaunay | selection | completion | inner | total | bare Delaunay | total / bare | medial stages / bare |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    std::ostringstream json;
    json << "[";
    for (size_t k = 0; k < counts.size(); ++k) {
      SamplingParams sp;
      sp.target_samples = counts[k];
      const double h0 = plan_sampling(solid, sp).spacing;
      const Row r = run(solid, counts[k], h0);
      double medial = 0;
      for (const auto& [n, s] : r.medial) medial += s;
      std::printf("| %zu | %zu | %.4g | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f | %.2f |\n",
                  r.target, r.samples, r.spacing, r.features, r.sampling, r.reconstruction, stage(r.medial, "delaunay"),
                  stage(r.medial, "selection"), stage(r.medial, "completion"), stage(r.medial, "inner"), r.total,
                  r.bare_delaunay, r.total / r.bare_delaunay, (medial + r.reconstruction) / r.bare_delaunay);
      std::fflush(stdout);
      json << (k ? ",\n " : "\n ") << "{\"target\": " << r.target << ", \"samples\": " << r.samples
           << ", \"spacing\": " << r.spacing << ", \"vertices\": " << r.vertices << ", \"faces\": " << r.faces
           << ", \"features\": " << r.features << ", \"sampling\": " << r.sampling
           << ", \"reconstruction\": " << r.reconstruction;
      for (const auto& [n, s] : r.medial) json << ", \"" << n << "\": " << s;
      json << ", \"total\": " << r.total << ", \"bare_delaunay\": " << r.bare_delaunay << "}";
    }
    json << "\n]\n";
    if (!json_path.empty()) std::ofstream(json_path) << json.str();
    std::printf("\npeak RSS %.0f MiB\n", peak_rss_mb());
  } catch (const Error& e) {
    std::fprintf(stderr, "bench_pipeline: %s\n", e.what());
    return 2;
  }
  return 0;
}
