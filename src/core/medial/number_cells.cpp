#include "number_cells.h"

#include <algorithm>
#include <cmath>

namespace cadmedial::internal {

std::vector<Cell> number_cells(const Delaunay& dt, const std::vector<int>& rank, MedialComplex& mc) {
  // A counting sort of the cells by their earliest-inserted sample: the insertion followed a
  // Hilbert curve, so this order is spatially coherent; CGAL's container order is not (cells are
  // freed and reused during insertion).
  const std::size_t n = rank.size();
  std::vector<int> count(n + 1, 0);
  auto key = [&](const Cell& c) {
    int k = static_cast<int>(n);
    for (int j = 0; j < 4; ++j) k = std::min(k, rank[c->vertex(j)->info()]);
    return k;
  };
  for (const Cell c : dt.finite_cell_handles()) ++count[key(c) + 1];
  for (std::size_t k = 0; k < n; ++k) count[k + 1] += count[k];
  const std::size_t nc = dt.number_of_finite_cells();
  std::vector<Cell> cells(nc);
  for (const Cell c : dt.finite_cell_handles()) {
    const int id = count[key(c)]++;
    cells[id] = c;
    c->info().id = id;
  }
  mc.cell_samples.resize(nc);
  mc.cell_neighbors.resize(nc);
  mc.centers.resize(nc);
  mc.radii.resize(nc);
  for (std::size_t id = 0; id < nc; ++id) {
    const Cell& c = cells[id];
    for (int j = 0; j < 4; ++j) {
      mc.cell_samples[id][j] = c->vertex(j)->info();
      const Cell nb = c->neighbor(j);
      mc.cell_neighbors[id][j] = dt.is_infinite(nb) ? -1 : nb->info().id;
    }
  }
  return cells;
}

void cell_centers(const std::vector<Cell>& cells, MedialComplex& mc) {
  for (std::size_t id = 0; id < cells.size(); ++id) {
    const Cell& c = cells[id];
    const K::Point_3 x = CGAL::circumcenter(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                            c->vertex(3)->point());
    mc.centers[id] = {x.x(), x.y(), x.z()};
    // The smallest of the four distances: the same whichever vertex CGAL stores first.
    double r2 = CGAL::squared_distance(x, c->vertex(0)->point());
    for (int k = 1; k < 4; ++k) r2 = std::min(r2, CGAL::squared_distance(x, c->vertex(k)->point()));
    mc.radii[id] = std::sqrt(r2);
  }
}

}  // namespace cadmedial::internal
