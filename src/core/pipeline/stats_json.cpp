// The statistics of a run as JSON, written by hand: the schema is small and fixed, and a JSON
// library would be a dependency for one function.
#include <sys/resource.h>

#include <charconv>
#include <cmath>
#include <string>

#include "compute_medial_axis.h"

namespace cadmedial {
namespace {

// JSON has no NaN or infinity: write null rather than an invalid document.
std::string number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          static const char hex[] = "0123456789abcdef";
          out += "\\u00";
          out += hex[c >> 4];
          out += hex[c & 15];
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

}  // namespace

std::string stats_to_json(const ComputeStats& stats) {
  std::string j = "{\n";
  j += "  \"samples\": " + std::to_string(stats.samples) + ",\n";
  j += "  \"vertices\": " + std::to_string(stats.vertices) + ",\n";
  j += "  \"faces\": " + std::to_string(stats.faces) + ",\n";
  j += "  \"edges\": " + std::to_string(stats.edges) + ",\n";
  j += "  \"spacing\": " + number(stats.spacing) + ",\n";
  j += "  \"timings\": {";
  for (std::size_t i = 0; i < stats.timings.size(); ++i)
    j += (i ? ", " : "") + quoted(stats.timings[i].first) + ": " + number(stats.timings[i].second);
  j += "},\n";
  j += "  \"peak_rss_mb\": " + number(stats.peak_rss_mb) + ",\n";
  j += "  \"diagonal\": " + number(stats.diagonal) + ",\n";
  if (stats.snap) {
    const SnapStats& n = *stats.snap;
    j += "  \"snap\": {\"vertices\": " + std::to_string(n.vertices) + ", \"snapped\": " + std::to_string(n.snapped) +
         ", \"max_move\": " + number(n.max_move) + ", \"mean_move\": " + number(n.mean_move) + "},\n";
  }
  if (stats.simplify) {
    const SimplifyStats& c = *stats.simplify;
    j += "  \"simplify\": {\"tolerance\": " + number(c.tolerance) + ", \"max_error\": " + number(c.max_error) +
         ", \"max_containment\": " + number(c.max_containment) +
         ", \"vertices_before\": " + std::to_string(c.vertices_before) + ", \"faces_before\": " +
         std::to_string(c.faces_before) + ", \"edges_before\": " + std::to_string(c.edges_before) +
         ", \"vertices_after\": " + std::to_string(c.vertices_after) + ", \"faces_after\": " +
         std::to_string(c.faces_after) + ", \"edges_after\": " + std::to_string(c.edges_after) +
         ", \"euler_before\": " + std::to_string(c.euler_before) + ", \"euler_after\": " +
         std::to_string(c.euler_after) + ", \"components_before\": " + std::to_string(c.components_before) +
         ", \"components_after\": " + std::to_string(c.components_after) + ", \"seconds\": " + number(c.seconds) +
         "},\n";
  }
  j += "  \"warnings\": [";
  for (std::size_t i = 0; i < stats.warnings.size(); ++i) j += (i ? ", " : "") + quoted(stats.warnings[i]);
  j += "],\n";
  j += "  \"skipped\": [";
  for (std::size_t i = 0; i < stats.skipped.size(); ++i) j += (i ? ", " : "") + quoted(stats.skipped[i]);
  j += "],\n";
  j += "  \"solids\": [";
  for (std::size_t i = 0; i < stats.solids.size(); ++i) {
    const SolidStats& s = stats.solids[i];
    j += i ? ",\n    {" : "\n    {";
    j += "\"samples\": " + std::to_string(s.samples);
    j += ", \"vertices\": " + std::to_string(s.vertices);
    j += ", \"faces\": " + std::to_string(s.faces);
    j += ", \"convex_edges\": " + std::to_string(s.convex_edges);
    j += ", \"concave_edges\": " + std::to_string(s.concave_edges);
    j += ", \"smooth_edges\": " + std::to_string(s.smooth_edges);
    j += ", \"nonconcave_corners\": " + std::to_string(s.nonconcave_corners);
    j += ", \"dropped_faces\": " + std::to_string(s.dropped_faces);
    j += ", \"components\": " + std::to_string(s.components);
    j += ", \"specks\": " + std::to_string(s.specks);
    j += ", \"pieces\": " + std::to_string(s.pieces);
    j += std::string(", \"topology_right\": ") + (s.topology_right ? "true" : "false");
    j += ", \"filler_faces\": " + std::to_string(s.filler_faces);
    j += ", \"opened_pockets\": " + std::to_string(s.opened_pockets);
    j += ", \"edges\": " + std::to_string(s.edges);
    j += ", \"unattached_faces\": " + std::to_string(s.unattached_faces);
    j += ", \"euler_characteristic\": " + std::to_string(s.euler_characteristic);
    j += ", \"solid_euler_characteristic\": " + std::to_string(s.solid_euler_characteristic);
    j += ", \"spacing\": " + number(s.spacing);
    j += ", \"refinements\": " + std::to_string(s.refinements);
    j += ", \"exact_inside_tests\": " + std::to_string(s.exact_inside_tests);
    j += ", \"mirrored_samples\": " + std::to_string(s.mirrored_samples);
    j += ", \"welded_vertices\": " + std::to_string(s.welded_vertices);
    j += ", \"radius_max_excess\": " + number(s.radius_max_excess);
    j += ", \"radius_mean_excess\": " + number(s.radius_mean_excess);
    j += ", \"radii_corrected\": " + std::to_string(s.radii_corrected);
    j += ", \"vertices_moved_inside\": " + std::to_string(s.vertices_moved_inside);
    j += ", \"convex_edges_reached\": " + number(s.convex_edges_reached);
    j += ", \"short_convex_edges\": " + std::to_string(s.short_convex_edges);
    j += ", \"thinnest_wall\": " + number(s.thinnest_wall);
    // Where: null with the wall (none found).
    const bool found = std::isfinite(s.thinnest_wall);
    j += ", \"thinnest_wall_at\": ";
    j += found ? "[" + number(s.thinnest_wall_at[0]) + ", " + number(s.thinnest_wall_at[1]) + ", " +
                     number(s.thinnest_wall_at[2]) + "]"
               : "null";
    j += "}";
  }
  j += stats.solids.empty() ? "]\n" : "\n  ]\n";
  j += "}\n";
  return j;
}

double peak_rss_mb() {
  struct rusage usage {};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

}  // namespace cadmedial
