// `cadmedial compute`: everything that can be refused is refused before the long computation.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>

#include "commands.h"
#include "core/errors.h"
#include "core/io/read_shape.h"
#include "core/io/write_medial_mesh.h"
#include "core/pipeline/compute_medial_axis.h"
#include "output_files.h"
#include "progress_printer.h"

namespace cadmedial::cli {

int run_compute(const Args& args) {
  const auto start = std::chrono::steady_clock::now();
  check_params(args.params);
  check_mesh_extension(args.output);
  check_writable(args.output);
  if (!args.stats.empty()) check_writable(args.stats);

  // The engine extracts and checks the solids itself (once: on NIST CTC 02 a second extraction
  // here, its signed volume, took 0.17 s).
  const TopoDS_Shape shape = read_shape_file(args.input);  // its messages already name the file
  ProgressPrinter printer(args.quiet);
  ComputeResult result;
  try {
    result = compute_medial_axis(shape, args.params, std::ref(printer));
  } catch (const InvalidInput& e) {
    throw InvalidInput(args.input + ": " + e.what());
  } catch (const GeometryError& e) {
    throw GeometryError(args.input + ": " + e.what());
  }

  for (const std::string& what : result.stats.skipped)
    std::fprintf(stderr, "cadmedial: warning: %s: skipped %s\n", args.input.c_str(), what.c_str());
  write_medial_mesh(result.mesh, args.output);
  if (!args.stats.empty()) write_text_atomically(args.stats, stats_to_json(result.stats));

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream summary;
  summary.precision(4);
  const std::size_t solids = result.stats.solids.size();
  summary << "cadmedial: " << solids << (solids == 1 ? " solid, " : " solids, ")
          << result.stats.samples << " samples (spacing " << result.stats.spacing;
  // The finest spacing a solid was sampled again at, for its axis's topology (--refine).
  double refined = 0;
  for (const SolidStats& s : result.stats.solids)
    if (s.refinements > 0 && (refined == 0 || s.spacing < refined)) refined = s.spacing;
  if (refined > 0) summary << ", refined to " << refined << " for the axis's topology";
  summary << "), medial mesh of " << result.mesh.num_vertices() << " vertices";
  // Edges only when there are some: most parts have none, and the line stays as it was for them.
  if (result.mesh.num_edges() > 0)
    summary << ", " << result.mesh.num_faces() << " faces and " << result.mesh.num_edges()
            << (result.mesh.num_edges() == 1 ? " edge" : " edges");
  else
    summary << " and " << result.mesh.num_faces() << " faces";
  if (const auto& c = result.stats.simplify)
    summary << " (compact: from " << c->vertices_before << " vertices and " << c->faces_before
            << " faces, every ball within " << std::max(c->max_error, c->max_containment)
            << " of the other mesh's, tolerance " << c->tolerance << ")";
  summary << " in " << seconds << " s; wrote " << args.output;
  if (!args.stats.empty()) summary << " and " << args.stats;
  summary << ".\n";
  std::fputs(summary.str().c_str(), stdout);
  for (const std::string& w : result.stats.warnings) std::fprintf(stderr, "cadmedial: warning: %s\n", w.c_str());
  return 0;
}

}  // namespace cadmedial::cli
