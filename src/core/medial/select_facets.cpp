#include "select_facets.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry_3.h"

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

// 4.2.6 lines 5-8: the bounded Voronoi facets dual to selected Delaunay edges. Unbounded facets
// belong to the outer medial axis (4.2.5) and are not kept. With `fillers`, the bounded facets of
// the other edges are added too, marked: the Voronoi complex inside the solid has the solid's
// homotopy type, and collapse_fillers keeps the few of them the selected axis needs for it.
// Each edge is visited once, from the first cell (in mc's order) around it: a walk around the
// edge marks it in the other cells. (CGAL's edge iterator walks around every edge of every cell
// to find the edge's first cell, and then we walked again.)
void select_facets(const Selection& sel, MedialComplex& mc, MedialAxisStats& st, const Progress& progress,
                   bool fillers) {
  static constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  auto edge_bit = [](int i, int j) {
    static constexpr int kIndex[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};
    return static_cast<std::uint8_t>(1u << kIndex[i][j]);
  };
  auto corner = [&](int cell, int sample) {
    const auto& v = mc.cell_samples[cell];
    return v[0] == sample ? 0 : v[1] == sample ? 1 : v[2] == sample ? 2 : 3;
  };
  const int nc = static_cast<int>(mc.num_cells());
  std::vector<std::uint8_t> done(nc, 0);
  std::vector<int> face;
  for (int c = 0; c < nc; ++c) {
    if (c % 65536 == 0) report(progress, "selection", static_cast<double>(c) / std::max(1, nc));
    for (const auto& [i, j] : kEdge) {
      if (done[c] & edge_bit(i, j)) continue;
      const int p = mc.cell_samples[c][i], q = mc.cell_samples[c][j];
      const bool selected = sel.selected(p, q);
      if (!selected && !fillers) continue;
      st.selected_facets += selected;
      // Around pq in CGAL's turning sense (its cell circulator); off the hull, back the other way
      // from c to mark the rest.
      face.clear();
      bool bounded = true;
      int cur = c, ci = i, cj = j;
      do {
        face.push_back(cur);
        done[cur] |= edge_bit(ci, cj);
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
        }
        continue;
      }
      if (face.size() >= 3) mc.add(face, FaceKind::Voronoi, {p, q}, !selected);
    }
  }
}

}  // namespace cadmedial::internal
