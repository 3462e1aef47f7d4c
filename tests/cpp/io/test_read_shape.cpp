#include "core/io/read_shape.h"

#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <gp_Pln.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <gp_Vec2d.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>

#include <sstream>

#include "core/errors.h"
#include "core/pipeline/compute_medial_axis.h"
#include "io/io_test_files.h"
#include "support/broken_solids.h"
#include "support/solids.h"

namespace cadmedial {
namespace {

using test::TempDir;

double volume(const TopoDS_Shape& s) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(s, props);
  return props.Mass();
}

TopoDS_Shape box(double x = 1, double y = 2, double z = 3) { return BRepPrimAPI_MakeBox(x, y, z).Shape(); }

TopoDS_Shell box_shell() { return TopoDS::Shell(TopExp_Explorer(box(), TopAbs_SHELL).Current()); }

// The faces of a box put into a new shell, all but `skip` of them (-1: all).
TopoDS_Shell shell_of_box_faces(int skip = -1) {
  BRep_Builder b;
  TopoDS_Shell shell;
  b.MakeShell(shell);
  int i = 0;
  for (TopExp_Explorer fx(box(), TopAbs_FACE); fx.More(); fx.Next(), ++i)
    if (i != skip) b.Add(shell, fx.Current());
  return shell;
}

std::string brep_file(const TempDir& dir, const TopoDS_Shape& shape, const std::string& name = "s.brep") {
  const std::string path = dir.file(name);
  EXPECT_TRUE(BRepTools::Write(shape, path.c_str()));
  return path;
}

std::string step_file(const TempDir& dir, const TopoDS_Shape& shape, const std::string& name = "s.step") {
  const std::string path = dir.file(name);
  STEPControl_Writer writer;
  EXPECT_EQ(writer.Transfer(shape, STEPControl_AsIs), IFSelect_RetDone);
  EXPECT_EQ(writer.Write(path.c_str()), IFSelect_RetDone);
  return path;
}

// The message of the InvalidInput that f throws ("" and a test failure when it throws nothing).
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected InvalidInput";
  return "";
}

#define EXPECT_CONTAINS(text, fragment) EXPECT_NE(std::string(text).find(fragment), std::string::npos) << text

TEST(ReadShapeFile, BoxBrepGivesOneSolidOfItsVolume) {
  TempDir dir;
  const auto solids = extract_solids(read_shape_file(brep_file(dir, box())));
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-9);
}

TEST(ReadShapeFile, BoxStepGivesOneSolidOfItsVolume) {
  TempDir dir;
  const auto solids = extract_solids(read_shape_file(step_file(dir, box())));
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-6);
}

TEST(ReadShapeFile, ExtensionIsCaseInsensitive) {
  TempDir dir;
  EXPECT_EQ(extract_solids(read_shape_file(step_file(dir, box(), "PART.STP"))).size(), 1u);
  EXPECT_EQ(extract_solids(read_shape_file(brep_file(dir, box(), "PART.Brp"))).size(), 1u);
}

TEST(ReadShapeFile, IgesOfFacesIsSewnIntoASolid) {
  TempDir dir;
  const std::string path = dir.file("box.igs");
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 0);  // mode 0: faces (trimmed surfaces), no solid entity
  ASSERT_TRUE(writer.AddShape(box(2, 2, 2)));
  writer.ComputeModel();
  ASSERT_TRUE(writer.Write(path.c_str()));
  const auto solids = extract_solids(read_shape_file(path));
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 8.0, 1e-4);
}

TEST(ReadShapeFile, MissingFileIsRefused) {
  TempDir dir;
  EXPECT_CONTAINS(refusal([&] { read_shape_file(dir.file("nope.step")); }), "nope.step: no such file");
}

TEST(ReadShapeFile, EmptyFileIsRefused) {
  TempDir dir;
  test::write_file(dir.file("empty.step"), "");
  EXPECT_CONTAINS(refusal([&] { read_shape_file(dir.file("empty.step")); }), "empty.step: the file is empty");
}

TEST(ReadShapeFile, UnknownExtensionIsRefused) {
  TempDir dir;
  test::write_file(dir.file("part.txt"), "hello");
  EXPECT_CONTAINS(refusal([&] { read_shape_file(dir.file("part.txt")); }), "unknown file type '.txt'");
}

TEST(ReadShapeFile, GarbageStepIsRefused) {
  TempDir dir;
  test::write_file(dir.file("junk.step"), "this is not STEP\n\x01\x02 at all\n");
  EXPECT_CONTAINS(refusal([&] { read_shape_file(dir.file("junk.step")); }), "junk.step: ");
}

TEST(ReadShapeFile, GarbageBrepIsRefused) {
  TempDir dir;
  test::write_file(dir.file("junk.brep"), "0 1 2 3 garbage\n");
  EXPECT_CONTAINS(refusal([&] { read_shape_file(dir.file("junk.brep")); }), "junk.brep: not a BREP file");
}

TEST(ReadShapeFile, TruncatedStepIsRefused) {
  TempDir dir;
  const std::string text = test::read_file(step_file(dir, box()));
  test::write_file(dir.file("cut.step"), text.substr(0, text.size() / 2));
  // The parser may keep the entities before the cut, but no closed solid can come of them.
  const std::string why = refusal([&] { extract_solids(read_shape_file(dir.file("cut.step"))); });
  EXPECT_FALSE(why.empty());
}

TEST(ReadShapeFile, TruncatedBrepIsRefused) {
  TempDir dir;
  const std::string text = test::read_file(brep_file(dir, box()));
  test::write_file(dir.file("cut.brep"), text.substr(0, text.size() / 2));
  const std::string why = refusal([&] { extract_solids(read_shape_file(dir.file("cut.brep"))); });
  EXPECT_FALSE(why.empty());
}

TEST(ReadBrepString, RoundTripOfABox) {
  std::ostringstream out;
  BRepTools::Write(box(), out);
  const auto solids = extract_solids(read_brep_string(out.str()));
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-9);
}

TEST(ReadBrepString, GarbageAndEmptyAreRefused) {
  EXPECT_CONTAINS(refusal([] { read_brep_string("not a shape"); }), "BREP text");
  EXPECT_CONTAINS(refusal([] { read_brep_string(""); }), "empty");
}

TEST(ExtractSolids, CompoundOfTwoBoxesGivesTwoSolidsInOrder) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, box(1, 1, 1));
  b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(5, 0, 0), 2, 2, 2).Shape());
  const auto solids = extract_solids(c);
  ASSERT_EQ(solids.size(), 2u);
  EXPECT_NEAR(volume(solids[0]), 1.0, 1e-9);
  EXPECT_NEAR(volume(solids[1]), 8.0, 1e-9);
}

TEST(ExtractSolids, EmptyCompoundIsRefused) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  EXPECT_CONTAINS(refusal([&] { extract_solids(c); }), "holds no solid");
}

TEST(ExtractSolids, NullShapeIsRefused) {
  EXPECT_CONTAINS(refusal([] { extract_solids(TopoDS_Shape()); }), "empty");
}

TEST(ExtractSolids, LooseEdgesAloneAreRefusedAndCounted) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge());
  b.Add(c, BRepBuilderAPI_MakeEdge(gp_Pnt(0, 1, 0), gp_Pnt(1, 1, 0)).Edge());
  EXPECT_CONTAINS(refusal([&] { extract_solids(c); }), "(only 2 loose edges)");
}

TEST(ExtractSolids, LooseEdgeBesideASolidIsIgnored) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, box());
  b.Add(c, BRepBuilderAPI_MakeEdge(gp_Pnt(9, 0, 0), gp_Pnt(10, 0, 0)).Edge());
  EXPECT_EQ(extract_solids(c).size(), 1u);
}

TEST(ExtractSolids, OpenShellIsRefusedNamingAnEdgeWithOneFace) {
  const std::string why = refusal([] { extract_solids(shell_of_box_faces(/*skip=*/0)); });
  EXPECT_CONTAINS(why, "shell 1");
  EXPECT_CONTAINS(why, "is bounded by 1 face (the shell is open)");
}

TEST(ExtractSolids, OpenShellInAFileIsRefused) {
  TempDir dir;
  const std::string why =
      refusal([&] { extract_solids(read_shape_file(brep_file(dir, shell_of_box_faces(2), "open.brep"))); });
  EXPECT_CONTAINS(why, "is bounded by 1 face (the shell is open)");
}

TEST(ExtractSolids, ClosedShellBecomesASolidWithPositiveVolume) {
  const auto solids = extract_solids(shell_of_box_faces());
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-9);
}

TEST(ExtractSolids, ReversedShellBecomesASolidWithPositiveVolume) {
  const auto solids = extract_solids(box_shell().Reversed());
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-9);
}

TEST(ExtractSolids, InsideOutSolidIsReversed) {
  const auto solids = extract_solids(box().Reversed());
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-9);
}

TEST(ExtractSolids, InsideOutCurvedSolidsAreReversed) {
  // The volume that decides the orientation is summed face by face (on two threads when there are
  // several faces, as the cylinder's three): curved faces, seams and poles, with the vertices'
  // mean off the origin.
  const TopoDS_Shape shapes[] = {BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(5, -3, 2), gp_Dir(0, 1, 1)), 1.5, 4.0).Shape(),
                                 BRepPrimAPI_MakeSphere(gp_Pnt(-7, 2, 9), 2.0).Shape()};
  for (const TopoDS_Shape& shape : shapes) {
    const double v = volume(shape);
    ASSERT_GT(v, 0.0);
    for (const TopoDS_Shape& given : {shape, shape.Reversed()}) {
      const auto solids = extract_solids(given);
      ASSERT_EQ(solids.size(), 1u);
      EXPECT_NEAR(volume(solids[0]), v, 1e-9 * v);
    }
  }
}

TEST(ExtractSolids, SolidWithInwardFacesIsReversed) {
  // MakeSolid keeps the shell as given: reversed, its faces point inward and the volume is negative.
  const TopoDS_Solid inward = BRepBuilderAPI_MakeSolid(TopoDS::Shell(box_shell().Reversed())).Solid();
  ASSERT_LT(volume(inward), 0.0);
  const auto solids = extract_solids(inward);
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-9);
}

TEST(ExtractSolids, FlatPillowHasZeroVolumeAndIsRefused) {
  // A square face and the same face reversed: every edge has two sides, but nothing is enclosed.
  const TopoDS_Face square = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 0, 1, 0, 1).Face();
  BRep_Builder b;
  TopoDS_Shell shell;
  b.MakeShell(shell);
  b.Add(shell, square);
  b.Add(shell, square.Reversed());
  const TopoDS_Solid pillow = BRepBuilderAPI_MakeSolid(shell).Solid();
  EXPECT_CONTAINS(refusal([&] { extract_solids(pillow); }), "solid 1: has zero volume");
}

TEST(ExtractSolids, SeamsAndPolesAreNotOpenEdges) {
  // A sphere has a seam (one face on both sides) and two degenerate edges at its poles; a cylinder
  // has a seam. Neither is open.
  EXPECT_EQ(extract_solids(BRepPrimAPI_MakeSphere(2.0).Shape()).size(), 1u);
  EXPECT_EQ(extract_solids(BRepPrimAPI_MakeCylinder(1.0, 3.0).Shape()).size(), 1u);
  const TopoDS_Shape sphere_shell = TopExp_Explorer(BRepPrimAPI_MakeSphere(2.0).Shape(), TopAbs_SHELL).Current();
  const auto solids = extract_solids(sphere_shell);
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 4.0 / 3.0 * M_PI * 8.0, 1e-6);
}

TEST(ExtractSolids, NonManifoldEdgeIsRefused) {
  // A fin: a square face hung on one edge of a closed box shell, so that edge has three faces.
  TopoDS_Shell shell = shell_of_box_faces();
  const TopoDS_Edge edge = TopoDS::Edge(TopExp_Explorer(shell, TopAbs_EDGE).Current());
  TopoDS_Vertex v1, v2;
  TopExp::Vertices(edge, v1, v2);
  const gp_Pnt p1 = BRep_Tool::Pnt(v1), p2 = BRep_Tool::Pnt(v2);
  // Away from the box: along the sum of the box's outward directions at the edge is enough.
  gp_Vec out(gp_Pnt(0.5, 1.0, 1.5), p1.Translated(0.5 * gp_Vec(p1, p2)));
  out.Normalize();
  const gp_Pnt p3 = p2.Translated(out), p4 = p1.Translated(out);
  const TopoDS_Vertex v3 = BRepBuilderAPI_MakeVertex(p3), v4 = BRepBuilderAPI_MakeVertex(p4);
  BRepBuilderAPI_MakeWire wire(edge, BRepBuilderAPI_MakeEdge(v2, v3).Edge(), BRepBuilderAPI_MakeEdge(v3, v4).Edge(),
                               BRepBuilderAPI_MakeEdge(v4, v1).Edge());
  ASSERT_TRUE(wire.IsDone());
  BRepBuilderAPI_MakeFace fin(wire.Wire(), true);
  ASSERT_TRUE(fin.IsDone());
  BRep_Builder b;
  shell.Free(true);
  b.Add(shell, fin.Face());
  const std::string why = refusal([&] { extract_solids(shell); });
  EXPECT_CONTAINS(why, "is bounded by 3 faces (non-manifold)");
}

TEST(ExtractSolids, LooseFacesOfABoxAreSewnIntoASolid) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  for (TopExp_Explorer fx(box(), TopAbs_FACE); fx.More(); fx.Next()) b.Add(c, fx.Current());
  const auto solids = extract_solids(c);
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-9);
}

TEST(ExtractSolids, LooseFacesThatDoNotCloseAreRefused) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  int i = 0;
  for (TopExp_Explorer fx(box(), TopAbs_FACE); fx.More(); fx.Next(), ++i)
    if (i != 3) b.Add(c, fx.Current());
  EXPECT_CONTAINS(refusal([&] { extract_solids(c); }), "do not sew into closed shells");
}

// Real STEP files (NIST CTC 02, 04) hold a solid and a one-face construction surface: the solid
// is computed, the surface is skipped and reported.
TEST(ExtractSolids, LooseFaceBesideASolidIsSkippedAndReported) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, box());
  b.Add(c, BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 10), gp_Dir(0, 0, 1)), 0, 1, 0, 1).Face());
  std::vector<std::string> skipped;
  EXPECT_EQ(extract_solids(c, &skipped).size(), 1u);
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_CONTAINS(skipped[0], "1 loose face");
}

TEST(ExtractSolids, LooseFaceAloneIsRefused) {
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 10), gp_Dir(0, 0, 1)), 0, 1, 0, 1).Face();
  EXPECT_CONTAINS(refusal([&] { extract_solids(face); }), "1 loose face");
}

// tests/data/bad/self_intersecting.brep: a prism on a bow-tie quadrilateral. BRepCheck names the
// wire; ShapeFix cannot heal it, and the refusal says so.
TEST(ExtractSolids, BRepCheckFailureNamesTheSubShape) {
  const std::string path = std::string(CADMEDIAL_SOURCE_DIR) + "/tests/data/bad/self_intersecting.brep";
  const std::string why = refusal([&] { extract_solids(read_shape_file(path)); });
  EXPECT_CONTAINS(why, "solid 1: wire 5 is invalid (BRepCheck_SelfIntersectingWire)");
  EXPECT_CONTAINS(why, "; ShapeFix cannot heal it");
}

// Moving a vertex of a box off its edges' ends by 3.7 times its tolerance breaks the B-rep for
// BRepCheck (it allows 1 x), and stays under the cheap curve-end check (10 x), which runs first.
// ShapeFix mends it (it widens the tolerance); the warning names what BRepCheck found.
TEST(ExtractSolids, BRepCheckFailureThatShapeFixHealsIsAWarning) {
  const TopoDS_Shape shape = test::box_with_vertex_off_its_edges(1, 1, 1);
  std::vector<std::string> warnings;
  const auto solids = extract_solids(shape, nullptr, &warnings);
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_TRUE(BRepCheck_Analyzer(solids[0]).IsValid());
  EXPECT_NEAR(volume(solids[0]), 1.0, 1e-5);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_CONTAINS(warnings[0], "solid 1: vertex 1 is invalid (BRepCheck_InvalidPointOnCurve)");
  EXPECT_CONTAINS(warnings[0], "; healed by ShapeFix");
}

// The pipeline defers BRepCheck to its second thread: the solid comes out unchecked, and the
// deferred check throws FailedBRepCheck with the eager check's words (which the eager one, healing,
// puts in its warning); the pipeline then computes the healed solid with that warning.
TEST(ExtractSolids, DeferredBRepCheckThrowsWhatTheEagerOneHeals) {
  const TopoDS_Shape shape = test::box_with_vertex_off_its_edges(1, 1, 1);
  std::vector<std::string> warnings;
  extract_solids(shape, nullptr, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  std::vector<DeferredCheck> checks;
  EXPECT_EQ(extract_solids(shape, nullptr, checks).size(), 1u);
  ASSERT_EQ(checks.size(), 1u);
  try {
    run_deferred_checks(checks);
    ADD_FAILURE() << "expected FailedBRepCheck";
  } catch (const FailedBRepCheck& e) {
    EXPECT_EQ(warnings[0].rfind(std::string(e.what()) + "; healed by ShapeFix", 0), 0u) << e.what();
  }
  ComputeParams params;
  params.sampling.target_samples = 2000;
  const ComputeResult one = compute_medial_axis(shape, params);
  EXPECT_EQ(one.stats.solids.size(), 1u);
  ASSERT_FALSE(one.stats.warnings.empty());
  EXPECT_EQ(one.stats.warnings[0], warnings[0]);
  // In a compound the first solid's triangulation checks them all: the second one is healed.
  BRep_Builder b;
  TopoDS_Compound two;
  b.MakeCompound(two);
  b.Add(two, BRepPrimAPI_MakeBox(gp_Pnt(5, 0, 0), 1, 2, 3).Shape());
  b.Add(two, shape);
  const ComputeResult both = compute_medial_axis(two, params);
  EXPECT_EQ(both.stats.solids.size(), 2u);
  ASSERT_FALSE(both.stats.warnings.empty());
  EXPECT_CONTAINS(both.stats.warnings[0], "solid 2: vertex 1 is invalid");
  // A valid solid passes its deferred check.
  checks.clear();
  extract_solids(BRepPrimAPI_MakeBox(1, 2, 3).Shape(), nullptr, checks);
  ASSERT_EQ(checks.size(), 1u);
  EXPECT_NO_THROW(run_deferred_checks(checks));
}

TEST(ExtractSolids, EmptySolidBesideOthersIsSkippedWithAWarningNamingIt) {
  const TopoDS_Shape shape = test::make_compound(
      {test::make_box(1, 1, 1), test::empty_solid(), BRepPrimAPI_MakeBox(gp_Pnt(1, 0, 0), 1, 1, 1).Solid()});
  std::vector<std::string> warnings;
  const auto solids = extract_solids(shape, nullptr, &warnings);
  ASSERT_EQ(solids.size(), 2u);
  EXPECT_NEAR(volume(solids[0]) + volume(solids[1]), 2.0, 1e-9);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_CONTAINS(warnings[0], "solid 2: has no shell (an empty solid); skipped");
}

TEST(ExtractSolids, ZeroVolumeSolidBesideABoxIsSkipped) {
  const TopoDS_Face square = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 5), gp_Dir(0, 0, 1)), 0, 1, 0, 1).Face();
  BRep_Builder b;
  TopoDS_Shell shell;
  b.MakeShell(shell);
  b.Add(shell, square);
  b.Add(shell, square.Reversed());
  const TopoDS_Shape shape = test::make_compound({BRepBuilderAPI_MakeSolid(shell).Solid(), test::make_box(1, 2, 3)});
  std::vector<std::string> warnings;
  const auto solids = extract_solids(shape, nullptr, &warnings);
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-9);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_CONTAINS(warnings[0], "solid 1: has zero volume");
}

// Nothing computable left: refused with the first bad solid's words, as before healing.
TEST(ExtractSolids, OnlyBadSolidsAreRefusedWithTheFirstOnesWords) {
  EXPECT_EQ(refusal([] { extract_solids(test::empty_solid()); }), "solid 1: has no shell (an empty solid)");
  const std::string why = refusal([] { extract_solids(test::make_compound({test::empty_solid(), test::empty_solid()})); });
  EXPECT_EQ(why, "solid 1: has no shell (an empty solid)");
}

TEST(ExtractSolids, SolidOpenByASmallGapIsSewnWithAWarning) {
  // 0.001 on a box of diagonal 37: closed at a ten-thousandth of it.
  std::vector<std::string> warnings;
  const auto solids = extract_solids(test::box_with_gap(10, 20, 30, 1, 0.001), nullptr, &warnings);
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_TRUE(BRepCheck_Analyzer(solids[0]).IsValid());
  EXPECT_NEAR(volume(solids[0]), 6000.0, 6000.0 * 1e-3);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_CONTAINS(warnings[0], "solid 1: edge ");
  EXPECT_CONTAINS(warnings[0], "is bounded by 1 face (the shell is open)");
  EXPECT_CONTAINS(warnings[0], "closed by sewing its faces");
}

TEST(ExtractSolids, SolidOpenByAWideGapIsRefused) {
  // 1 on a box of diagonal 37 is a hole, not a gap of the export.
  const std::string why = refusal([] { extract_solids(test::box_with_gap(10, 20, 30, 1, 1.0)); });
  EXPECT_CONTAINS(why, "solid 1: edge ");
  EXPECT_CONTAINS(why, "is bounded by 1 face (the shell is open)");
}

TEST(ExtractSolids, SolidWithHalfItsFacesInsideOutIsHealedWithAWarning) {
  // Faces x max, y max, z max reversed: the volume sums to zero, and ShapeFix orients the shell.
  std::vector<std::string> warnings;
  const auto solids = extract_solids(test::box_with_reversed_faces(10, 8, 6, 0b101010), nullptr, &warnings);
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 480.0, 1e-6);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_CONTAINS(warnings[0], "solid 1: has zero volume (flat, or partly inside out); healed by ShapeFix");
}

TEST(ExtractSolids, FaceReversedInItsShellIsHealedWithAWarning) {
  std::vector<std::string> warnings;
  const auto solids = extract_solids(test::box_with_reversed_face(10, 20, 30, 5), nullptr, &warnings);
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6000.0, 1e-6);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_CONTAINS(warnings[0], "solid 1: shell 1 is invalid (BRepCheck_BadOrientationOfSubshape); healed by ShapeFix");
}

TEST(ExtractSolids, VertexFarFromItsCurveEndsIsRefusedBeforeBRepCheck) {
  const TopoDS_Shape shape = BRepPrimAPI_MakeBox(1, 1, 1).Shape();
  const TopoDS_Vertex v = TopoDS::Vertex(TopExp_Explorer(shape, TopAbs_VERTEX).Current());
  BRep_Builder().UpdateVertex(v, BRep_Tool::Pnt(v).Translated(gp_Vec(0.3, 0.2, 0.1)), 1e-7);
  const std::string why = refusal([&] { extract_solids(shape); });
  EXPECT_CONTAINS(why, "'s curve does not end at its vertex: 0.374166 away, tolerance 1e-07");
}

// In an assembly, only the solid whose geometry the cheap checks refuse is left out; its edges
// are numbered over it, as FreeCAD numbers them.
TEST(ExtractSolids, SolidWithBrokenGeometryBesideAnotherIsSkipped) {
  const TopoDS_Shape bad = BRepPrimAPI_MakeBox(gp_Pnt(5, 0, 0), 1, 1, 1).Shape();
  const TopoDS_Vertex v = TopoDS::Vertex(TopExp_Explorer(bad, TopAbs_VERTEX).Current());
  BRep_Builder().UpdateVertex(v, BRep_Tool::Pnt(v).Translated(gp_Vec(0.3, 0.2, 0.1)), 1e-7);
  const std::string alone = refusal([&] { extract_solids(bad); });
  BRep_Builder b;
  TopoDS_Compound two;
  b.MakeCompound(two);
  b.Add(two, box());
  b.Add(two, bad);
  std::vector<std::string> warnings;
  const auto solids = extract_solids(two, nullptr, &warnings);
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(volume(solids[0]), 6.0, 1e-9);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind("solid 2: " + alone + "; skipped", 0), 0u) << warnings[0];
}

TEST(ExtractSolids, CurveOnFaceAwayFromTheEdgeIsRefusedBeforeBRepCheck) {
  // One edge's curve on one of its faces moved by 0.5 in that face's parameter plane.
  const TopoDS_Shape shape = BRepPrimAPI_MakeBox(1, 1, 1).Shape();
  const TopoDS_Face face = TopoDS::Face(TopExp_Explorer(shape, TopAbs_FACE).Current());
  const TopoDS_Edge edge = TopoDS::Edge(TopExp_Explorer(face, TopAbs_EDGE).Current());
  double first = 0, last = 0;
  const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, face, first, last);
  BRep_Builder().UpdateEdge(edge, Handle(Geom2d_Curve)::DownCast(pc->Translated(gp_Vec2d(0.5, 0))), face, 1e-7);
  const std::string why = refusal([&] { extract_solids(shape); });
  EXPECT_CONTAINS(why, "'s curve on a face strays from its 3D curve: 0.5 apart at an end, tolerance 1e-07");
}

// tests/data/bad/fuzz-slow/: mangled numbers in a 1e-6 box that kept BRepCheck_Wire::SelfIntersect
// busy for minutes. Refused by the curve-end check in microseconds; the message says which check
// refused it, so BRepCheck never ran.
TEST(ExtractSolids, SlowFuzzInputsAreRefusedBeforeBRepCheck) {
  const std::string dir = std::string(CADMEDIAL_SOURCE_DIR) + "/tests/data/bad/fuzz-slow/";
  for (const char* name : {"timeout_40e90c94.brep", "timeout_brepcheck_wire_selfintersect.brep", "timeout_d3eedfb5.brep"}) {
    const std::string why = refusal([&] { extract_solids(read_shape_file(dir + name)); });
    EXPECT_TRUE(why.find("'s curve does not end at its vertex") != std::string::npos ||
                why.find("'s curve on a face strays from its 3D curve") != std::string::npos)
        << name << ": " << why;
  }
}

}  // namespace
}  // namespace cadmedial
