// heal_solid: ShapeFix on a solid BRepCheck refuses, and what it says it did.
#include "core/io/heal_shape.h"

#include <gtest/gtest.h>

#include <string>

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "support/broken_solids.h"

namespace cadmedial {
namespace {

double volume(const TopoDS_Shape& s) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(s, props);
  return props.Mass();
}

TEST(HealSolid, FaceReversedInItsShellIsReoriented) {
  const TopoDS_Solid broken = test::box_with_reversed_face(10, 8, 6, 5);
  ASSERT_FALSE(BRepCheck_Analyzer(broken).IsValid());
  const HealedSolid healed = heal_solid(broken);
  ASSERT_FALSE(healed.solid.IsNull()) << healed.fixes;
  EXPECT_TRUE(BRepCheck_Analyzer(healed.solid).IsValid());
  EXPECT_NEAR(volume(healed.solid), 480.0, 1e-9);
  EXPECT_NE(healed.fixes.find("faces oriented inconsistently in the shell, reoriented"), std::string::npos)
      << healed.fixes;
}

TEST(HealSolid, VertexOffItsEdgesIsMadeValid) {
  const TopoDS_Solid broken =
      TopoDS::Solid(TopExp_Explorer(test::box_with_vertex_off_its_edges(1, 2, 3), TopAbs_SOLID).Current());
  ASSERT_FALSE(BRepCheck_Analyzer(broken).IsValid());
  const HealedSolid healed = heal_solid(broken);
  ASSERT_FALSE(healed.solid.IsNull()) << healed.fixes;
  EXPECT_TRUE(BRepCheck_Analyzer(healed.solid).IsValid());
  EXPECT_NEAR(volume(healed.solid), 6.0, 1e-5);
}

// tests/data/bad/self_intersecting.brep: a prism on a bow-tie quadrilateral, its side faces
// crossing. It cannot be a solid; ShapeFix fails on it, and says so instead of throwing.
TEST(HealSolid, BowTiePrismIsNotHealed) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  const std::string path = std::string(CADMEDIAL_SOURCE_DIR) + "/tests/data/bad/self_intersecting.brep";
  ASSERT_TRUE(BRepTools::Read(shape, path.c_str(), builder));
  const TopoDS_Solid solid = TopoDS::Solid(TopExp_Explorer(shape, TopAbs_SOLID).Current());
  const HealedSolid healed = heal_solid(solid);
  EXPECT_TRUE(healed.solid.IsNull());
  EXPECT_NE(healed.fixes.find("ShapeFix failed"), std::string::npos) << healed.fixes;
}

}  // namespace
}  // namespace cadmedial
