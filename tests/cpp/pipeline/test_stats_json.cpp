#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "core/pipeline/compute_medial_axis.h"
#include "io/io_test_files.h"

namespace cadmedial {
namespace {

ComputeStats sample_stats() {
  ComputeStats s;
  s.spacing = 0.125;
  s.samples = 1234;
  s.vertices = 567;
  s.faces = 89;
  s.edges = 5;
  s.timings = {{"features", 0.5}, {"sampling", 1.25}, {"delaunay", 2.0}, {"total", 3.75}};
  s.peak_rss_mb = 42.5;
  SolidStats a;
  a.samples = 1000;
  a.convex_edges = 12;
  a.edges = 4;
  SolidStats b;
  b.samples = 234;
  b.dropped_faces = 3;
  b.edges = 1;
  s.solids = {a, b};
  return s;
}

TEST(StatsToJson, HoldsTheFiguresAndTimingsInOrder) {
  const std::string j = stats_to_json(sample_stats());
  EXPECT_NE(j.find("\"samples\": 1234"), std::string::npos) << j;
  EXPECT_NE(j.find("\"spacing\": 0.125"), std::string::npos) << j;
  EXPECT_NE(j.find("\"timings\": {\"features\": 0.5, \"sampling\": 1.25, \"delaunay\": 2, \"total\": 3.75}"),
            std::string::npos)
      << j;
  EXPECT_NE(j.find("\"peak_rss_mb\": 42.5"), std::string::npos) << j;
  EXPECT_NE(j.find("\"convex_edges\": 12"), std::string::npos) << j;
  EXPECT_NE(j.find("\"dropped_faces\": 3"), std::string::npos) << j;
  // Top level: edges right after faces.
  EXPECT_NE(j.find("  \"faces\": 89,\n  \"edges\": 5,\n"), std::string::npos) << j;
  EXPECT_NE(j.find(", \"edges\": 4,"), std::string::npos) << j;
  EXPECT_NE(j.find(", \"edges\": 1,"), std::string::npos) << j;
}

// Parsed by Python's json module, the strictest parser at hand: the document is valid JSON even
// with a stage name that needs escaping and a NaN timing.
TEST(StatsToJson, IsValidJson) {
  if (std::system("/usr/bin/python3 -c 'import json' 2>/dev/null") != 0) GTEST_SKIP() << "no python3";
  test::TempDir dir;
  ComputeStats s = sample_stats();
  s.timings.push_back({"we\"ird\\stage\n", std::numeric_limits<double>::quiet_NaN()});
  s.warnings = {"walls down to 1 thick \"here\"", "second"};
  s.solids[0].thinnest_wall = 1.5;
  s.solids[0].thinnest_wall_at = {1, -2.5, 3};
  s.solids[1].thinnest_wall = std::numeric_limits<double>::infinity();  // none found: null
  test::write_file(dir.file("s.json"), stats_to_json(s));
  test::write_file(dir.file("empty.json"), stats_to_json(ComputeStats{}));
  const std::string check =
      "/usr/bin/python3 -c 'import json,sys\n"
      "d = json.load(open(sys.argv[1]))\n"
      "assert d[\"samples\"] == 1234 and len(d[\"solids\"]) == 2\n"
      "assert (d[\"faces\"], d[\"edges\"]) == (89, 5)\n"
      "assert [s[\"edges\"] for s in d[\"solids\"]] == [4, 1]\n"
      "assert all(\"bare_edges\" not in s for s in d[\"solids\"])\n"
      "assert list(d[\"timings\"])[:4] == [\"features\", \"sampling\", \"delaunay\", \"total\"]\n"
      "assert d[\"timings\"][\"we\\\"ird\\\\stage\\n\"] is None\n"
      "assert d[\"warnings\"] == [\"walls down to 1 thick \\\"here\\\"\", \"second\"]\n"
      "assert [s[\"thinnest_wall\"] for s in d[\"solids\"]] == [1.5, None]\n"
      "assert [s[\"thinnest_wall_at\"] for s in d[\"solids\"]] == [[1, -2.5, 3], None]\n"
      "json.load(open(sys.argv[2]))' " +
      dir.file("s.json") + " " + dir.file("empty.json");
  EXPECT_EQ(std::system(check.c_str()), 0) << test::read_file(dir.file("s.json"));
}

TEST(PeakRss, IsPositiveAndGrowsWithUse) {
  const double before = peak_rss_mb();
  EXPECT_GT(before, 1.0);
  // A touched block larger than the peak so far must raise the peak past it.
  std::vector<char> block(static_cast<std::size_t>((before + 64.0) * (1 << 20)), 1);
  volatile char sink = block[block.size() / 2];
  (void)sink;
  EXPECT_GE(peak_rss_mb(), before + 32.0);
}

}  // namespace
}  // namespace cadmedial
