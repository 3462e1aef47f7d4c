#include "select_facets.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry_3.h"
#include "prefetch.h"
#include "../two_cores.h"

namespace cadmedial::internal {

namespace {

// Unit normal and circumradius of every umbrella triangle.
struct TriangleGeometry {
  std::vector<Point3> normal;
  std::vector<double> radius;
};

TriangleGeometry triangle_geometry(const Samples& samples, const Umbrellas& umbrellas) {
  TriangleGeometry g;
  g.normal.resize(umbrellas.triangles.size());
  g.radius.resize(umbrellas.triangles.size());
  for (size_t t = 0; t < umbrellas.triangles.size(); ++t) {
    const auto& tri = umbrellas.triangles[t];
    const Point3 &a = samples.points[tri[0]], &b = samples.points[tri[1]], &c = samples.points[tri[2]];
    const Point3 ab = sub(b, a), ac = sub(c, a), bc = sub(c, b);
    const Point3 n = cross(ab, ac);
    const double area2 = norm(n);
    g.normal[t] = area2 > 0 ? Point3{n[0] / area2, n[1] / area2, n[2] / area2} : Point3{0, 0, 0};
    // R = |ab| |ac| |bc| / (4 area) = |ab||ac||bc| / (2 |ab x ac|)
    g.radius[t] = area2 > 0 ? norm(ab) * norm(ac) * norm(bc) / (2.0 * area2) : 1e300;
  }
  return g;
}

}  // namespace

// Section 3, MEDIAL's umbrellas (for the ablation only): the pole p+ is the farthest Voronoi
// vertex of V_p (for an unbounded V_p, the average direction of its unbounded edges); U_p is the
// set of Delaunay triangles at p whose dual Voronoi edges the plane through p normal to p+ - p
// crosses.
Umbrellas umbrellas_from_poles(const Delaunay& dt, std::size_t n) {
  Umbrellas u;
  u.start.assign(n + 1, 0);
  std::vector<std::vector<int>> per_sample(n);
  std::vector<Cell> cells;
  std::vector<Delaunay::Facet> facets;
  auto center = [](const Cell& c) {
    const K::Point_3 x = CGAL::circumcenter(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                            c->vertex(3)->point());
    return K::Vector_3(x.x(), x.y(), x.z());
  };
  // Direction of the unbounded Voronoi edge dual to hull facet (c, i) of finite cell c: the
  // facet's normal pointing away from c.
  auto outward = [](const Cell& c, int i) {
    const K::Point_3 &a = c->vertex((i + 1) % 4)->point(), &b = c->vertex((i + 2) % 4)->point(),
                     &d = c->vertex((i + 3) % 4)->point();
    K::Vector_3 nrm = CGAL::cross_product(b - a, d - a);
    if (nrm * (c->vertex(i)->point() - a) > 0) nrm = -nrm;
    const double l = std::sqrt(nrm.squared_length());
    return l > 0 ? nrm / l : nrm;
  };
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    const K::Vector_3 p(v->point().x(), v->point().y(), v->point().z());
    cells.clear();
    dt.incident_cells(v, std::back_inserter(cells));
    K::Vector_3 pole(0, 0, 0), unbounded(0, 0, 0);
    double far = -1;
    bool open = false;
    for (const Cell& c : cells) {
      if (dt.is_infinite(c)) {
        const Cell finite = c->neighbor(c->index(dt.infinite_vertex()));
        unbounded = unbounded + outward(finite, finite->index(c));
        open = true;
        continue;
      }
      const K::Vector_3 x = center(c) - p;
      if (x.squared_length() > far) far = x.squared_length(), pole = x;
    }
    if (open) pole = unbounded;
    if (pole.squared_length() == 0) continue;
    facets.clear();
    dt.finite_incident_facets(v, std::back_inserter(facets));
    auto& mine = per_sample[v->info()];
    for (auto [c, i] : facets) {
      Cell other = c->neighbor(i);
      if (dt.is_infinite(c)) {  // look from the finite side
        std::swap(c, other);
        i = c->index(other);
      }
      // The dual Voronoi edge, a segment to the other circumcentre or a ray off the hull,
      // crosses the plane when its ends lie on both sides, or the ray heads for the plane.
      const double s1 = (center(c) - p) * pole;
      const bool crosses = dt.is_infinite(other) ? (s1 == 0 || (outward(c, i) * pole) * s1 < 0)
                                                 : s1 * ((center(other) - p) * pole) <= 0;
      if (!crosses) continue;
      std::array<int, 3> tri;
      int k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i) tri[k++] = c->vertex(j)->info();
      mine.push_back(static_cast<int>(u.triangles.size()));
      u.triangles.push_back(tri);
      u.face.push_back(-1);
    }
  }
  for (size_t s = 0; s < n; ++s) u.start[s + 1] = u.start[s] + static_cast<int>(per_sample[s].size());
  for (const auto& list : per_sample) u.incident.insert(u.incident.end(), list.begin(), list.end());
  return u;
}

// Section 3: the Angle and Ratio conditions at p's umbrella.
Selection::Selection(const Samples& s, const Umbrellas& u, const MedialParams& params)
    : s_(s),
      u_(u),
      sin_theta_(std::sin(params.theta_deg * 3.14159265358979323846 / 180.0)),
      rho_(params.rho),
      cos_cone_side_(std::cos(45.0 * 3.14159265358979323846 / 180.0)),
      concave_fans_(!params.plain_medial) {
  // Each sample's umbrella normals side by side, and its largest circumradius: the Ratio
  // condition against every triangle is one comparison against the largest.
  const TriangleGeometry g = triangle_geometry(s, u);
  normals_.resize(u.incident.size());
  max_radius_.assign(s.size(), 0.0);
  for (size_t p = 0; p < s.size(); ++p)
    for (int k = u.start[p]; k < u.start[p + 1]; ++k) {
      normals_[k] = g.normal[u.incident[k]];
      max_radius_[p] = std::max(max_radius_[p], g.radius[u.incident[k]]);
    }
}

// At a concave edge the inner medial balls touching p have their centres anywhere in the wedge
// between the two faces' inward normals (not along one normal): the axis leaves a concave edge as
// a fan, e.g. the sheet under a thin rib, which bisects the rib's two foot edges. Every umbrella
// triangle on the floor is tangent to pq there, so the Angle condition cannot pass; the exact
// normals from the B-rep can: pq (within theta) in the wedge, and well away from the edge's
// direction, which chords between samples along the edge are close to.
bool Selection::in_concave_cone(int p, const Point3& d, double len) const {
  if (!concave_fans_ || s_.edge_convex[p] != 2) return false;
  const Point3 &n1 = s_.normal[p], &n2 = s_.normal2[p];  // outward
  if (dot(d, n1) > sin_theta_ * len || dot(d, n2) > sin_theta_ * len) return false;
  const Point3 t = cross(n1, n2);
  const double tl = norm(t);
  return tl > sin_theta_ && std::abs(dot(d, t)) <= cos_cone_side_ * len * tl;
}

bool Selection::passes(int p, int q) const {
  const int begin = u_.start[p], end = u_.start[p + 1];
  if (begin == end) return false;
  const Point3 d = sub(s_.points[q], s_.points[p]);
  const double len = norm(d);
  if (len <= 0) return false;
  if (in_concave_cone(p, d, len)) return true;
  // Ratio [rho]: |pq| / R_ptu > rho for every umbrella triangle.
  if (len > rho_ * max_radius_[p]) return true;
  // Angle [theta]: the acute angle between n_ptu and pq is below pi/2 - theta for every
  // umbrella triangle, i.e. |cos| > sin(theta).
  const double bound = sin_theta_ * len;
  for (int k = begin; k < end; ++k)
    if (std::abs(dot(normals_[k], d)) <= bound) return false;
  return true;
}

namespace {

constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

std::uint8_t edge_bit(int i, int j) {
  static constexpr int kIndex[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};
  return static_cast<std::uint8_t>(1u << kIndex[i][j]);
}

// One thread's facets, in the order of their first cells.
struct Facets {
  std::vector<int> first;  ///< per facet: the smallest cell id around its edge
  std::vector<int> start{0};
  std::vector<int> nodes;
  std::vector<std::array<int, 2>> dual;
  std::vector<std::uint8_t> filler;
  std::vector<std::uint8_t> unbuilt_use;  ///< per cell id, as MedialComplex::unbuilt_use
  std::size_t selected = 0;
};

// A cell of the other thread's, in a thread's array of walked edges (edge bits are 1 to 32).
constexpr std::uint8_t kOthers = 0x80;

// The facets of the edges whose first cell (the smallest id around the edge, of those not surely
// outside) is one of this thread's, visited in the order of their first cells. `done` is this
// thread's own: the other thread's cells are marked kOthers in it. A walk around an edge marks the
// edge in every cell on the way; an edge found from one of our cells whose walk meets an earlier
// cell (one of the other thread's) is theirs. No walk starts at a cell surely outside, and a facet
// with such a corner is not built: its other corners are marked in unbuilt_use. (Most cells are
// far outside on parts with large gently curved faces: 2.4 of 2.8 million on tail_turbine at
// 106k samples; on the Y-rod mount about half the selected facets have a corner that the votes
// put outside.) `tick(c)` before each cell: false stops.
template <class Tick>
Facets facets_of(const Selection& sel, const MedialComplex& mc, std::vector<std::uint8_t>& done, bool fillers,
                 const Tick& tick) {
  auto corner = [&](int cell, int sample) {
    const auto& v = mc.cell_samples[cell];
    return v[0] == sample ? 0 : v[1] == sample ? 1 : v[2] == sample ? 2 : 3;
  };
  Facets out;
  const int nc = static_cast<int>(mc.num_cells());
  out.unbuilt_use.assign(nc, 0);
  std::vector<int> face;
  for (int c = 0; c < nc; ++c) {
    if (!tick(c)) break;
    // The walks from a cell start into its neighbours (of this thread's cells).
    const std::size_t ahead = static_cast<std::size_t>(c) + kPrefetchAhead;
    if (ahead < static_cast<std::size_t>(nc) && !(done[ahead] & kOthers))
      for (const int nb : mc.cell_neighbors[ahead])
        if (nb >= 0) prefetch(mc.cell_samples[nb]), prefetch(mc.cell_neighbors[nb]);
    if ((done[c] & kOthers) || mc.surely_outside[c]) continue;
    for (const auto& [i, j] : kEdge) {
      if (done[c] & edge_bit(i, j)) continue;
      const int p = mc.cell_samples[c][i], q = mc.cell_samples[c][j];
      const bool selected = sel.selected(p, q);
      if (!selected && !fillers) continue;
      // Around pq in CGAL's turning sense (its cell circulator); off the hull, back the other way
      // from c to mark the rest.
      face.clear();
      bool bounded = true, first = true, unbuilt = false;
      int cur = c, ci = i, cj = j;
      do {
        face.push_back(cur);
        done[cur] |= edge_bit(ci, cj);
        unbuilt = unbuilt || mc.surely_outside[cur];
        first = first && (cur >= c || mc.surely_outside[cur]);
        const int nb = mc.cell_neighbors[cur][Delaunay::next_around_edge(ci, cj)];
        if (nb < 0) {
          bounded = false;
          break;
        }
        cur = nb, ci = corner(nb, p), cj = corner(nb, q);
      } while (cur != c);
      if (!bounded) {
        cur = c, ci = i, cj = j;
        for (int nb; (nb = mc.cell_neighbors[cur][Delaunay::next_around_edge(cj, ci)]) >= 0;) {
          cur = nb, ci = corner(nb, p), cj = corner(nb, q);
          done[cur] |= edge_bit(ci, cj);
          first = first && (cur >= c || mc.surely_outside[cur]);
        }
      }
      if (!first) continue;
      out.selected += selected;
      if (!bounded || face.size() < 3) continue;
      if (unbuilt) {
        for (int x : face) out.unbuilt_use[x] = std::max<std::uint8_t>(out.unbuilt_use[x], selected ? 2 : 1);
        continue;
      }
      out.first.push_back(c);
      out.nodes.insert(out.nodes.end(), face.begin(), face.end());
      out.start.push_back(static_cast<int>(out.nodes.size()));
      out.dual.push_back({p, q});
      out.filler.push_back(!selected);
    }
  }
  return out;
}

// Both threads' facets into mc, in the order of their first cells: the order one thread would
// have found them in.
void add_in_order(MedialComplex& mc, const Facets& a, const Facets& b) {
  const std::size_t n = a.first.size() + b.first.size();
  mc.dual.reserve(mc.dual.size() + n);
  mc.filler.reserve(mc.filler.size() + n);
  mc.kind.reserve(mc.kind.size() + n);
  mc.start.reserve(mc.start.size() + n);
  mc.nodes.reserve(mc.nodes.size() + a.nodes.size() + b.nodes.size());
  auto take = [&mc](const Facets& f, std::size_t k) {
    mc.dual.push_back(f.dual[k]);
    mc.filler.push_back(f.filler[k]);
    mc.nodes.insert(mc.nodes.end(), f.nodes.begin() + f.start[k], f.nodes.begin() + f.start[k + 1]);
    mc.start.push_back(static_cast<int>(mc.nodes.size()));
    mc.kind.push_back(FaceKind::Voronoi);
  };
  std::size_t i = 0, j = 0;
  while (i < a.first.size() || j < b.first.size()) {
    if (j == b.first.size() || (i < a.first.size() && a.first[i] < b.first[j]))
      take(a, i++);
    else
      take(b, j++);
  }
}

}  // namespace

// 4.2.6 lines 5-8: the bounded Voronoi facets dual to selected Delaunay edges. Unbounded facets
// belong to the outer medial axis (4.2.5) and are not kept. With `fillers`, the bounded facets of
// the other edges are added too, marked: the Voronoi complex inside the solid has the solid's
// homotopy type, and collapse_fillers keeps the few of them the selected axis needs for it.
// Each edge is visited once, from the first cell (in mc's order) around it: a walk around the
// edge marks it in the other cells. (CGAL's edge iterator walks around every edge of every cell
// to find the edge's first cell, and then we walked again.)
// Two threads take the cells on either side of the median plane across the samples' longest
// extent: few edges have cells on both sides, so each thread walks about half of them.
void select_facets(const Selection& sel, MedialComplex& mc, MedialAxisStats& st, const Progress& progress,
                   bool fillers, int threads) {
  const int nc = static_cast<int>(mc.num_cells());
  const std::vector<Point3>& points = sel.samples().points;
  int axis = 0;
  double split = 0;
  if (!points.empty()) {
    const auto [lo, hi] = bounding_box(points);
    for (int k = 1; k < 3; ++k)
      if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    std::vector<double> x(points.size());
    for (std::size_t s = 0; s < points.size(); ++s) x[s] = points[s][axis];
    std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
    split = x[x.size() / 2];
  }
  // Each thread's array of walked edges, with the other thread's cells marked: a cell's side is
  // its first sample's. (One shared array, or a look at the side in every step of a walk, cost
  // as much as the walks saved.)
  auto walked = [&](bool upper) {
    std::vector<std::uint8_t> done(nc);
    for (int c = 0; c < nc; ++c) done[c] = (points[mc.cell_samples[c][0]][axis] >= split) != upper ? kOthers : 0;
    return done;
  };
  auto report_every = [&](int c) {
    if (c % 65536 == 0) report(progress, "selection", static_cast<double>(c) / std::max(1, nc));
    return true;
  };
  Facets lower_facets, upper_facets;
  if (threads < 2) {
    std::vector<std::uint8_t> done(nc, 0);
    lower_facets = facets_of(sel, mc, done, fillers, report_every);
  } else {
    on_two_cores(
        [&] {
          std::vector<std::uint8_t> done = walked(false);
          lower_facets = facets_of(sel, mc, done, fillers, report_every);
        },
        [&](const std::atomic<bool>& stop) {
          std::vector<std::uint8_t> done = walked(true);
          upper_facets = facets_of(sel, mc, done, fillers, [&](int c) { return c % 16384 != 0 || !stop; });
        });
  }
  st.selected_facets += lower_facets.selected + upper_facets.selected;
  add_in_order(mc, lower_facets, upper_facets);
  mc.unbuilt_use.swap(lower_facets.unbuilt_use);
  const std::vector<std::uint8_t>& upper_use = upper_facets.unbuilt_use;
  if (upper_use.size() == mc.unbuilt_use.size())
    for (std::size_t c = 0; c < upper_use.size(); ++c)
      mc.unbuilt_use[c] = std::max(mc.unbuilt_use[c], upper_use[c]);
}

}  // namespace cadmedial::internal
