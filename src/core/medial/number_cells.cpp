#include "number_cells.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <CGAL/Mpzf.h>

#include "geometry_3.h"
#include "prefetch.h"

#include "../two_cores.h"

namespace cadmedial::internal {

namespace {

// mc's samples and neighbours of the cells with ids in [begin, end). An infinite neighbour has
// id -1: number_cells numbers only the finite cells, and CGAL constructs every cell with a
// default CellData, so its id need not be asked by comparing its vertices with the infinite one.
void fill_cells(const std::vector<Cell>& cells, MedialComplex& mc, std::size_t begin, std::size_t end) {
  for (std::size_t id = begin; id < end; ++id) {
    // A cell ahead, then its vertices and neighbours once the cell is in.
    if (id + 2 * kPrefetchAhead < end) prefetch(*cells[id + 2 * kPrefetchAhead]);
    if (id + kPrefetchAhead < end) {
      const Cell& next = cells[id + kPrefetchAhead];
      for (int j = 0; j < 4; ++j) prefetch(*next->vertex(j)), prefetch(*next->neighbor(j));
    }
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
  mc.flat.resize(nc);
  mc.surely_outside.resize(nc);
  mc.voted.resize(nc);
  // Half the cells each on two cores: the reads wander over CGAL's cells.
  on_two_halves(nc, [&](int, std::size_t begin, std::size_t end) { fill_cells(cells, mc, begin, end); });
}

void cell_centers(const std::vector<Point3>& points, MedialComplex& mc, std::size_t begin, std::size_t end) {
  // From the flat arrays, not CGAL's cells: the same doubles (a vertex's point is its sample's),
  // read from 1.6 MB of points rather than half a million scattered cells.
  auto point = [&points](int s) { return K::Point_3(points[s][0], points[s][1], points[s][2]); };
  for (std::size_t id = begin; id < end; ++id) {
    if (id + kPrefetchAhead < end)
      for (const int s : mc.cell_samples[id + kPrefetchAhead]) prefetch(points[s]);
    const std::array<int, 4>& v = mc.cell_samples[id];
    // Coplanar to rounding (the volume the samples span against the cube of the longest edge):
    // the circumcentre below is noise along the axis of their circle (settle_flat_cells).
    {
      const Point3 &a = points[v[0]], &b = points[v[1]], &c = points[v[2]], &d = points[v[3]];
      const Point3 ab = sub(b, a), ac = sub(c, a), ad = sub(d, a), bc = sub(c, b), bd = sub(d, b), cd = sub(d, c);
      const double l2 = std::max({dot(ab, ab), dot(ac, ac), dot(ad, ad), dot(bc, bc), dot(bd, bd), dot(cd, cd)});
      mc.flat[id] = std::abs(dot(ab, cross(ac, ad))) <= 1e-10 * l2 * std::sqrt(l2);
    }
    const K::Point_3 p[4] = {point(v[0]), point(v[1]), point(v[2]), point(v[3])};
    const K::Point_3 x = CGAL::circumcenter(p[0], p[1], p[2], p[3]);
    mc.centers[id] = {x.x(), x.y(), x.z()};
    // The smallest of the four distances: the same whichever vertex CGAL stores first.
    double r2 = CGAL::squared_distance(x, p[0]);
    for (int k = 1; k < 4; ++k) r2 = std::min(r2, CGAL::squared_distance(x, p[k]));
    mc.radii[id] = std::sqrt(r2);
  }
}

namespace {

// The circumcentre a + n / m, n = |u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v), m = 2 u.(v x w)
// for u = b - a, v = c - a, w = d - a: n and m exact (CGAL's Mpzf adds and multiplies doubles
// exactly), rounded once each before the division.
Point3 exact_circumcenter(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  using E = CGAL::Mpzf;
  using V = std::array<E, 3>;
  auto diff = [&a](const Point3& p) { return V{E(p[0]) - E(a[0]), E(p[1]) - E(a[1]), E(p[2]) - E(a[2])}; };
  auto cross_e = [](const V& x, const V& y) {
    return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  auto dot_e = [](const V& x, const V& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const V u = diff(b), v = diff(c), w = diff(d);
  const V vw = cross_e(v, w), wu = cross_e(w, u), uv = cross_e(u, v);
  const E uu = dot_e(u, u), vv = dot_e(v, v), ww = dot_e(w, w);
  const double m = 2.0 * CGAL::to_double(dot_e(u, vw));
  Point3 x;
  for (int k = 0; k < 3; ++k) x[k] = a[k] + CGAL::to_double(uu * vw[k] + vv * wu[k] + ww * uv[k]) / m;
  return x;
}

// Whether a neighbour's sample that is not one of the cell's lies strictly inside the cell's
// ball (an exact Delaunay cell's ball holds none).
bool ball_holds_a_sample(const std::vector<Point3>& points, const MedialComplex& mc, std::size_t id) {
  const std::array<int, 4>& v = mc.cell_samples[id];
  for (int n : mc.cell_neighbors[id]) {
    if (n < 0) continue;
    for (int s : mc.cell_samples[n])
      if (s != v[0] && s != v[1] && s != v[2] && s != v[3] &&
          norm(sub(points[s], mc.centers[id])) < mc.radii[id] * (1.0 - 1e-9))
        return true;
  }
  return false;
}

}  // namespace

std::size_t settle_flat_cells(const std::vector<Point3>& points, MedialComplex& mc) {
  auto point = [&points](int s) { return K::Point_3(points[s][0], points[s][1], points[s][2]); };
  // Per half of the cells: the exactly coplanar ones, listed; the others recomputed exactly.
  std::vector<int> flat, flat_upper;
  std::size_t moved = 0, moved_upper = 0;
  on_two_halves(mc.num_cells(), [&](int part, std::size_t begin, std::size_t end) {
    std::vector<int>& coplanar = part ? flat_upper : flat;
    std::size_t& recomputed = part ? moved_upper : moved;
    for (std::size_t id = begin; id < end; ++id) {
      if (!mc.flat[id]) continue;
      const std::array<int, 4>& v = mc.cell_samples[id];
      // Samples on a plane normal to an axis share that coordinate: coplanar, no predicate needed.
      bool shared = false;
      for (int k = 0; k < 3 && !shared; ++k)
        shared = points[v[0]][k] == points[v[1]][k] && points[v[0]][k] == points[v[2]][k] && points[v[0]][k] == points[v[3]][k];
      const K::Point_3 p[4] = {point(v[0]), point(v[1]), point(v[2]), point(v[3])};
      if (shared || CGAL::orientation(p[0], p[1], p[2], p[3]) == CGAL::COPLANAR) {
        coplanar.push_back(static_cast<int>(id));
        continue;
      }
      // Not quite coplanar (a sliver): its centre exists. Rounding moved the one computed in
      // doubles where it is not equally far from the four samples (off the circle's axis), or
      // where a neighbour's far sample is inside its ball (along the axis past the neighbours'
      // centres): then it is computed exactly, and rounded once.
      mc.flat[id] = 0;
      double lo = 1e300, hi = 0;
      for (int k = 0; k < 4; ++k) {
        const double d = norm(sub(points[v[k]], mc.centers[id]));
        lo = std::min(lo, d), hi = std::max(hi, d);
      }
      if (!(hi - lo > 1e-6 * hi) && !ball_holds_a_sample(points, mc, id)) continue;
      const Point3 c = exact_circumcenter(points[v[0]], points[v[1]], points[v[2]], points[v[3]]);
      double r = norm(sub(points[v[0]], c));
      for (int k = 1; k < 4; ++k) r = std::min(r, norm(sub(points[v[k]], c)));
      mc.centers[id] = c;
      mc.radii[id] = r;
      ++recomputed;
    }
  }, 65536);
  flat.insert(flat.end(), flat_upper.begin(), flat_upper.end());
  moved += moved_upper;
  // Coplanar samples of a Delaunay cell lie on one circle (two rows of samples at one spacing
  // along a straight edge of a planar face make many). Their Voronoi facets meet along the part
  // of the circle's axis between the cell's neighbours' centres, each of whose balls passes
  // through three of them and the fourth: the cell takes the centre of its neighbour with the
  // smallest ball (an end of that part). A neighbour settled so counts in the next round.
  for (bool changed = true; changed;) {
    changed = false;
    for (int& id : flat) {
      if (id < 0) continue;
      int best = -1;
      for (int n : mc.cell_neighbors[id])
        if (n >= 0 && !mc.flat[n] && (best < 0 || mc.radii[n] < mc.radii[best])) best = n;
      if (best < 0) continue;
      mc.centers[id] = mc.centers[best];
      mc.radii[id] = mc.radii[best];
      mc.flat[id] = 0;
      id = -1;
      ++moved;
      changed = true;
    }
  }
  return moved;
}

}  // namespace cadmedial::internal
