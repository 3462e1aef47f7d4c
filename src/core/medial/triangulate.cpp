#include "triangulate.h"

#include <utility>

#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

namespace cadmedial::internal {

void triangulate(const Samples& samples, Delaunay& dt, std::vector<Vertex>& handle, std::vector<int>& rank,
                 const Progress& progress, const std::string& stage, const std::atomic<bool>* give_up) {
  handle.assign(samples.size(), Vertex());
  rank.assign(samples.size(), -1);
  // CGAL's spatial sort (Hilbert curve over a BRIO shuffle with its own fixed seed), as its range
  // insert does, but keeping each sample's index beside its point (sorting indices into the
  // points instead was a fifth slower, and the insertion then read the points out of order).
  // With SpatialSortPolicy (delaunay_3.h): 3 % slower on NIST FTC 11's samples, faster on most.
  using Item = std::pair<K::Point_3, int>;
  std::vector<Item> order;
  order.reserve(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Point3& p = samples.points[i];
    order.emplace_back(K::Point_3(p[0], p[1], p[2]), static_cast<int>(i));
  }
  using Traits = CGAL::Spatial_sort_traits_adapter_3<K, CGAL::First_of_pair_property_map<Item>>;
  CGAL::spatial_sort(order.begin(), order.end(), Traits(), SpatialSortPolicy());
  Vertex hint;
  std::size_t done = 0;
  for (const auto& [point, i] : order) {
    rank[i] = static_cast<int>(done);
    // Cancelling must not wait for the whole triangulation (3 s at 250k samples).
    if (++done % 16384 == 0) report(progress, stage, static_cast<double>(done) / order.size());
    // Giving up (another thread found the samples must change) is checked more often: about
    // every millisecond.
    if (give_up && done % 128 == 0 && give_up->load(std::memory_order_relaxed)) throw Cancelled();
    const Vertex v = dt.insert(point, hint == Vertex() ? Cell() : hint->cell());
    // A sample that coincides with another keeps no vertex of its own.
    if (v->info() < 0 || v->info() == i) {
      v->info() = i;
      handle[i] = v;
    }
    hint = v;
  }
}

}  // namespace cadmedial::internal
