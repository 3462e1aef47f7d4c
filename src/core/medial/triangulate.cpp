#include "triangulate.h"

#include <numeric>

#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

namespace cadmedial::internal {

void triangulate(const Samples& samples, Delaunay& dt, std::vector<Vertex>& handle, std::vector<int>& rank,
                 const Progress& progress, const std::string& stage, const std::atomic<bool>* give_up) {
  handle.assign(samples.size(), Vertex());
  rank.assign(samples.size(), -1);
  // CGAL's spatial sort (Hilbert curve over a BRIO shuffle with its own fixed seed), as its range
  // insert does, but keeping each sample's index.
  std::vector<K::Point_3> pts;
  pts.reserve(samples.size());
  for (const Point3& p : samples.points) pts.emplace_back(p[0], p[1], p[2]);
  std::vector<std::size_t> order(pts.size());
  std::iota(order.begin(), order.end(), 0);
  using Traits = CGAL::Spatial_sort_traits_adapter_3<K, CGAL::Pointer_property_map<K::Point_3>::type>;
  CGAL::spatial_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(pts)));
  Vertex hint;
  std::size_t done = 0;
  for (std::size_t i : order) {
    rank[i] = static_cast<int>(done);
    // Cancelling must not wait for the whole triangulation (3 s at 250k samples).
    if (++done % 16384 == 0) report(progress, stage, static_cast<double>(done) / order.size());
    // Giving up (another thread found the samples must change) is checked more often: about
    // every millisecond.
    if (give_up && done % 128 == 0 && give_up->load(std::memory_order_relaxed)) throw Cancelled();
    const Vertex v = dt.insert(pts[i], hint == Vertex() ? Cell() : hint->cell());
    // A sample that coincides with another keeps no vertex of its own.
    if (v->info() < 0 || v->info() == static_cast<int>(i)) {
      v->info() = static_cast<int>(i);
      handle[i] = v;
    }
    hint = v;
  }
}

}  // namespace cadmedial::internal
