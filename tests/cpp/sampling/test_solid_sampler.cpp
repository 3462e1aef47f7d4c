// The sampler across passes: refining thin walls resamples the solid, and the faces away from
// them keep their samples; the result must be exactly what a fresh sampler places.
#include <cmath>

#include <gtest/gtest.h>

#include "core/features/classify_features.h"
#include "core/sampling/sample_solid.h"
#include "core/sampling/spacing_field.h"
#include "core/sampling/thin_walls.h"
#include "support/solids.h"

namespace cadmedial {
namespace {

void expect_same_samples(const Samples& a, const Samples& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.points[i], b.points[i]) << i;
    ASSERT_EQ(a.tag[i], b.tag[i]) << i;
    ASSERT_EQ(a.normal[i], b.normal[i]) << i;
    ASSERT_EQ(a.normal2[i], b.normal2[i]) << i;
    ASSERT_EQ(a.curvature[i], b.curvature[i]) << i;
    ASSERT_EQ(a.face[i], b.face[i]) << i;
    ASSERT_EQ(a.edge[i], b.edge[i]) << i;
  }
  ASSERT_EQ(a.triplets.size(), b.triplets.size());
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (size_t f = 0; f < a.faces.size(); ++f) {
    EXPECT_EQ(a.faces[f].sample, b.faces[f].sample) << "face " << f;
    EXPECT_EQ(a.faces[f].uv, b.faces[f].uv) << "face " << f;
    EXPECT_EQ(a.faces[f].boundary, b.faces[f].boundary) << "face " << f;
    EXPECT_EQ(a.faces[f].u_scale, b.faces[f].u_scale) << "face " << f;
    EXPECT_EQ(a.faces[f].v_scale, b.faces[f].v_scale) << "face " << f;
  }
}

TEST(SolidSampler, ARefinedPassKeepsFarFacesAndEqualsAFreshSampling) {
  // A 20 x 20 x 6 block with a pocket whose floor is 0.6 thick, at spacing 1: the floor and the
  // pocket's walls near it are refined; the outer sides, more than the field's reach away, are not.
  const TopoDS_Solid solid = test::make_pocket_block(20, 6, 5, 15, 5.4);
  const Features f = classify_features(solid);
  const double h = 1.0;
  SolidSampler sampler(solid, f);
  const Samples first = sampler.sample(SpacingField(h));
  EXPECT_EQ(sampler.kept_faces(), 0);  // nothing to keep from
  const std::vector<double> radii = wall_radii(first, h, convex_face_pairs(f), -0.95);
  SpacingField field = thin_wall_spacing(first, radii, h, 0.5, 4.0, 0.5);
  ASSERT_FALSE(field.is_uniform());
  field.measure_on(first, f.edge_faces);
  int refined = 0;
  for (int fi = 0; fi < f.faces.Extent(); ++fi) refined += field.on_face(fi) < h;
  ASSERT_GT(refined, 0);
  ASSERT_LT(refined, f.faces.Extent());

  const Samples second = sampler.sample(field);
  EXPECT_GT(second.size(), first.size());
  EXPECT_GT(sampler.kept_faces(), 0);
  EXPECT_LE(sampler.kept_faces(), f.faces.Extent() - refined);
  expect_same_samples(second, SolidSampler(solid, f).sample(field));

  // The same spacing again keeps every face, and samples as the first pass did.
  const Samples again = sampler.sample(SpacingField(h));
  EXPECT_EQ(sampler.kept_faces(), f.faces.Extent());
  expect_same_samples(again, first);
}

TEST(SolidSampler, FacesWhoseCornerBallChangedAreSampledAgain) {
  // A field finer only around one corner of a cube (from a point outside it, 2.3 from the
  // corner): the corner's ball shrinks (0.475 against 0.5) while no face or edge sample lies
  // where the field is finer, so no face counts as refined. But the samples along the corner's
  // three edges move (one more fits between the balls), and those edges reach all six faces:
  // every face must be sampled again.
  const TopoDS_Solid solid = test::make_box(10, 10, 10);
  const Features f = classify_features(solid);
  const double h = 1.0, d = 2.3 / std::sqrt(3.0);
  SolidSampler sampler(solid, f);
  const Samples first = sampler.sample(SpacingField(h));
  SpacingField field(h, {{-d, -d, -d}}, {0.3}, 0.5);
  field.measure_on(first, f.edge_faces);
  for (int fi = 0; fi < f.faces.Extent(); ++fi) ASSERT_EQ(field.on_face(fi), h);
  ASSERT_LT(field.at({0, 0, 0}), h);
  const Samples second = sampler.sample(field);
  EXPECT_EQ(sampler.kept_faces(), 0);
  expect_same_samples(second, SolidSampler(solid, f).sample(field));
}

}  // namespace
}  // namespace cadmedial
