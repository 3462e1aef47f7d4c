#include "medial_axis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <set>
#include <unordered_map>

#include "../errors.h"
#include "delaunay_3.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <CGAL/spatial_sort.h>
#include <CGAL/property_map.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>

namespace cadmedial {

using namespace internal;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Point3& a) { return std::sqrt(dot(a, a)); }

std::pair<Point3, Point3> bounding_box(const std::vector<Point3>& pts) {
  Point3 lo = pts.empty() ? Point3{0, 0, 0} : pts[0], hi = lo;
  for (const Point3& p : pts)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  return {lo, hi};
}

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

// Section 3: does Delaunay edge pq pass the Angle or the Ratio condition at p's umbrella?
class Selection {
 public:
  Selection(const Samples& s, const Umbrellas& u, const MedialParams& params)
      : s_(s), u_(u), sin_theta_(std::sin(params.theta_deg * 3.14159265358979323846 / 180.0)), rho_(params.rho) {
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

  bool passes(int p, int q) const {
    const int begin = u_.start[p], end = u_.start[p + 1];
    if (begin == end) return false;
    const Point3 d = sub(s_.points[q], s_.points[p]);
    const double len = norm(d);
    if (len <= 0) return false;
    // Ratio [rho]: |pq| / R_ptu > rho for every umbrella triangle.
    if (len > rho_ * max_radius_[p]) return true;
    // Angle [theta]: the acute angle between n_ptu and pq is below pi/2 - theta for every
    // umbrella triangle, i.e. |cos| > sin(theta).
    const double bound = sin_theta_ * len;
    for (int k = begin; k < end; ++k)
      if (std::abs(dot(normals_[k], d)) <= bound) return false;
    return true;
  }
  // 4.2.6 line 6: either endpoint may pass.
  bool selected(int p, int q) const { return passes(p, q) || passes(q, p); }

 private:
  const Samples& s_;
  const Umbrellas& u_;
  double sin_theta_, rho_;
  std::vector<Point3> normals_;
  std::vector<double> max_radius_;
};

// 4.2.6 lines 5-8: the bounded Voronoi facets dual to selected Delaunay edges. Unbounded facets
// belong to the outer medial axis (4.2.5) and are not kept.
void select_facets(const Delaunay& dt, const Selection& sel, MedialComplex& mc, MedialAxisStats& st,
                   const Progress& progress) {
  std::vector<int> face;
  size_t count = 0;
  const size_t total = 7 * dt.number_of_vertices();  // about; counting the edges is a full pass
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e, ++count) {
    if (count % 65536 == 0) report(progress, "selection", static_cast<double>(count) / std::max<size_t>(1, total));
    const int p = e->first->vertex(e->second)->info(), q = e->first->vertex(e->third)->info();
    if (!sel.selected(p, q)) continue;
    ++st.selected_facets;
    face.clear();
    bool bounded = true;
    auto cc = dt.incident_cells(*e), done = cc;
    do {
      if (dt.is_infinite(cc)) {
        bounded = false;
        break;
      }
      face.push_back(mc.cell_id(cc));
    } while (++cc != done);
    if (bounded && face.size() >= 3) mc.add(face, FaceKind::Voronoi, {p, q});
  }
}

// 4.2.2 ProcConvexEdges: triangle s v1 v2 for the Voronoi edge dual to each triplet triangle,
// and the fill triangles s s' v where v is a Voronoi vertex of s' too.
void complete_convex_edges(const Delaunay& dt, const std::vector<Vertex>& handle, const Samples& samples,
                           MedialComplex& mc, MedialAxisStats& st) {
  std::set<std::array<int, 3>> fills;
  for (const Triplet& t : samples.triplets) {
    Vertex vs = handle[t.s], vl = handle[t.sl], vr = handle[t.sr];
    if (vs == Vertex() || vl == Vertex() || vr == Vertex()) continue;
    Cell c;
    int i, j, k;
    if (!dt.is_facet(vs, vl, vr, c, i, j, k)) continue;  // the sampling did not make it Delaunay
    const Cell n = c->neighbor(6 - i - j - k);
    if (dt.is_infinite(c) || dt.is_infinite(n)) continue;
    const int v1 = mc.cell_id(c), v2 = mc.cell_id(n);
    mc.add({MedialComplex::sample_node(t.s), v1, v2}, FaceKind::Edge);
    ++st.edge_triangles;
    for (int nb : {t.prev, t.next}) {
      if (nb < 0 || handle[nb] == Vertex()) continue;
      for (const Cell& cell : {c, n}) {
        // v in V_s' means s' is among v's nearest samples; with cospherical samples that need
        // not make s' a vertex of this very cell, so ask the distance.
        const int id = mc.cell_id(cell);
        const double to_nb = norm(sub(mc.centers[id], samples.points[nb]));
        if (!cell->has_vertex(handle[nb]) && std::abs(to_nb - mc.radii[id]) > 1e-9 * mc.radii[id]) continue;
        std::array<int, 3> key{std::min(t.s, nb), std::max(t.s, nb), mc.cell_id(cell)};
        if (!fills.insert(key).second) continue;
        mc.add({MedialComplex::sample_node(t.s), MedialComplex::sample_node(nb), mc.cell_id(cell)}, FaceKind::Edge);
        ++st.edge_triangles;
      }
    }
  }
}

// 4.2.3 ProcNonconcaveCorners: join corner p to each Voronoi edge of V_p on the medial axis whose
// incident facets of V_p are all unselected. The Voronoi edge dual to Delaunay triangle pab lies
// on facets dual to pa, pb and ab; so it is joined when ab is selected and pa, pb are not.
void complete_corners(const Delaunay& dt, const std::vector<Vertex>& handle, const Samples& samples,
                      const Selection& sel, MedialComplex& mc, MedialAxisStats& st) {
  std::vector<Delaunay::Facet> facets;
  for (size_t p = 0; p < samples.size(); ++p) {
    if (samples.tag[p] != SampleTag::Corner || !samples.nonconcave[p] || handle[p] == Vertex()) continue;
    facets.clear();
    dt.finite_incident_facets(handle[p], std::back_inserter(facets));
    for (const auto& [c, i] : facets) {
      int ab[2], k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i && c->vertex(j) != handle[p]) ab[k++] = c->vertex(j)->info();
      if (k != 2) continue;
      if (!sel.selected(ab[0], ab[1]) || sel.selected(static_cast<int>(p), ab[0]) ||
          sel.selected(static_cast<int>(p), ab[1]))
        continue;
      const Cell n = c->neighbor(i);
      if (dt.is_infinite(c) || dt.is_infinite(n)) continue;
      mc.add({MedialComplex::sample_node(static_cast<int>(p)), mc.cell_id(c), mc.cell_id(n)}, FaceKind::Corner);
      ++st.corner_triangles;
    }
  }
}

// 4.2.5 with the exact solid at hand. A Voronoi vertex x is the centre of a ball through its
// cell's samples p that holds no sample. Each sample votes with the side of its face's tangent
// plane that x lies on (at a sharp edge, the two faces' half-spaces: inside both for convex,
// either for concave). A vote counts only when x clears the plane by more than the surface can
// bend within |x - p| (kappa |x - p|^2 / 2); the empty ball keeps other sheets of the surface
// from passing between p and x unless the sampling missed them. Vertices with a dissenting vote
// or none go to the exact B-rep classifier; vertices beyond the samples' box or with a ball
// larger than it are outside.
int vote(const Samples& samples, int s, const Point3& x) {
  const Point3 d = sub(x, samples.points[s]);
  const double r2 = dot(d, d);
  const double margin = 0.5 * samples.curvature[s] * r2 + 1e-12 * std::sqrt(r2);
  const SampleTag tag = samples.tag[s];
  const bool on_edge = tag == SampleTag::Edge || tag == SampleTag::Ball;
  if (tag == SampleTag::Face || tag == SampleTag::Triplet || (on_edge && samples.edge_convex[s] == 0)) {
    const double a = dot(d, samples.normal[s]);
    if (dot(samples.normal[s], samples.normal[s]) == 0) return 0;
    return a < -margin ? 1 : a > margin ? -1 : 0;
  }
  if (on_edge) {
    const double a1 = dot(d, samples.normal[s]), a2 = dot(d, samples.normal2[s]);
    const bool in1 = a1 < -margin, in2 = a2 < -margin, out1 = a1 > margin, out2 = a2 > margin;
    if (samples.edge_convex[s] == 1) return (in1 && in2) ? 1 : (out1 || out2) ? -1 : 0;
    return (in1 || in2) ? 1 : (out1 && out2) ? -1 : 0;
  }
  return 0;
}

// The face-by-face reconstruction is a closed triangle mesh within its sag of the true surface.
// A point farther from it than that sag, whose nearest mesh point lies inside a triangle, is on
// the side of that triangle's outward normal: inside (1), outside (0), or undecided (-1).
class ReconstructionSide {
 public:
  ReconstructionSide(const Samples& s, const Umbrellas& u) : s_(s) {
    tris_.reserve(u.triangles.size());
    for (const auto& t : u.triangles) {
      tris_.emplace_back(point(t[0]), point(t[1]), point(t[2]));
      ids_.push_back(t);
    }
    tree_.insert(tris_.begin(), tris_.end());
    if (!tris_.empty()) tree_.accelerate_distance_queries();
  }

  int side(const Point3& x) const {
    if (tris_.empty()) return -1;
    const K::Point_3 q(x[0], x[1], x[2]);
    const auto [closest, it] = tree_.closest_point_and_primitive(q);
    const std::size_t t = static_cast<std::size_t>(it - tris_.begin());
    const auto& tri = tris_[t];
    const K::Vector_3 n = CGAL::cross_product(tri[1] - tri[0], tri[2] - tri[0]);
    const double n_len = std::sqrt(n.squared_length());
    if (n_len <= 0) return -1;
    // Outward: agree with the samples' exact normals.
    Point3 avg{0, 0, 0};
    double sag = 0, edge2 = 0;
    for (int k = 0; k < 3; ++k) {
      const int v = ids_[t][k];
      for (int c = 0; c < 3; ++c) avg[c] += s_.normal[v][c];
      sag = std::max(sag, static_cast<double>(s_.curvature[v]));
      edge2 = std::max(edge2, (tri[(k + 1) % 3] - tri[k]).squared_length());
    }
    const double orient = avg[0] * n.x() + avg[1] * n.y() + avg[2] * n.z();
    if (orient == 0) return -1;
    sag = sag * edge2 / 8.0 + 1e-12 * std::sqrt(edge2);
    const K::Vector_3 d = q - closest;
    const double dist = std::sqrt(d.squared_length());
    const double along = (d * n) / n_len * (orient > 0 ? 1 : -1);
    // The nearest point is interior to the triangle when d runs along its normal.
    if (dist <= sag || std::abs(along) < 0.999 * dist) return -1;
    return along < 0 ? 1 : 0;
  }

 private:
  K::Point_3 point(int i) const { return {s_.points[i][0], s_.points[i][1], s_.points[i][2]}; }
  using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  const Samples& s_;
  std::vector<K::Triangle_3> tris_;
  std::vector<std::array<int, 3>> ids_;
  Tree tree_;
};

std::vector<std::uint8_t> label_inside(const MedialComplex& mc, const Samples& samples, const Umbrellas& umbrellas,
                                       const InsideTest& inside, MedialAxisStats& st) {
  const size_t n = mc.cells.size();
  std::vector<std::uint8_t> label(n, 0);
  std::vector<int> unsure;
  std::vector<char> used(n, 0);
  for (int node : mc.nodes)
    if (node >= 0) used[node] = 1;
  for (int node : mc.points) used[node] = 1;
  const auto [lo, hi] = bounding_box(samples.points);
  const double diag = norm(sub(hi, lo));
  for (size_t id = 0; id < n; ++id) {
    if (!used[id]) continue;
    const Point3& x = mc.centers[id];
    bool beyond = mc.radii[id] > diag;
    for (int k = 0; k < 3; ++k) beyond = beyond || x[k] < lo[k] || x[k] > hi[k];
    if (beyond) continue;  // label 0
    int in = 0, out = 0;
    for (int j = 0; j < 4; ++j) {
      const int v = vote(samples, mc.cells[id]->vertex(j)->info(), x);
      in += v > 0;
      out += v < 0;
    }
    // Inside needs two agreeing votes: a wrong "inside" leaves a vertex out in the open.
    if (in >= 2 && out == 0)
      label[id] = 1;
    else if (out >= 1 && in == 0)
      label[id] = 0;
    else
      unsure.push_back(static_cast<int>(id));
  }
  if (!unsure.empty()) {
    // Then the reconstruction mesh; what it cannot settle goes to the exact B-rep classifier.
    const ReconstructionSide mesh(samples, umbrellas);
    std::vector<int> still;
    for (int id : unsure) {
      const int side = mesh.side(mc.centers[id]);
      if (side < 0)
        still.push_back(id);
      else
        label[id] = static_cast<std::uint8_t>(side);
    }
    unsure.swap(still);
  }
  if (!unsure.empty()) {
    std::vector<Point3> pts;
    pts.reserve(unsure.size());
    for (int id : unsure) pts.push_back(mc.centers[id]);
    const std::vector<std::uint8_t> exact = inside(pts);
    for (size_t k = 0; k < unsure.size(); ++k) label[unsure[k]] = exact[k];
    st.exact_inside_tests += unsure.size();
  }
  return label;
}

// Cospherical samples (regular edge samples and their triplets form right prisms, which are
// inscribed in spheres) give several Delaunay cells with one circumcentre: the true Voronoi
// diagram has a single vertex there. Merging them removes zero-length Voronoi edges, which would
// otherwise leave pinholes wherever the perturbation picked one selected facet over another.
void merge_coincident_cells(const Delaunay& dt, MedialComplex& mc, double eps) {
  const size_t n = mc.cells.size();
  // Cells that share a circumcentre come from one cospherical set of samples, so they are
  // adjacent in the triangulation (possibly through cells no face uses): walk neighbours.
  std::vector<int> rep(n, -1);
  std::vector<Cell> stack;
  for (size_t id = 0; id < n; ++id) {
    if (rep[id] >= 0) continue;
    rep[id] = static_cast<int>(id);
    const Point3 c = mc.centers[id];
    const int mark = static_cast<int>(id) + 1;
    mc.cells[id]->info().visit = mark;
    stack.assign(1, mc.cells[id]);
    while (!stack.empty()) {
      const Cell cell = stack.back();
      stack.pop_back();
      for (int i = 0; i < 4; ++i) {
        const Cell nb = cell->neighbor(i);
        if (nb->info().visit == mark || dt.is_infinite(nb)) continue;
        Point3 x;
        if (nb->info().id >= 0) {
          x = mc.centers[nb->info().id];
        } else {
          const K::Point_3 p = CGAL::circumcenter(nb->vertex(0)->point(), nb->vertex(1)->point(),
                                                  nb->vertex(2)->point(), nb->vertex(3)->point());
          x = {p.x(), p.y(), p.z()};
        }
        if (!(norm(sub(x, c)) <= eps)) continue;  // also for the NaN centre of a flat cell
        nb->info().visit = mark;
        if (nb->info().id >= 0) rep[nb->info().id] = static_cast<int>(id);
        stack.push_back(nb);
      }
    }
  }
  // The merged vertex takes the smallest of its members' positions: CGAL visits edges in an order
  // that depends on memory addresses, so "the first member" would differ from run to run.
  for (size_t id = 0; id < n; ++id) {
    const int r = rep[id];
    if (r != static_cast<int>(id) && mc.centers[id] < mc.centers[r]) {
      mc.centers[r] = mc.centers[id];
      mc.radii[r] = mc.radii[id];
    }
  }
  std::vector<int> group_size(n, 0);
  for (size_t id = 0; id < n; ++id) ++group_size[rep[id]];
  // Rewrite faces: drop repeated corners, then faces left with fewer than three, then duplicates.
  std::vector<int> start{0}, nodes;
  std::vector<FaceKind> kind;
  std::vector<std::array<int, 2>> dual;
  std::set<std::vector<int>> seen;
  std::vector<int> face, key_nodes;
  for (size_t f = 0; f < mc.size(); ++f) {
    face.clear();
    for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) {
      const int node = mc.nodes[k] >= 0 ? rep[mc.nodes[k]] : mc.nodes[k];
      if (face.empty() || face.back() != node) face.push_back(node);
    }
    while (face.size() > 1 && face.front() == face.back()) face.pop_back();
    // A sphere's facets all shrink to its centre: keep the point.
    if (face.size() == 1 && face[0] >= 0) mc.points.push_back(face[0]);
    if (face.size() < 3) continue;
    // Only faces with a corner in a merged group can repeat one or duplicate another face.
    bool merged = false;
    for (int k = mc.start[f]; k < mc.start[f + 1] && !merged; ++k)
      merged = mc.nodes[k] >= 0 && group_size[rep[mc.nodes[k]]] > 1;
    if (merged) {
      key_nodes = face;
      std::sort(key_nodes.begin(), key_nodes.end());
      if (std::unique(key_nodes.begin(), key_nodes.end()) != key_nodes.end()) continue;
      if (!seen.insert(key_nodes).second) continue;
    }
    nodes.insert(nodes.end(), face.begin(), face.end());
    start.push_back(static_cast<int>(nodes.size()));
    kind.push_back(mc.kind[f]);
    dual.push_back(mc.dual[f]);
  }
  mc.dual = std::move(dual);
  mc.start = std::move(start);
  mc.nodes = std::move(nodes);
  mc.kind = std::move(kind);
}

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Keeps faces whose Voronoi vertices are all inside, then the largest connected piece (the inner
// medial axis of a connected solid is connected, homotopy equivalent to the solid) and any other
// piece that reaches the boundary.
MedialMesh extract_inner(const MedialComplex& mc, const std::vector<std::uint8_t>& inside, const Samples& samples,
                         int solid_index, MedialAxisStats& st) {
  std::vector<int> kept;
  for (size_t f = 0; f < mc.size(); ++f) {
    bool in = true;
    for (int k = mc.start[f]; k < mc.start[f + 1] && in; ++k)
      if (mc.nodes[k] >= 0 && !inside[mc.nodes[k]]) in = false;
    if (in) kept.push_back(static_cast<int>(f));
  }
  // Union-find over faces sharing a node.
  std::unordered_map<int, int> node_owner;
  std::vector<int> parent(kept.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < kept.size(); ++i) {
    const int f = kept[i];
    for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) {
      auto [it, fresh] = node_owner.emplace(mc.nodes[k], static_cast<int>(i));
      if (!fresh) parent[find_root(parent, static_cast<int>(i))] = find_root(parent, it->second);
    }
  }
  // Pieces: faces, and faces that reach the boundary (completion triangles at convex edges and
  // corners). A stray piece floats inside; a piece that reaches the boundary is medial axis that
  // a too coarse sampling cut off from the rest (a neck thinner than the spacing): it is kept.
  std::unordered_map<int, std::pair<int, int>> piece;  // root -> (faces, completion faces)
  for (size_t i = 0; i < kept.size(); ++i) {
    auto& p = piece[find_root(parent, static_cast<int>(i))];
    ++p.first;
    p.second += mc.kind[kept[i]] != FaceKind::Voronoi;
  }
  st.components = piece.size();
  int best = -1, best_size = 0;
  for (const auto& [root, p] : piece)
    if (p.first > best_size || (p.first == best_size && root < best)) best = root, best_size = p.first;
  std::set<int> keep{best};
  for (const auto& [root, p] : piece)
    if (p.second >= 8 && p.first >= best_size / 100) keep.insert(root);

  MedialMesh mesh;
  std::unordered_map<int, int> out_index;
  std::vector<int> poly;
  for (size_t i = 0; i < kept.size(); ++i) {
    if (!keep.count(find_root(parent, static_cast<int>(i)))) continue;
    const int f = kept[i];
    poly.clear();
    for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) {
      const int node = mc.nodes[k];
      auto [it, fresh] = out_index.emplace(node, static_cast<int>(mesh.vertices.size()));
      if (fresh) {
        if (node >= 0) {
          mesh.vertices.push_back(mc.centers[node]);
          mesh.radius.push_back(mc.radii[node]);
        } else {
          mesh.vertices.push_back(samples.points[-node - 1]);
          mesh.radius.push_back(0.0);  // a sample on the boundary: its medial ball has radius 0
        }
      }
      poly.push_back(it->second);
    }
    mesh.add_face(poly, mc.kind[f], solid_index);
  }
  // A medial axis that is a point (a sphere's centre) has no faces: keep its vertex.
  if (mesh.num_faces() == 0) {
    for (int node : mc.points) {
      if (!inside[node] || !out_index.emplace(node, static_cast<int>(mesh.vertices.size())).second) continue;
      mesh.vertices.push_back(mc.centers[node]);
      mesh.radius.push_back(mc.radii[node]);
    }
  }
  st.dropped_faces = mc.size() - mesh.num_faces();
  return mesh;
}

}  // namespace

MedialMesh medial_axis(const Samples& samples, const Umbrellas& umbrellas, const MedialParams& params,
                       const InsideTest& inside, int solid_index, MedialAxisStats* stats_out,
                       const Progress& progress) {
  MedialAxisStats st;
  auto t0 = Clock::now();
  Delaunay dt;
  std::vector<Vertex> handle(samples.size());
  {
    // CGAL's spatial sort (Hilbert curve over a BRIO shuffle with its own fixed seed), as its
    // range insert does, but keeping each sample's index.
    std::vector<K::Point_3> pts;
    pts.reserve(samples.size());
    for (const Point3& p : samples.points) pts.emplace_back(p[0], p[1], p[2]);
    std::vector<std::size_t> order(pts.size());
    std::iota(order.begin(), order.end(), 0);
    using Traits = CGAL::Spatial_sort_traits_adapter_3<K, CGAL::Pointer_property_map<K::Point_3>::type>;
    CGAL::spatial_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(pts)));
    Vertex hint;
    for (std::size_t i : order) {
      const Vertex v = dt.insert(pts[i], hint == Vertex() ? Cell() : hint->cell());
      // A sample that coincides with another keeps no vertex of its own.
      if (v->info() < 0 || v->info() == static_cast<int>(i)) {
        v->info() = static_cast<int>(i);
        handle[i] = v;
      }
      hint = v;
    }
  }
  st.timings.push_back({"delaunay", seconds_since(t0)});
  report(progress, "selection", 0.0);

  t0 = Clock::now();
  const Umbrellas pole_umbrellas = params.plain_medial ? umbrellas_from_poles(dt, samples.size()) : Umbrellas();
  const Selection sel(samples, params.plain_medial ? pole_umbrellas : umbrellas, params);
  MedialComplex mc;
  select_facets(dt, sel, mc, st, progress);
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
    merge_coincident_cells(dt, mc, 1e-9 * norm(sub(hi, lo)));
  }
  const std::vector<std::uint8_t> in = label_inside(mc, samples, umbrellas, inside, st);
  MedialMesh mesh = extract_inner(mc, in, samples, solid_index, st);
  st.timings.push_back({"inner", seconds_since(t0)});
  if (stats_out) *stats_out = st;
  return mesh;
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
