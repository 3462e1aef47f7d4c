// The cadmedial program as other tools see it: exit status, one error line on stderr, and no
// output file after a refusal.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>

#include "core/io/write_medial_mesh.h"
#include "io/io_test_files.h"
#include "support/engine_run.h"

namespace cadmedial {
namespace {

using test::TempDir;

struct CliRun {
  int status = -1;
  std::string out, err;
};

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

CliRun run(const TempDir& dir, const std::vector<std::string>& args) {
  std::string cmd = quote(CADMEDIAL_CLI);
  for (const std::string& a : args) cmd += " " + quote(a);
  const std::string out = dir.file(".stdout"), err = dir.file(".stderr");
  cmd += " >" + quote(out) + " 2>" + quote(err) + " </dev/null";
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = test::read_file(out);
  r.err = test::read_file(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// Inputs, made fresh in each test's directory.
std::string box_brep(const TempDir& dir) {
  const std::string path = dir.file("box.brep");
  BRepTools::Write(BRepPrimAPI_MakeBox(1, 1, 1).Shape(), path.c_str());
  return path;
}

std::string open_shell_brep(const TempDir& dir) {
  BRep_Builder b;
  TopoDS_Shell shell;
  b.MakeShell(shell);
  int i = 0;
  for (TopExp_Explorer fx(BRepPrimAPI_MakeBox(1, 1, 1).Shape(), TopAbs_FACE); fx.More(); fx.Next(), ++i)
    if (i != 4) b.Add(shell, fx.Current());
  const std::string path = dir.file("open.brep");
  BRepTools::Write(shell, path.c_str());
  return path;
}

// A refusal: status 2, exactly one stderr line "cadmedial: error: ...<fragment>...", nothing on
// stdout, and no file in the directory but the inputs (no output, no temporary file).
void expect_refusal(const std::vector<std::string>& args, const std::string& fragment,
                    const std::function<void(const TempDir&)>& prepare = {}) {
  TempDir dir;
  box_brep(dir);
  if (prepare) prepare(dir);
  const std::vector<std::string> before = dir.entries();
  std::vector<std::string> full;
  for (std::string a : args) {
    // "@/x" names a file in the test directory.
    if (a.rfind("@/", 0) == 0) a = dir.file(a.substr(2));
    full.push_back(a);
  }
  const CliRun r = run(dir, full);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("cadmedial: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << "stderr: " << r.err << "expected: " << fragment;
  EXPECT_EQ(r.out, "");
  std::vector<std::string> after = dir.entries(), expected = before;
  std::sort(after.begin(), after.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(after, expected);
}

const std::vector<std::string> kCompute{"compute", "@/box.brep", "-o", "@/out.ply"};

std::vector<std::string> with(std::vector<std::string> extra) {
  std::vector<std::string> a = kCompute;
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

TEST(CliRefusal, MissingInput) { expect_refusal({"compute", "@/none.step", "-o", "@/out.ply"}, "none.step: no such file"); }

TEST(CliRefusal, EmptyFile) {
  expect_refusal({"compute", "@/empty.step", "-o", "@/out.ply"}, "empty.step: the file is empty",
                 [](const TempDir& d) { test::write_file(d.file("empty.step"), ""); });
}

TEST(CliRefusal, GarbageStep) {
  expect_refusal({"compute", "@/junk.step", "-o", "@/out.ply"}, "junk.step: not a readable STEP file",
                 [](const TempDir& d) { test::write_file(d.file("junk.step"), "garbage\nmore garbage;\n"); });
}

TEST(CliRefusal, GarbageBrep) {
  expect_refusal({"compute", "@/junk.brep", "-o", "@/out.ply"}, "junk.brep: not a BREP file",
                 [](const TempDir& d) { test::write_file(d.file("junk.brep"), "garbage\n"); });
}

TEST(CliRefusal, OpenShell) {
  expect_refusal({"compute", "@/open.brep", "-o", "@/out.ply"}, "is bounded by 1 face (the shell is open)",
                 [](const TempDir& d) { open_shell_brep(d); });
}

TEST(CliRefusal, UnknownOutputExtension) {
  expect_refusal({"compute", "@/box.brep", "-o", "@/out.stl"}, "unknown output type '.stl'");
}

TEST(CliRefusal, UnwritableOutputDirectory) {
  expect_refusal({"compute", "@/box.brep", "-o", "@/no/such/dir/out.ply"}, "does not exist");
}

TEST(CliRefusal, OutputIsADirectory) {
  expect_refusal({"compute", "@/box.brep", "-o", "@/sub.ply"}, "is a directory",
                 [](const TempDir& d) { std::filesystem::create_directory(d.file("sub.ply")); });
}

TEST(CliRefusal, StatsInMissingDirectory) {
  expect_refusal(with({"--stats", "@/no/dir/s.json"}), "does not exist");
}

TEST(CliRefusal, SpacingZero) { expect_refusal(with({"--spacing", "0"}), "--spacing must be > 0"); }
TEST(CliRefusal, SpacingNegative) { expect_refusal(with({"--spacing", "-1"}), "--spacing must be > 0"); }
TEST(CliRefusal, SpacingNaN) { expect_refusal(with({"--spacing", "nan"}), "--spacing: 'nan' is not a finite number"); }
TEST(CliRefusal, SpacingInf) { expect_refusal(with({"--spacing", "inf"}), "not a finite number"); }
TEST(CliRefusal, SpacingNotANumber) { expect_refusal(with({"--spacing", "abc"}), "--spacing: 'abc' is not a number"); }
TEST(CliRefusal, SpacingTrailingJunk) { expect_refusal(with({"--spacing", "0.5mm"}), "'0.5mm' is not a number"); }
TEST(CliRefusal, SpacingMissingValue) { expect_refusal(with({"--spacing"}), "--spacing: missing value"); }
TEST(CliRefusal, SamplesZero) { expect_refusal(with({"--samples", "0"}), "--samples must be > 0"); }
TEST(CliRefusal, SamplesFractional) { expect_refusal(with({"--samples", "2.5"}), "whole number"); }
TEST(CliRefusal, SpacingAndSamples) {
  expect_refusal(with({"--spacing", "0.1", "--samples", "100"}), "--spacing or --samples, not both");
}
TEST(CliRefusal, ThetaZero) { expect_refusal(with({"--theta", "0"}), "--theta must be in (0, 90)"); }
TEST(CliRefusal, ThetaNinety) { expect_refusal(with({"--theta", "90"}), "--theta must be in (0, 90)"); }
TEST(CliRefusal, ThetaHundred) { expect_refusal(with({"--theta", "100"}), "--theta must be in (0, 90)"); }
TEST(CliRefusal, RhoZero) { expect_refusal(with({"--rho", "0"}), "--rho must be > 0"); }
TEST(CliRefusal, RhoNegative) { expect_refusal(with({"--rho", "-3"}), "--rho must be > 0"); }
TEST(CliRefusal, UnknownOption) { expect_refusal(with({"--frobnicate"}), "unknown option '--frobnicate'"); }
TEST(CliRefusal, MissingOutput) { expect_refusal({"compute", "@/box.brep"}, "missing -o OUTPUT"); }
TEST(CliRefusal, UnknownCommand) { expect_refusal({"explode", "@/box.brep"}, "unknown command 'explode'"); }
TEST(CliRefusal, NoArguments) { expect_refusal({}, "no command given"); }

TEST(Cli, HelpAndVersionSucceed) {
  TempDir dir;
  const CliRun help = run(dir, {"--help"});
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("cadmedial compute INPUT -o OUTPUT"), std::string::npos) << help.out;
  const CliRun version = run(dir, {"--version"});
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out.rfind("cadmedial 0.1.0", 0), 0u) << version.out;
}

TEST(Cli, InfoDescribesTheSolid) {
  TempDir dir;
  const CliRun r = run(dir, {"info", box_brep(dir), "--samples", "600"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("1 solid"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("faces 6, edges 12, vertices 8, volume 1,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("box [0, 0, 0] .. [1, 1, 1], Euler characteristic 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sampling plan: spacing"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("finer for a solid"), std::string::npos) << r.out;  // a chosen density is kept
  const CliRun by_default = run(dir, {"info", box_brep(dir)});
  EXPECT_NE(by_default.out.find("samples, finer for a solid whose axis comes out with another topology"),
            std::string::npos)
      << by_default.out;
}

// The medial axis of the unit cube lies inside the cube; no point of it is farther than 1/2 from the
// boundary (up to the sample spacing, since radii are distances to samples), its centre is at 1/2,
// and it reaches the convex edges, where the radius is 0.
TEST(Cli, ComputeWritesAMeshInsideTheCubeAndValidStats) {
  TempDir dir;
  const std::string input = box_brep(dir), output = dir.file("cube.ply"), stats = dir.file("cube.json");
  const CliRun r = run(dir, {"compute", input, "-o", output, "--samples", "1500", "--stats", stats, "--quiet"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");  // --quiet
  EXPECT_NE(r.out.find("wrote " + output), std::string::npos) << r.out;
  const MedialMesh m = read_medial_mesh(output);
  ASSERT_GT(m.num_faces(), 0u);
  const double slack = 0.1;  // > spacing: sqrt(6 / 1500) ~ 0.063
  double max_radius = 0.0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    int on_faces = 0;  // coordinates at 0 or 1: two or more for a point on an edge of the cube
    for (double c : m.vertices[v]) {
      EXPECT_GE(c, -slack);
      EXPECT_LE(c, 1.0 + slack);
      on_faces += std::abs(c) < 1e-9 || std::abs(c - 1.0) < 1e-9;
    }
    EXPECT_GE(m.radius[v], 0.0);
    EXPECT_LE(m.radius[v], 0.5 + slack);
    if (m.radius[v] == 0.0) EXPECT_GE(on_faces, 2) << "radius 0 off the cube's edges at vertex " << v;
    max_radius = std::max(max_radius, m.radius[v]);
  }
  EXPECT_GT(max_radius, 0.5 - slack);
  const std::string json = test::read_file(stats);
  EXPECT_EQ(json.rfind("{", 0), 0u);
  EXPECT_NE(json.find("\"timings\""), std::string::npos);
  std::vector<std::string> names = dir.entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"box.brep", "cube.json", "cube.ply"}));
}

// A file with a solid and a loose construction face (as NIST CTC 02 and 04 have): the solid is
// computed, the face left out, and both the warning and the stats say so. Nothing of the axis
// comes from the face (it lies at z = 10, far above the unit cube).
TEST(Cli, ComputeSkipsALooseFaceBesideTheSolidAndSaysSo) {
  TempDir dir;
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, BRepPrimAPI_MakeBox(1, 1, 1).Shape());
  b.Add(c, BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 10), gp_Dir(0, 0, 1)), 0, 1, 0, 1).Face());
  const std::string input = dir.file("with_face.brep"), output = dir.file("out.ply"), stats = dir.file("out.json");
  BRepTools::Write(c, input.c_str());
  const CliRun r = run(dir, {"compute", input, "-o", output, "--samples", "1500", "--stats", stats, "--quiet"});
  ASSERT_EQ(r.status, 0) << r.err;
  // One line: the warning, naming the file.
  EXPECT_EQ(r.err.rfind("cadmedial: warning: " + input + ": skipped 1 loose face", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.out.find("cadmedial: 1 solid, "), std::string::npos) << r.out;
  const std::string json = test::read_file(stats);
  EXPECT_NE(json.find("\"skipped\": [\"1 loose face"), std::string::npos) << json;
  const MedialMesh m = read_medial_mesh(output);
  ASSERT_GT(m.num_faces(), 0u);
  for (const Point3& v : m.vertices) EXPECT_LE(v[2], 1.0 + 1e-9);
}

// The summary line counts what the file holds; edges are named only when there are some.
TEST(Cli, SummaryCountsTheEdgesOfTheOutputWhenThereAreAny) {
  TempDir dir;
  const std::string torus = dir.file("torus.brep");
  BRepTools::Write(BRepPrimAPI_MakeTorus(10, 3).Shape(), torus.c_str());
  for (const std::string& input : {torus, box_brep(dir)}) {
    const std::string output = dir.file("out.ply");
    const CliRun r = run(dir, {"compute", input, "-o", output, "--samples", "1500", "--quiet"});
    ASSERT_EQ(r.status, 0) << r.err;
    const MedialMesh m = read_medial_mesh(output);
    const std::string counts = "medial mesh of " + std::to_string(m.num_vertices()) + " vertices";
    const std::string expected =
        m.num_edges() == 0
            ? counts + " and " + std::to_string(m.num_faces()) + " faces in "
            : counts + ", " + std::to_string(m.num_faces()) + " faces and " + std::to_string(m.num_edges()) +
                  (m.num_edges() == 1 ? " edge in " : " edges in ");
    EXPECT_NE(r.out.find(expected), std::string::npos) << "expected: " << expected << "\nout: " << r.out;
    // The torus's core circle is where the axis is a curve: without an edge there, this test
    // would not see the summary's edge count.
    if (input == torus) EXPECT_GT(m.num_edges(), 0u) << "the torus's medial mesh has no 1-D edge";
    else EXPECT_EQ(m.num_edges(), 0u) << "a box's medial axis is all faces";
  }
}

// A plate 1 thick at spacing 1 with --uniform (no refinement of thin walls): the result is
// written, and one warning line says the walls are too thin for the spacing (also under --quiet,
// which silences only progress). Without --uniform the plate is sampled finer and nothing is said.
TEST(Cli, WarnsOfWallsThinnerThanTwoSpacings) {
  TempDir dir;
  const std::string plate = dir.file("plate.brep");
  BRepTools::Write(BRepPrimAPI_MakeBox(30, 30, 1).Shape(), plate.c_str());
  const CliRun r =
      run(dir, {"compute", plate, "-o", dir.file("plate.ply"), "--spacing", "1", "--quiet", "--uniform"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.rfind("cadmedial: warning: walls down to 1", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.out.find("wrote "), std::string::npos) << r.out;
  const CliRun adapted = run(dir, {"compute", plate, "-o", dir.file("plate2.ply"), "--spacing", "1", "--quiet"});
  ASSERT_EQ(adapted.status, 0) << adapted.err;
  EXPECT_EQ(adapted.err, "");
}

// --min-feature 2 on the plate 1 thick: it is not sampled finer (about as many samples as
// --uniform takes; refined, it takes 5.6 times as many), and the warning names the minimum given.
TEST(Cli, NamesWallsBelowTheMinimumFeatureSize) {
  TempDir dir;
  const std::string plate = dir.file("plate.brep");
  BRepTools::Write(BRepPrimAPI_MakeBox(30, 30, 1).Shape(), plate.c_str());
  const CliRun r = run(dir, {"compute", plate, "-o", dir.file("plate.ply"), "--spacing", "1", "--quiet",
                             "--min-feature", "2", "--stats", dir.file("limited.json")});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("thinner than the minimum feature size given (2)"), std::string::npos) << r.err;
  const CliRun uniform = run(dir, {"compute", plate, "-o", dir.file("uniform.ply"), "--spacing", "1", "--quiet",
                                   "--uniform", "--stats", dir.file("uniform.json")});
  ASSERT_EQ(uniform.status, 0) << uniform.err;
  auto samples_in = [](const std::string& path) {
    std::ifstream in(path);
    const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = json.find("\"samples\": ");
    return at == std::string::npos ? -1L : std::strtol(json.c_str() + at + 11, nullptr, 10);
  };
  EXPECT_GT(samples_in(dir.file("limited.json")), 0);
  // (Not one for one: the thin plate's faces are sampled in mirrored pairs without --uniform.)
  EXPECT_LT(samples_in(dir.file("limited.json")), 1.05 * samples_in(dir.file("uniform.json")));
}

TEST(CliRefusal, MinFeatureNegative) { expect_refusal(with({"--min-feature", "-1"}), "--min-feature must be > 0"); }

// The stats' figure `key` of the first solid (a number), or NaN.
double first_solid_figure(const std::string& json, const std::string& key) {
  const std::size_t solids = json.find("\"solids\"");
  const std::size_t at = json.find("\"" + key + "\": ", solids);
  if (solids == std::string::npos || at == std::string::npos) return std::nan("");
  return std::strtod(json.c_str() + at + key.size() + 4, nullptr);
}

// A box 40 x 30 x 20 hollowed to walls 1 thick, at spacing 2 with --uniform: the sheets inside
// the walls break apart (Euler 0, the solid's 1). The program says so; with --refine it samples
// the cup again, finer, and the axis is right: the summary gives the finer spacing, the stats
// the refinement, and no warning of the topology is left.
TEST(Cli, RefineSamplesASolidFinerWhereItsAxisHasTheWrongTopology) {
  TempDir dir;
  const std::string cup = dir.file("cup.brep");
  const TopoDS_Shape hollowed = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(40, 30, 20).Shape(),
                                                BRepPrimAPI_MakeBox(gp_Pnt(1, 1, 1), gp_Pnt(39, 29, 20)).Shape())
                                    .Shape();
  BRepTools::Write(hollowed, cup.c_str());
  const std::vector<std::string> base{"compute", cup, "-o", dir.file("cup.ply"), "--spacing", "2", "--uniform",
                                      "--quiet", "--stats", dir.file("cup.json")};
  const CliRun once = run(dir, base);
  ASSERT_EQ(once.status, 0) << once.err;
  EXPECT_NE(once.err.find("cadmedial: warning: the medial axis's Euler characteristic is 0 where the solid's is 1"),
            std::string::npos)
      << once.err;
  EXPECT_EQ(once.out.find("refined to"), std::string::npos) << once.out;
  EXPECT_EQ(first_solid_figure(test::read_file(dir.file("cup.json")), "refinements"), 0);

  std::vector<std::string> refine = base;
  refine.push_back("--refine");
  const CliRun refined = run(dir, refine);
  ASSERT_EQ(refined.status, 0) << refined.err;
  EXPECT_NE(refined.out.find("(spacing 2, refined to 1.265 for the axis's topology)"), std::string::npos)
      << refined.out;
  EXPECT_EQ(refined.err.find("medial axis"), std::string::npos) << refined.err;
  const std::string json = test::read_file(dir.file("cup.json"));
  EXPECT_EQ(first_solid_figure(json, "refinements"), 1) << json;
  EXPECT_EQ(first_solid_figure(json, "euler_characteristic"), 1) << json;
  EXPECT_EQ(first_solid_figure(json, "solid_euler_characteristic"), 1) << json;
}

// Without --spacing or --samples the density is only where the sampling starts: axom's
// boxed_sphere (a box with a spherical void, and the ball in it) has holes in its box's sheets at
// the default 20,000 samples, and is sampled finer; asked for 20,000 samples, it is not.
TEST(Cli, TheDefaultDensityIsRefinedWhereTheAxisIsWrongAChosenOneIsNot) {
  const std::string part = test::model_path("axom/boxed_sphere.step");
  if (part.empty()) GTEST_SKIP() << "../shared/data/models is not beside the repository";
  TempDir dir;
  const std::string stats = dir.file("s.json");
  const CliRun chosen = run(dir, {"compute", part, "-o", dir.file("a.ply"), "--samples", "20000", "--quiet",
                                  "--stats", stats});
  ASSERT_EQ(chosen.status, 0) << chosen.err;
  EXPECT_EQ(first_solid_figure(test::read_file(stats), "refinements"), 0);
  EXPECT_NE(chosen.err.find("solid 1: the medial axis's Euler characteristic is"), std::string::npos) << chosen.err;
  const CliRun by_default = run(dir, {"compute", part, "-o", dir.file("b.ply"), "--quiet", "--stats", stats});
  ASSERT_EQ(by_default.status, 0) << by_default.err;
  const std::string json = test::read_file(stats);
  EXPECT_GE(first_solid_figure(json, "refinements"), 1) << json;
  EXPECT_EQ(first_solid_figure(json, "euler_characteristic"), first_solid_figure(json, "solid_euler_characteristic"))
      << json;
  EXPECT_EQ(by_default.err.find("medial axis"), std::string::npos) << by_default.err;
}

TEST(Cli, ProgressIsALinePerStageChangeNotAFlood) {
  TempDir dir;
  const CliRun r = run(dir, {"compute", box_brep(dir), "-o", dir.file("c.obj"), "--samples", "1500"});
  ASSERT_EQ(r.status, 0) << r.err;
  const long lines = std::count(r.err.begin(), r.err.end(), '\n');
  EXPECT_GE(lines, 1) << r.err;
  EXPECT_LE(lines, 100) << r.err;
  EXPECT_EQ(r.err.rfind("[", 0), 0u) << r.err;
}

}  // namespace
}  // namespace cadmedial
