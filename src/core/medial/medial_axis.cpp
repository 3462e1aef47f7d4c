#include "medial_axis.h"

#include <atomic>
#include <chrono>
#include <future>
#include <optional>

#include "../errors.h"
#include "delaunay_3.h"
#include <CGAL/spatial_sort.h>

#include "complete_medial_axis.h"
#include "geometry_3.h"
#include "inner_axis.h"
#include "number_cells.h"
#include "preserve_topology.h"
#include "sample_votes.h"
#include "select_facets.h"
#include "triangulate.h"
#include "weld_vertices.h"
#include "../two_cores.h"

namespace cadmedial {

using namespace internal;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

namespace {

// The umbrellas are `ready`, or `pending` on another thread: then the selection's tables,
// which need only them and the samples, are built by a thread of their own as soon as they
// come, while CGAL triangulates (the worker's jobs end before the triangulation does: 0.08 s
// before at "10k", bench/README.md).
MedialMesh medial_axis_after(const Samples& samples, const Umbrellas* ready,
                             const std::shared_future<Umbrellas>* pending, const MedialParams& params,
                             const InsideTest& inside, int solid_index, MedialAxisStats* stats_out,
                             const Progress& progress, const std::atomic<bool>* give_up) {
  MedialAxisStats st;
  // In this order: `tables`' destructor waits for the task, which reads `leaving` until then.
  std::optional<const Selection> selection;
  std::atomic<bool> leaving{false};
  std::future<void> tables;
  // A deferred future would never become ready here: its umbrellas are made by get(), below.
  if (pending && !params.plain_medial &&
      pending->wait_for(std::chrono::seconds(0)) != std::future_status::deferred) {
    tables = std::async(std::launch::async, [&selection, &samples, &params, &leaving, mine = *pending] {
      // Polled, so that a cancel or an error here does not wait for the reconstruction.
      while (mine.wait_for(std::chrono::milliseconds(1)) == std::future_status::timeout)
        if (leaving) return;
      const Umbrellas& u = mine.get();  // a failure is rethrown by tables.get()
      // Empty when the worker found the samples must change (give_up follows).
      if (!leaving && u.start.size() == samples.size() + 1) selection.emplace(samples, u, params);
    });
  }
  const SetOnExit leave{leaving};  // destroyed before `tables`, whose destructor waits
  auto t0 = Clock::now();
  Delaunay dt;
  std::vector<Vertex> handle;
  std::vector<int> rank;
  triangulate(samples, dt, handle, rank, progress, "delaunay", give_up);
  st.timings.push_back({"delaunay", seconds_since(t0)});
  report(progress, "selection", 0.0);
  if (tables.valid()) tables.get();  // after the umbrellas: they are ready now, or failed
  const Umbrellas& umbrellas = ready ? *ready : pending->get();
  if (give_up && give_up->load()) throw Cancelled();

  t0 = Clock::now();
  const Umbrellas pole_umbrellas = params.plain_medial ? umbrellas_from_poles(dt, samples.size()) : Umbrellas();
  MedialComplex mc;
  if (selection) {
    number_cells(dt, rank, mc);
  } else {
    // The selection's tables on the second core while the cells are numbered.
    on_two_cores([&] { number_cells(dt, rank, mc); },
                 [&](const std::atomic<bool>&) {
                   selection.emplace(samples, params.plain_medial ? pole_umbrellas : umbrellas, params);
                 });
  }
  const Selection& sel = *selection;
  {
    // The circumcentres, and which lie far outside (the selection builds no facet at those), half
    // the cells on each core; once the flat cells' centres are settled, those the votes put
    // outside.
    const auto [lo, hi] = bounding_box(samples.points);
    on_two_halves(mc.num_cells(), [&](int, std::size_t begin, std::size_t end) {
      cell_centers(samples.points, mc, begin, end);
      mark_far_outside(samples, lo, hi, mc, begin, end);
    });
    settle_flat_cells(samples.points, mc);
    const double eps = coincident_eps(samples.points);
    on_two_halves(mc.num_cells(), [&](int, std::size_t begin, std::size_t end) {
      mark_voted_outside(samples, eps, mc, begin, end);
    });
  }
  select_facets(sel, mc, st, progress, !params.plain_medial);
  st.timings.push_back({"selection", seconds_since(t0)});

  t0 = Clock::now();
  // Which cells merge (it reads only their centres and neighbours) on the second core meanwhile.
  std::vector<int> rep;
  on_two_cores(
      [&] {
        if (params.plain_medial) return;
        complete_convex_edges(handle, samples, mc, st);
        complete_corners(dt, handle, samples, sel, mc, st);
      },
      [&](const std::atomic<bool>&) {
        rep = coincident_cells(mc, samples.points, coincident_eps(samples.points));
      });
  if (!params.plain_medial) star_cells(mc, samples.size());
  st.timings.push_back({"completion", seconds_since(t0)});
  report(progress, "inner", 0.0);

  t0 = Clock::now();
  // The triangulation is not read after the completion: it goes on another thread while the
  // cells merge and the inside is labelled (their second core is not always busy).
  std::future<void> released = std::async(std::launch::async, [&dt, &handle] {
    dt.clear();
    handle = std::vector<Vertex>();
  });
  merge_coincident_cells(mc, std::move(rep), progress);
  report(progress, "inner", 0.2);
  const std::vector<std::uint8_t> in = label_inside(mc, samples, umbrellas, inside, st, progress);
  report(progress, "inner", 0.7);
  MedialMesh mesh = extract_inner(mc, in, samples, solid_index, st, progress);
  // The topology is counted on the geometry: vertices closer than coincident_cells' eps are one.
  st.welded_vertices = weld_vertices(mesh, coincident_eps(samples.points)).merged_vertices;
  released.get();
  // The complex goes while the second core counts the mesh (each about 10 ms at 65k samples).
  on_two_cores([&] { mc = MedialComplex(); },
               [&](const std::atomic<bool>&) { st.euler_characteristic = euler_characteristic(mesh); });
  st.timings.push_back({"inner", seconds_since(t0)});
  if (stats_out) *stats_out = st;
  return mesh;
}

}  // namespace

MedialMesh medial_axis(const Samples& samples, const Umbrellas& umbrellas, const MedialParams& params,
                       const InsideTest& inside, int solid_index, MedialAxisStats* stats, const Progress& progress) {
  return medial_axis_after(samples, &umbrellas, nullptr, params, inside, solid_index, stats, progress, nullptr);
}

MedialMesh medial_axis(const Samples& samples, std::shared_future<Umbrellas> umbrellas, const MedialParams& params,
                       const InsideTest& inside, int solid_index, MedialAxisStats* stats, const Progress& progress,
                       const std::atomic<bool>* give_up) {
  return medial_axis_after(samples, nullptr, &umbrellas, params, inside, solid_index, stats, progress, give_up);
}

double bare_delaunay_seconds(const std::vector<Point3>& points, BareOrder order) {
  using Bare = CGAL::Delaunay_triangulation_3<K>;
  std::vector<K::Point_3> pts;
  pts.reserve(points.size());
  for (const Point3& p : points) pts.emplace_back(p[0], p[1], p[2]);
  // Timed up to the triangulation's end, not its destruction.
  const auto t0 = Clock::now();
  double s = 0;
  std::size_t vertices = 0;
  if (order == BareOrder::CgalDefault) {
    const Bare dt(pts.begin(), pts.end());
    s = seconds_since(t0);
    vertices = dt.number_of_vertices();
  } else {
    // What the range insert does, with the other policy: each point located from the last one.
    CGAL::spatial_sort(pts.begin(), pts.end(), K(), SpatialSortPolicy());
    Bare dt;
    Bare::Vertex_handle hint;
    for (const K::Point_3& p : pts) hint = dt.insert(p, hint == Bare::Vertex_handle() ? Bare::Cell_handle() : hint->cell());
    s = seconds_since(t0);
    vertices = dt.number_of_vertices();
  }
  if (vertices == 0 && !points.empty()) throw GeometryError("Delaunay failed");
  return s;
}

}  // namespace cadmedial
