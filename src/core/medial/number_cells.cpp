#include "number_cells.h"

#include <algorithm>
#include <cmath>

#include "../two_cores.h"

namespace cadmedial::internal {

namespace {

// mc's samples and neighbours of the cells with ids in [begin, end). An infinite neighbour has
// id -1: number_cells numbers only the finite cells, and CGAL constructs every cell with a
// default CellData, so its id need not be asked by comparing its vertices with the infinite one.
void fill_cells(const std::vector<Cell>& cells, MedialComplex& mc, std::size_t begin, std::size_t end) {
  for (std::size_t id = begin; id < end; ++id) {
    const Cell& c = cells[id];
    for (int j = 0; j < 4; ++j) {
      mc.cell_samples[id][j] = c->vertex(j)->info();
      mc.cell_neighbors[id][j] = c->neighbor(j)->info().id;
    }
  }
}

}  // namespace

void number_cells(const Delaunay& dt, const std::vector<int>& rank, MedialComplex& mc) {
  // A counting sort of the cells by their earliest-inserted sample: the insertion followed a
  // Hilbert curve, so this order is spatially coherent; CGAL's container order is not (cells are
  // freed and reused during insertion). On two cores, each half of the container: a key's cells
  // from the second half go after those from the first, as in one pass. The key waits in the
  // cell's id until the cell has its id.
  const std::size_t n = rank.size(), nc = dt.number_of_finite_cells();
  std::vector<Cell> found;
  found.reserve(nc);
  for (const Cell c : dt.finite_cell_handles()) found.push_back(c);
  std::vector<int> lower(n, 0), upper(n, 0);
  auto count_keys = [&](std::size_t begin, std::size_t end, std::vector<int>& count) {
    for (std::size_t i = begin; i < end; ++i) {
      const Cell& c = found[i];
      int k = static_cast<int>(n);
      for (int j = 0; j < 4; ++j) k = std::min(k, rank[c->vertex(j)->info()]);
      c->info().id = k;
      ++count[k];
    }
  };
  on_two_halves(nc, [&](int part, std::size_t begin, std::size_t end) { count_keys(begin, end, part ? upper : lower); });
  // Where each half's next cell of a key goes.
  for (std::size_t k = 0, at = 0; k < n; ++k) {
    const int here = lower[k], there = upper[k];
    lower[k] = static_cast<int>(at);
    upper[k] = static_cast<int>(at) + here;
    at += static_cast<std::size_t>(here + there);
  }
  std::vector<Cell> cells(nc);
  auto number = [&](std::size_t begin, std::size_t end, std::vector<int>& next) {
    for (std::size_t i = begin; i < end; ++i) {
      const Cell& c = found[i];
      const int id = next[c->info().id]++;
      cells[id] = c;
      c->info().id = id;
    }
  };
  on_two_halves(nc, [&](int part, std::size_t begin, std::size_t end) { number(begin, end, part ? upper : lower); });
  mc.cell_samples.resize(nc);
  mc.cell_neighbors.resize(nc);
  mc.centers.resize(nc);
  mc.radii.resize(nc);
  // Half the cells each on two cores: the reads wander over CGAL's cells.
  on_two_halves(nc, [&](int, std::size_t begin, std::size_t end) { fill_cells(cells, mc, begin, end); });
}

void cell_centers(const std::vector<Point3>& points, MedialComplex& mc, std::size_t begin, std::size_t end) {
  // From the flat arrays, not CGAL's cells: the same doubles (a vertex's point is its sample's),
  // read from 1.6 MB of points rather than half a million scattered cells.
  auto point = [&points](int s) { return K::Point_3(points[s][0], points[s][1], points[s][2]); };
  for (std::size_t id = begin; id < end; ++id) {
    const std::array<int, 4>& v = mc.cell_samples[id];
    const K::Point_3 p[4] = {point(v[0]), point(v[1]), point(v[2]), point(v[3])};
    const K::Point_3 x = CGAL::circumcenter(p[0], p[1], p[2], p[3]);
    mc.centers[id] = {x.x(), x.y(), x.z()};
    // The smallest of the four distances: the same whichever vertex CGAL stores first.
    double r2 = CGAL::squared_distance(x, p[0]);
    for (int k = 1; k < 4; ++k) r2 = std::min(r2, CGAL::squared_distance(x, p[k]));
    mc.radii[id] = std::sqrt(r2);
  }
}

}  // namespace cadmedial::internal
