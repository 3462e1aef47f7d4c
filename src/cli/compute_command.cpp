// `cadmedial compute`: everything that can be refused is refused before the long computation.
#include <chrono>
#include <cstdio>
#include <sstream>

#include "commands.h"
#include "core/errors.h"
#include "core/io/write_medial_mesh.h"
#include "core/pipeline/compute_medial_axis.h"
#include "load_solids.h"
#include "output_files.h"
#include "progress_printer.h"

namespace cadmedial::cli {

int run_compute(const Args& args) {
  const auto start = std::chrono::steady_clock::now();
  check_params(args.params);
  check_mesh_extension(args.output);
  check_writable(args.output);
  if (!args.stats.empty()) check_writable(args.stats);

  const LoadedSolids loaded = load_solids(args.input, false);
  ProgressPrinter printer(args.quiet);
  ComputeResult result;
  try {
    result = compute_medial_axis(loaded.compound, args.params, std::ref(printer));
  } catch (const InvalidInput& e) {
    throw InvalidInput(args.input + ": " + e.what());
  } catch (const GeometryError& e) {
    throw GeometryError(args.input + ": " + e.what());
  }

  write_medial_mesh(result.mesh, args.output);
  if (!args.stats.empty()) write_text_atomically(args.stats, stats_to_json(result.stats));

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream summary;
  summary.precision(4);
  summary << "cadmedial: " << loaded.solids.size() << (loaded.solids.size() == 1 ? " solid, " : " solids, ")
          << result.stats.samples << " samples (spacing " << result.stats.spacing << "), medial mesh of "
          << result.mesh.num_vertices() << " vertices";
  // Edges only when there are some: most parts have none, and the line stays as it was for them.
  if (result.mesh.num_edges() > 0)
    summary << ", " << result.mesh.num_faces() << " faces and " << result.mesh.num_edges()
            << (result.mesh.num_edges() == 1 ? " edge" : " edges");
  else
    summary << " and " << result.mesh.num_faces() << " faces";
  summary << " in " << seconds << " s; wrote " << args.output;
  if (!args.stats.empty()) summary << " and " << args.stats;
  summary << ".\n";
  std::fputs(summary.str().c_str(), stdout);
  for (const std::string& w : result.stats.warnings) std::fprintf(stderr, "cadmedial: warning: %s\n", w.c_str());
  return 0;
}

}  // namespace cadmedial::cli
