#include "simplify_axis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_map>
#include <vector>

#include "../sampling/point_grid.h"
#include "ball_distance.h"
#include "triangle_complex.h"

namespace cadmedial {

namespace {

using compact::Ball;
using compact::TriangleComplex;

// How many times the whole check of a vertex's contraction may fail before it stays.
constexpr int kMaxFailures = 16;
// A triangle that a contraction turns by more than 60 degrees folds its sheet: not contracted.
constexpr double kMinNormalCos = 0.5;

std::uint64_t side_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

struct Candidate {
  double cost;
  int u, v;
  unsigned stamp;
  bool operator>(const Candidate& o) const {
    if (cost != o.cost) return cost > o.cost;
    if (u != o.u) return u > o.u;
    return v > o.v;
  }
};

// What may move a vertex: inside a sheet to any neighbour, on a border or seam only along it.
struct Role {
  bool movable = false;
  int along[2] = {-1, -1};  ///< on a border or seam: its two neighbours along it
  bool on_feature() const { return along[0] >= 0; }
};

// The full mesh's triangles and 1-D edges, found near a point: each is filed under points of it
// at most a cell apart (its vertices, its centroid and, on a large one, a lattice), so every
// piece within d of a point has a filed point within d + cell of it.
class FullMeshIndex {
 public:
  /// Cells of at least a median side and at least half the tolerance: a query within the
  /// tolerance then visits at most 7 x 7 x 7 cells (with cells of a median side, at 1 % of the
  /// diagonal on NIST FTC 11, tens of thousands: 60 s).
  FullMeshIndex(const MedialMesh& mesh, const TriangleComplex& c, double tolerance) : mesh_(mesh), grid_(1.0) {
    std::vector<double> longest;
    for (int t = 0; t < c.num_triangles(); ++t) {
      pieces_.push_back(c.triangle(t));
      longest.push_back(longest_side(pieces_.back()));
    }
    for (const auto& e : mesh.edges) {
      pieces_.push_back({e[0], e[1], e[1]});
      longest.push_back(longest_side(pieces_.back()));
    }
    std::vector<double> sorted = longest;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    median_ = sorted.empty() || !(sorted[sorted.size() / 2] > 0) ? 1.0 : sorted[sorted.size() / 2];
    cell_ = std::max(median_, 0.5 * tolerance);
    grid_ = PointGrid(cell_);
    for (std::size_t k = 0; k < pieces_.size(); ++k) {
      const int n = std::clamp(static_cast<int>(std::ceil(longest[k] / cell_)), 1, 64);
      for_lattice(pieces_[k], n, [&](const Point3& q) { grid_.insert(q, static_cast<int>(k)); });
    }
  }

  /// The median longest side of the full mesh's triangles: the checks' lattices go by it.
  double median_side() const { return median_; }

  /// Whether some piece of the full mesh is within `tol` of ball p (|dc| + |dr|).
  bool near(const Ball& p, double tol) const {
    return grid_.any_near(p.c, tol + cell_, [&](int k) {
      const auto& t = pieces_[static_cast<std::size_t>(k)];
      return compact::ball_to_triangle(p, ball(t[0]), ball(t[1]), ball(t[2])) <= tol;
    });
  }

  /// The least |dc| + |dr| from ball p to the pieces of the full mesh,
  /// looking within `reach` (beyond it: reach).
  /// Stops once it is at most `enough`.
  double excess(const Ball& p, double reach, double enough) const {
    double best = reach;
    grid_.any_near(p.c, reach + cell_, [&](int k) {
      const auto& t = pieces_[static_cast<std::size_t>(k)];
      best = std::min(best, compact::ball_to_triangle(p, ball(t[0]), ball(t[1]), ball(t[2])));
      return best <= enough;
    });
    return best;
  }

  /// Calls f(q) at the points of the lattice of triangle t with n steps a side.
  template <class F>
  void for_lattice(const std::array<int, 3>& t, int n, F&& f) const {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double a = double(i) / n, b = double(j) / n, w = 1 - a - b;
        Point3 q;
        for (int k = 0; k < 3; ++k) q[k] = a * vertex(t[0])[k] + b * vertex(t[1])[k] + w * vertex(t[2])[k];
        f(q);
      }
  }

  Ball ball(int v) const { return {vertex(v), mesh_.radius[static_cast<std::size_t>(v)]}; }
  const Point3& vertex(int v) const { return mesh_.vertices[static_cast<std::size_t>(v)]; }
  double longest_side(const std::array<int, 3>& t) const {
    double l = 0;
    for (int k = 0; k < 3; ++k) {
      const Point3 d = compact::sub(vertex(t[(k + 1) % 3]), vertex(t[k]));
      l = std::max(l, std::sqrt(compact::dot(d, d)));
    }
    return l;
  }

 private:
  const MedialMesh& mesh_;
  std::vector<std::array<int, 3>> pieces_;
  double median_ = 1.0, cell_ = 1.0;
  PointGrid grid_;
};

class Simplifier {
 public:
  Simplifier(const MedialMesh& mesh, double tolerance)
      : mesh_(mesh), tol_(tolerance), c_(mesh), full_(mesh, c_, tolerance), carried_(static_cast<std::size_t>(c_.num_triangles())),
        stamp_(mesh.num_vertices(), 0), failed_(mesh.num_vertices()), failures_(mesh.num_vertices(), 0) {}

  TriangleComplex& complex() { return c_; }

  void run(const Progress& progress) {
    report(progress, "compact", 0.0);
    for (int u = 0; u < c_.num_vertices(); ++u) push_best(u);
    std::vector<int> vanished, moved, nb;
    // Each contraction removes a vertex: their share of the vertices is a fair measure of the work.
    const double vertices = std::max(1, c_.num_vertices());
    std::size_t done = 0;
    while (!queue_.empty()) {
      if (++done % 4096 == 0) report(progress, "compact", std::min(0.99, static_cast<double>(done) / vertices));
      const Candidate top = queue_.top();
      queue_.pop();
      if (top.stamp != stamp_[static_cast<std::size_t>(top.u)] || c_.triangles_at(top.u).empty()) continue;
      Plan plan;
      if (!plan_contraction(top.u, top.v, plan)) {
        failed_[static_cast<std::size_t>(top.u)].push_back(top.v);
        // A vertex whose checks keep failing as its neighbours change is given up: on NIST FTC
        // 11 (a messy axis of thin raised letters) the retries made 1 % take 160 s.
        if (++failures_[static_cast<std::size_t>(top.u)] < kMaxFailures) push_best(top.u);
        continue;
      }
      apply(plan, vanished, moved);
      c_.neighbours(top.v, nb);
      nb.push_back(top.v);
      for (int x : nb) {
        ++stamp_[static_cast<std::size_t>(x)];
        failed_[static_cast<std::size_t>(x)].clear();
        push_best(x);
      }
    }
    thin_bare_chains();
  }

  /// The largest |dc| + |dr| from a ball of the compact mesh to the full one, on a lattice of each
  /// triangle with steps of at most a median side of the full mesh (an upper bound at each
  /// point; below half the tolerance it says only that).
  double max_containment() const {
    double e = 0;
    for (int t = 0; t < c_.num_triangles(); ++t) {
      if (!c_.alive(t)) continue;
      const auto& tr = c_.triangle(t);
      const int n = std::clamp(static_cast<int>(std::ceil(full_.longest_side(tr) / full_.median_side())), 2, 16);
      // A point stops at the first piece within half the tolerance (or the largest so far): an
      // upper bound of its distance, which is all the figure needs (with none the queries ran
      // through every piece within twice the tolerance: 60 s on NIST FTC 11 at 1 %).
      full_.for_lattice(tr, n, [&](const Point3& q) {
        e = std::max(e, full_.excess(interpolated(tr, q), 2 * tol_, std::max(e, 0.5 * tol_)));
      });
    }
    return e;
  }

  /// The largest error of a removed vertex's ball to the triangle or side standing for it.
  double max_error() const {
    double e = 0;
    for (int t = 0; t < c_.num_triangles(); ++t)
      if (c_.alive(t))
        for (int p : carried_[static_cast<std::size_t>(t)]) e = std::max(e, to_triangle(ball(p), t));
    for (const auto& [key, points] : side_carried_) {
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
      for (int p : points) e = std::max(e, compact::ball_to_segment(ball(p), ball(a), ball(b)));
    }
    return e;
  }

 private:
  struct Plan {
    int u = -1, v = -1, w = -1;  ///< w: u's other neighbour along its border or seam
    std::vector<int> points;     ///< removed vertices standing on u's triangles, and u
    std::vector<int> home;       ///< per point: the moved triangle nearest it
    std::vector<int> side_points;  ///< on a border or seam: those of its sides uv and uw, and u
  };

  Ball ball(int v) const {
    return {mesh_.vertices[static_cast<std::size_t>(v)], mesh_.radius[static_cast<std::size_t>(v)]};
  }

  // The ball at point q of triangle tr (q in its plane): the radius interpolated barycentrically.
  Ball interpolated(const std::array<int, 3>& tr, const Point3& q) const {
    const Point3 a = mesh_.vertices[static_cast<std::size_t>(tr[0])], b = mesh_.vertices[static_cast<std::size_t>(tr[1])],
                 c = mesh_.vertices[static_cast<std::size_t>(tr[2])];
    const Point3 n = compact::cross(compact::sub(b, a), compact::sub(c, a));
    const double n2 = compact::dot(n, n);
    const auto r = [&](int k) { return mesh_.radius[static_cast<std::size_t>(tr[k])]; };
    if (!(n2 > 0)) return {q, std::max({r(0), r(1), r(2)})};
    const double wa = compact::dot(compact::cross(compact::sub(b, q), compact::sub(c, q)), n) / n2;
    const double wb = compact::dot(compact::cross(compact::sub(c, q), compact::sub(a, q)), n) / n2;
    return {q, wa * r(0) + wb * r(1) + (1 - wa - wb) * r(2)};
  }

  // Error of p to triangle t as it is, or with u standing at v.
  double to_triangle(const Ball& p, int t, int u = -1, int v = -1) const {
    auto tr = c_.triangle(t);
    for (int& x : tr)
      if (x == u) x = v;
    return compact::ball_to_triangle(p, ball(tr[0]), ball(tr[1]), ball(tr[2]));
  }

  // nb: gets u's neighbours.
  Role role(int u, std::vector<int>& nb) const {
    Role r;
    nb.clear();
    if (c_.triangles_at(u).empty() || !c_.bare_at(u).empty() || c_.pinned(u)) return r;
    std::vector<int> counts;
    c_.neighbours(u, nb);
    c_.side_counts(u, nb, counts);
    int features = 0, count = -1;
    for (std::size_t i = 0; i < nb.size(); ++i) {
      const int x = nb[i], k = counts[i];
      if (k == 2) continue;
      if (features == 2 || (count >= 0 && k != count)) return r;  // a junction
      count = k;
      r.along[features++] = x;
    }
    if (features == 1) return r;  // a seam or border ends here
    if (!c_.link_connected(u, nb)) return r;
    r.movable = true;
    return r;
  }

  // Whether u's triangles, with u at v, stay triangles turned by at most 60 degrees.
  bool keeps_shape(int u, int v) const {
    for (int t : c_.triangles_at(u)) {
      const auto& tr = c_.triangle(t);
      if (tr[0] == v || tr[1] == v || tr[2] == v) continue;
      Point3 p[3], q[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = mesh_.vertices[static_cast<std::size_t>(tr[k])];
        q[k] = tr[k] == u ? mesh_.vertices[static_cast<std::size_t>(v)] : p[k];
      }
      const Point3 n0 = compact::cross(compact::sub(p[1], p[0]), compact::sub(p[2], p[0]));
      const Point3 n1 = compact::cross(compact::sub(q[1], q[0]), compact::sub(q[2], q[0]));
      double longest = 0;
      for (int k = 0; k < 3; ++k) {
        const Point3 d = compact::sub(q[(k + 1) % 3], q[k]);
        longest = std::max(longest, compact::dot(d, d));
      }
      const double a0 = std::sqrt(compact::dot(n0, n0)), a1 = std::sqrt(compact::dot(n1, n1));
      const bool was_flat = !(a0 > 1e-12 * longest);
      if (!(a1 > 1e-12 * longest)) {
        if (!was_flat) return false;
        continue;
      }
      if (!was_flat && compact::dot(n0, n1) < kMinNormalCos * a0 * a1) return false;
    }
    return true;
  }

  // Queues u's shortest side along which it may move (the checks wait until it comes out of the
  // queue: most candidates are queued again before that). Shortest first gave fewer faces than
  // least error first, in less time: Y-rod mount at 0.1 %, 6,394 faces in 3.6 s against 6,774
  // in 8.7 s.
  void push_best(int u) {
    std::vector<int> nu;
    const Role r = role(u, nu);
    if (!r.movable) return;
    std::vector<int> targets;
    if (r.on_feature()) {
      targets = {r.along[0], r.along[1]};
    } else {
      targets = nu;
    }
    const auto& failed = failed_[static_cast<std::size_t>(u)];
    Candidate best{std::numeric_limits<double>::infinity(), u, -1, stamp_[static_cast<std::size_t>(u)]};
    for (int v : targets) {
      if (std::find(failed.begin(), failed.end(), v) != failed.end()) continue;
      const Point3 d = compact::sub(mesh_.vertices[static_cast<std::size_t>(u)], mesh_.vertices[static_cast<std::size_t>(v)]);
      const double length = compact::dot(d, d);
      if (length < best.cost || (length == best.cost && v < best.v)) best.cost = length, best.v = v;
    }
    if (best.v >= 0) queue_.push(best);
  }

  // The whole check of contracting u into v: the link condition, the shape, and every ball the
  // triangles (and sides) of u stand for within the tolerance of what stands for it after.
  bool plan_contraction(int u, int v, Plan& plan) const {
    std::vector<int> nu;
    const Role r = role(u, nu);
    if (!r.movable) return false;
    if (r.on_feature() ? (r.along[0] != v && r.along[1] != v) : false) return false;
    if (!c_.can_contract(u, v, nu) || !keeps_shape(u, v)) return false;
    plan = Plan{};
    plan.u = u, plan.v = v;
    std::vector<int> moved;
    for (int t : c_.triangles_at(u)) {
      const auto& tr = c_.triangle(t);
      if (tr[0] != v && tr[1] != v && tr[2] != v) moved.push_back(t);
    }
    if (moved.empty()) return false;
    plan.points.push_back(u);
    plan.home.push_back(-1);
    for (int t : c_.triangles_at(u)) {
      const bool stays = std::find(moved.begin(), moved.end(), t) != moved.end();
      for (int p : carried_[static_cast<std::size_t>(t)]) plan.points.push_back(p), plan.home.push_back(stays ? t : -1);
    }
    for (std::size_t i = 0; i < plan.points.size(); ++i) {
      const Ball p = ball(plan.points[i]);
      // A point whose triangle moves stays with it if it is near enough: the nearest of the
      // moved triangles is not needed, any within the tolerance will do.
      if (plan.home[i] >= 0 && to_triangle(p, plan.home[i], u, v) <= tol_) continue;
      double best = std::numeric_limits<double>::infinity();
      for (int t : moved) {
        const double e = to_triangle(p, t, u, v);
        if (e < best) best = e, plan.home[i] = t;
      }
      if (!(best <= tol_)) return false;
    }
    // And the other way: every point of the moved triangles within the tolerance of the full
    // mesh (a contraction across a fold would bridge empty space), on a lattice of them.
    for (int t : moved) {
      auto tr = c_.triangle(t);
      for (int& x : tr)
        if (x == u) x = v;
      // Steps of at most half a median side of the full mesh (its corners are its own vertices).
      const int n = std::clamp(static_cast<int>(std::ceil(2 * full_.longest_side(tr) / full_.median_side())), 2, 8);
      bool near = true;
      full_.for_lattice(tr, n, [&](const Point3& q) {
        if (near && q != mesh_.vertices[static_cast<std::size_t>(tr[0])] &&
            q != mesh_.vertices[static_cast<std::size_t>(tr[1])] && q != mesh_.vertices[static_cast<std::size_t>(tr[2])])
          near = full_.near(interpolated(tr, q), tol_);
      });
      if (!near) return false;
    }
    if (r.on_feature()) {
      plan.w = r.along[0] == v ? r.along[1] : r.along[0];
      plan.side_points.push_back(u);
      for (int other : {v, plan.w}) {
        const auto it = side_carried_.find(side_key(u, other));
        if (it != side_carried_.end()) plan.side_points.insert(plan.side_points.end(), it->second.begin(), it->second.end());
      }
      const Ball a = ball(v), b = ball(plan.w);
      for (int p : plan.side_points)
        if (!(compact::ball_to_segment(ball(p), a, b) <= tol_)) return false;
    }
    return true;
  }

  void apply(const Plan& plan, std::vector<int>& vanished, std::vector<int>& moved) {
    for (int t : c_.triangles_at(plan.u)) carried_[static_cast<std::size_t>(t)].clear();
    c_.contract(plan.u, plan.v, vanished, moved);
    for (std::size_t i = 0; i < plan.points.size(); ++i)
      carried_[static_cast<std::size_t>(plan.home[i])].push_back(plan.points[i]);
    if (plan.w < 0) return;
    side_carried_.erase(side_key(plan.u, plan.v));
    side_carried_.erase(side_key(plan.u, plan.w));
    auto& side = side_carried_[side_key(plan.v, plan.w)];
    side.insert(side.end(), plan.side_points.begin(), plan.side_points.end());
  }

  // A chain of 1-D edges (a cylinder's axis) keeps its branch points and ends; a vertex between
  // two edges goes where the chain without it stays within the tolerance of its balls.
  void thin_bare_chains() {
    std::vector<int> na, nb;
    for (bool changed = true; changed;) {
      changed = false;
      for (int u = 0; u < c_.num_vertices(); ++u) {
        if (!c_.triangles_at(u).empty() || c_.bare_at(u).size() != 2) continue;
        const int a = c_.bare_at(u)[0], b = c_.bare_at(u)[1];
        c_.neighbours(a, na);
        if (a == b || std::find(na.begin(), na.end(), b) != na.end()) continue;
        std::vector<int> points{u};
        for (int other : {a, b}) {
          const auto it = side_carried_.find(side_key(u, other));
          if (it != side_carried_.end()) points.insert(points.end(), it->second.begin(), it->second.end());
        }
        bool near = true;
        for (int p : points) near = near && compact::ball_to_segment(ball(p), ball(a), ball(b)) <= tol_;
        if (!near) continue;
        c_.bypass_bare(u);
        side_carried_.erase(side_key(u, a));
        side_carried_.erase(side_key(u, b));
        auto& side = side_carried_[side_key(a, b)];
        side.insert(side.end(), points.begin(), points.end());
        changed = true;
      }
    }
  }

  const MedialMesh& mesh_;
  double tol_;
  TriangleComplex c_;
  FullMeshIndex full_;
  std::vector<std::vector<int>> carried_;  ///< per triangle: the removed vertices it stands for
  std::unordered_map<std::uint64_t, std::vector<int>> side_carried_;  ///< the same per border, seam or 1-D side
  std::vector<unsigned> stamp_;
  std::vector<std::vector<int>> failed_;  ///< per vertex: targets whose whole check failed since it changed
  std::vector<int> failures_;             ///< per vertex: whole checks failed in all
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue_;
};

}  // namespace

MedialMesh simplify_axis(const MedialMesh& mesh, double tolerance, SimplifyStats* stats, const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (!(tolerance >= 0) || !std::isfinite(tolerance)) tolerance = 0;
  // Pinned: a vertex added at a polygon's centre is not the full axis's, and stays where it is
  // (its polygon is folded onto others: it is rare, and its faces are best left as they are).
  std::vector<char> added;
  const MedialMesh work = compact::triangulated(mesh, added);
  Simplifier s(work, tolerance);
  for (std::size_t v = 0; v < added.size(); ++v)
    if (added[v]) s.complex().pin(static_cast<int>(v));
  const compact::ComplexTopology before = compact::topology_of(s.complex());
  s.run(progress);
  MedialMesh out = s.complex().to_mesh(work);
  if (stats) {
    const compact::ComplexTopology after = compact::topology_of(s.complex());
    stats->tolerance = tolerance;
    stats->vertices_before = mesh.num_vertices();
    stats->faces_before = mesh.num_faces();
    stats->edges_before = mesh.num_edges();
    stats->vertices_after = out.num_vertices();
    stats->faces_after = out.num_faces();
    stats->edges_after = out.num_edges();
    stats->max_error = s.max_error();
    stats->max_containment = s.max_containment();
    stats->euler_before = before.euler, stats->euler_after = after.euler;
    stats->components_before = before.components, stats->components_after = after.components;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return out;
}

}  // namespace cadmedial
