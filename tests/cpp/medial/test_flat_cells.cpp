// Delaunay cells whose four samples are coplanar, to rounding, have no circumcentre that doubles
// can compute (two rows of samples at one spacing on a planar face make many): the computed
// centre is noise, a ball holding other samples, a spike of the axis. On NIST CTC 01 one was 1.4
// spacings long. Every Voronoi vertex's ball is empty: no sample lies inside it.
#include <gtest/gtest.h>

#include "core/io/read_shape.h"
#include "core/pipeline/compute_medial_axis.h"
#include "core/sampling/point_grid.h"
#include "support/engine_run.h"

namespace cadmedial::test {
namespace {

TEST(FlatCells, NoMedialBallHoldsASampleOnNistCtc01) {
  const std::string path = model_path("nist/nist_ctc_01_asme1_rd.stp");
  if (path.empty()) GTEST_SKIP() << "../shared/data/models is not here";
  const TopoDS_Shape shape = read_shape_file(path);
  ComputeParams params;
  params.sampling.target_samples = 20000;
  const ComputeResult r = compute_medial_axis(shape, params);
  const Samples samples = sample_shape(shape, params.sampling).front();
  ASSERT_EQ(samples.size(), r.stats.samples);
  PointGrid grid(r.stats.spacing);
  for (std::size_t s = 0; s < samples.size(); ++s) grid.insert(samples.points[s], static_cast<int>(s));
  std::size_t holding = 0;
  double worst = 0;
  for (std::size_t v = 0; v < r.mesh.num_vertices(); ++v) {
    const Point3& x = r.mesh.vertices[v];
    const double inside = r.mesh.radius[v] * (1.0 - 1e-6);
    if (!(inside > 0)) continue;
    double nearest = inside;
    grid.any_near(x, inside, [&](int s) {
      nearest = std::min(nearest, std::sqrt(distance2(samples.points[s], x)));
      return false;
    });
    if (nearest < inside) {
      ++holding;
      worst = std::max(worst, (r.mesh.radius[v] - nearest) / r.stats.spacing);
    }
  }
  EXPECT_EQ(holding, 0u) << "the deepest sample lies " << worst << " spacings inside its ball";
}

}  // namespace
}  // namespace cadmedial::test
