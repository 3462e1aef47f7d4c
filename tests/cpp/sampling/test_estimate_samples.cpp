// The plan's estimate of the sample count against the samples sample_solid places: --samples
// calibrates the spacing with it, and a pass is taken again while the count misses by 15 %. And
// the estimate for a spacing refined at thin walls: the sampling finer than 4 times is tried only
// when it says the count stays within budget.
#include <cmath>

#include <gtest/gtest.h>

#include "core/features/classify_features.h"
#include "core/pipeline/compute_medial_axis.h"
#include "core/io/read_shape.h"
#include "core/sampling/sample_solid.h"
#include "core/sampling/spacing_field.h"
#include "core/sampling/thin_walls.h"
#include "support/engine_run.h"
#include "support/solids.h"

namespace cadmedial {
namespace {

using test::make_box;
using test::make_cylinder;

double estimate_over_actual(const TopoDS_Solid& solid, double spacing) {
  const Features features = classify_features(solid);
  const double estimate = estimate_samples(measure_solid(solid, features), spacing);
  return estimate / static_cast<double>(sample_solid(solid, features, spacing).size());
}

// Flat faces and sharp edges (their triplets and the strip they keep free of face samples), and
// a curved face whose spacing follows its curvature, from coarse to fine.
TEST(EstimateSamples, WithinTenPercentOnABoxAndACylinder) {
  // From 5 spacings across the box's thinnest side (1.07; 1.14 at 3 across) to 30 (1.01).
  for (double h : {6.0, 3.0, 1.0}) EXPECT_NEAR(estimate_over_actual(make_box(100, 60, 30), h), 1.0, 0.1) << h;
  for (double h : {5.0, 2.0, 0.5}) EXPECT_NEAR(estimate_over_actual(make_cylinder(10, 100), h), 1.0, 0.1) << h;
}

// With an estimate that close, a target count is met in the first pass: the spacing it settles on
// is the one whose estimate is the target (a second pass would have rescaled it).
TEST(EstimateSamples, TargetCountMetInTheFirstPass) {
  const TopoDS_Solid box = make_box(100, 60, 30);
  const Features features = classify_features(box);
  for (std::size_t target : {2000u, 20000u}) {
    SamplingParams params;
    params.target_samples = target;
    const SamplingPlan plan = plan_sampling(box, params);
    EXPECT_NEAR(static_cast<double>(plan.estimated_samples) / target, 1.0, 0.15) << target;
    EXPECT_NEAR(estimate_samples(measure_solid(box, features), plan.spacing) / target, 1.0, 0.01) << target;
  }
}

// The estimate for `solid` sampled at spacing h refined at its thin walls down to h / finest,
// over the count the sampler places.
double refined_estimate_over_actual(const TopoDS_Solid& solid, double h, double finest) {
  const Features f = classify_features(solid);
  SolidSampler sampler(solid, f);
  // The density rules only: the estimate does not foresee the mirrors across thin walls
  // (mirror_thin_walls.h; with them CTC 04's refined count is a third above it).
  sampler.mirror_thin_walls(false);
  const Samples first = sampler.sample(SpacingField(h));
  const std::vector<double> radii = wall_radii(first, h, convex_face_pairs(f), -0.95);
  SpacingField field = thin_wall_spacing(first, radii, h, 0.5, finest, 0.5);
  EXPECT_FALSE(field.is_uniform());
  field.measure_on(first, f.edge_faces);
  const double estimate = estimate_samples(measure_solid(solid, f), f, field, first);
  return estimate / static_cast<double>(sampler.sample(field).size());
}

TEST(EstimateSamples, RefinedOnPartsWithNarrowFacesWithinTwentyPercent) {
  // NIST CTC 04 and FTC 10 at the spacing of the default 20,000 samples, down to a 32nd: 115,677
  // and 180,855 samples on narrow ribs, fillets and lettering. Their small faces have few interior
  // samples or none at the uniform spacing; counting only what those stand for, and each edge
  // sample by the field at it rather than by its edge's smallest, gave 38,518 and 98,906.
  for (const auto& [part, h] : {std::pair<const char*, double>{"nist/nist_ctc_04_asme1_rd.stp", 26.46},
                                {"nist/nist_ftc_10_asme1_rb.stp", 7.676}}) {
    const std::string path = test::model_path(part);
    if (path.empty()) GTEST_SKIP() << "../shared/data/models is not beside the repository";
    const std::vector<TopoDS_Solid> solids = extract_solids(read_shape_file(path));
    ASSERT_EQ(solids.size(), 1u);
    EXPECT_NEAR(refined_estimate_over_actual(solids.front(), h, 32.0), 1.0, 0.2) << part;
  }
}

}  // namespace
}  // namespace cadmedial
