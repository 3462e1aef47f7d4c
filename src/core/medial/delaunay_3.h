// Internal to medial/: the CGAL Delaunay triangulation with our per-vertex and per-cell data.
#pragma once

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/hilbert_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "../types.h"

namespace cadmedial::internal {

struct CellData {
  int id = -1;  ///< the finite cell's index into MedialComplex's cell arrays (number_cells)
};

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
// Sample index; -1 until set.
struct SampleId {
  int id = -1;
  operator int() const { return id; }
  SampleId& operator=(int i) { id = i; return *this; }
};
using Vb = CGAL::Triangulation_vertex_base_with_info_3<SampleId, K>;
using Cb = CGAL::Triangulation_cell_base_with_info_3<CellData, K, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using Delaunay = CGAL::Delaunay_triangulation_3<K, Tds>;
using Cell = Delaunay::Cell_handle;
using Vertex = Delaunay::Vertex_handle;
/// The Hilbert sort's policy before insertion: boxes split at their middle, not at the points'
/// median (CGAL's default), 3 to 13 % faster on the Y-rod mount's samples (bench/README.md).
/// bench_pipeline's like-for-like yardstick sorts with it too.
using SpatialSortPolicy = CGAL::Hilbert_sort_middle_policy;

/// An allocator whose resize leaves trivially constructible elements uninitialized: number_cells
/// sizes arrays for half a million cells that two threads then fill, and zeroing them first
/// faulted in their pages on one core (20 ms at 65k samples).
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
/// A per-cell array of MedialComplex: uninitialized until written.
template <class T>
using CellArray = std::vector<T, UninitializedAllocator<T>>;

/// A value per node of a MedialComplex (cell ids and samples), in flat arrays: the inner stage
/// looks nodes up hundreds of thousands of times.
template <class T>
class NodeMap {
 public:
  NodeMap(std::size_t cells, std::size_t samples, T init) : cells_(cells, init), samples_(samples, init) {}
  T& operator[](int node) { return node >= 0 ? cells_[node] : samples_[-node - 1]; }
  const T& operator[](int node) const { return node >= 0 ? cells_[node] : samples_[-node - 1]; }
  /// Every node's value set to v (reusing the arrays: their pages are already in).
  void fill(T v) {
    std::fill(cells_.begin(), cells_.end(), v);
    std::fill(samples_.begin(), samples_.end(), v);
  }

 private:
  std::vector<T> cells_, samples_;
};

/// Faces before separation: their corners are Voronoi vertices (cells, id >= 0) or samples
/// (encoded -(sample+1)).
struct MedialComplex {
  /// The finite Delaunay cells in flat arrays (number_cells): the later stages walk around edges
  /// and across facets millions of times, and CGAL's cells lie wherever its allocator put them.
  CellArray<std::array<int, 4>> cell_samples;    ///< per cell id: its four samples
  CellArray<std::array<int, 4>> cell_neighbors;  ///< per cell id: the cell across the facet opposite each corner, -1 off the hull
  CellArray<Point3> centers;   ///< circumcentre per cell id
  CellArray<double> radii;     ///< circumradius per cell id
  CellArray<std::uint8_t> flat;  ///< per cell id: 1 while its samples are coplanar to rounding (settle_flat_cells)
  /// per cell id: 1 for a Voronoi vertex surely outside, far off (mark_far_outside) or by its
  /// samples' votes (mark_voted_outside): the facets at it are not built
  CellArray<std::uint8_t> surely_outside;
  /// per cell id: votes_settle of its samples' votes at its centre where mark_voted_outside
  /// counted them (the centre is final there: the cell merges with no neighbour), else kNotVoted;
  /// label_inside reads it rather than count them again
  CellArray<std::int8_t> voted;
  static constexpr std::int8_t kNotVoted = -2;
  /// per cell id: 2 if a facet not built (surely_outside) that was selected has it as a corner, 1 if
  /// only unselected ones do, else 0 (what label_inside would have read from those facets)
  std::vector<std::uint8_t> unbuilt_use;
  std::vector<int> start{0};     ///< CSR over nodes
  std::vector<int> nodes;
  std::vector<FaceKind> kind;
  std::vector<int> points;       ///< cells where a selected facet collapsed to a single point
  std::vector<std::array<int, 2>> dual;  ///< per face: the Delaunay edge pq of a Voronoi facet, else -1
  /// per face: 1 for a Voronoi facet that no condition selected, kept only where the axis's
  /// topology needs it (collapse_fillers)
  std::vector<std::uint8_t> filler;
  /// The Voronoi vertices of each sample that completion faces join to the axis (cells incident
  /// to it, by id), for fan_completions.
  std::vector<int> star_sample;
  std::vector<int> star_start{0};
  std::vector<int> star_cells;
  /// After merge_coincident_cells: the id each cell id was merged into, and the Voronoi facets
  /// that merged into a segment (corners, filler flag).
  std::vector<int> rep;
  std::vector<std::array<int, 3>> segments;

  /// The id number_cells gave a finite cell.
  static int cell_id(const Cell& c) { return c->info().id; }
  std::size_t num_cells() const { return centers.size(); }
  static int sample_node(int s) { return -(s + 1); }
  void add(const std::vector<int>& face_nodes, FaceKind k, std::array<int, 2> pq = {-1, -1}, bool is_filler = false) {
    dual.push_back(pq);
    filler.push_back(is_filler);
    nodes.insert(nodes.end(), face_nodes.begin(), face_nodes.end());
    start.push_back(static_cast<int>(nodes.size()));
    kind.push_back(k);
  }
  std::size_t size() const { return kind.size(); }
};

}  // namespace cadmedial::internal
