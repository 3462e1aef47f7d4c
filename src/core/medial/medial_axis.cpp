#include "medial_axis.h"

#include <chrono>
#include <future>

#include "../errors.h"
#include "delaunay_3.h"

#include "complete_medial_axis.h"
#include "geometry_3.h"
#include "inner_axis.h"
#include "number_cells.h"
#include "select_facets.h"
#include "triangulate.h"

namespace cadmedial {

using namespace internal;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

namespace {

MedialMesh medial_axis_after(const Samples& samples, const std::function<const Umbrellas&()>& wait_for_umbrellas,
                             const MedialParams& params, const InsideTest& inside, int solid_index,
                             MedialAxisStats* stats_out, const Progress& progress) {
  MedialAxisStats st;
  auto t0 = Clock::now();
  Delaunay dt;
  std::vector<Vertex> handle;
  std::vector<int> rank;
  triangulate(samples, dt, handle, rank, progress, "delaunay");
  st.timings.push_back({"delaunay", seconds_since(t0)});
  report(progress, "selection", 0.0);
  const Umbrellas& umbrellas = wait_for_umbrellas();

  t0 = Clock::now();
  const Umbrellas pole_umbrellas = params.plain_medial ? umbrellas_from_poles(dt, samples.size()) : Umbrellas();
  const Selection sel(samples, params.plain_medial ? pole_umbrellas : umbrellas, params);
  MedialComplex mc;
  const std::vector<Cell> cells = number_cells(dt, rank, mc);
  {
    // The circumcentres on the second core while the selection walks the cells (it needs only
    // their samples and neighbours). No progress from there; the future waits for it on any exit.
    std::future<void> centers = std::async(std::launch::async, [&cells, &mc] { cell_centers(cells, mc); });
    select_facets(sel, mc, st, progress, !params.plain_medial);
    centers.get();
  }
  st.timings.push_back({"selection", seconds_since(t0)});

  t0 = Clock::now();
  if (!params.plain_medial) {
    complete_convex_edges(dt, handle, samples, mc, st);
    complete_corners(dt, handle, samples, sel, mc, st);
  }
  st.timings.push_back({"completion", seconds_since(t0)});
  report(progress, "inner", 0.0);

  t0 = Clock::now();
  {
    const auto [lo, hi] = bounding_box(samples.points);
    merge_coincident_cells(mc, 1e-9 * norm(sub(hi, lo)), progress);
  }
  report(progress, "inner", 0.2);
  const std::vector<std::uint8_t> in = label_inside(mc, samples, umbrellas, inside, st, progress);
  report(progress, "inner", 0.7);
  MedialMesh mesh = extract_inner(mc, in, samples, solid_index, st, progress);
  st.timings.push_back({"inner", seconds_since(t0)});
  if (stats_out) *stats_out = st;
  return mesh;
}

}  // namespace

MedialMesh medial_axis(const Samples& samples, const Umbrellas& umbrellas, const MedialParams& params,
                       const InsideTest& inside, int solid_index, MedialAxisStats* stats, const Progress& progress) {
  return medial_axis_after(samples, [&]() -> const Umbrellas& { return umbrellas; }, params, inside, solid_index,
                           stats, progress);
}

MedialMesh medial_axis(const Samples& samples, std::shared_future<Umbrellas> umbrellas, const MedialParams& params,
                       const InsideTest& inside, int solid_index, MedialAxisStats* stats, const Progress& progress) {
  return medial_axis_after(samples, [&]() -> const Umbrellas& { return umbrellas.get(); }, params, inside,
                           solid_index, stats, progress);
}

double bare_delaunay_seconds(const std::vector<Point3>& points) {
  std::vector<K::Point_3> pts;
  pts.reserve(points.size());
  for (const Point3& p : points) pts.emplace_back(p[0], p[1], p[2]);
  const auto t0 = Clock::now();
  CGAL::Delaunay_triangulation_3<K> dt(pts.begin(), pts.end());
  const double s = seconds_since(t0);
  if (dt.number_of_vertices() == 0 && !points.empty()) throw GeometryError("Delaunay failed");
  return s;
}

}  // namespace cadmedial
