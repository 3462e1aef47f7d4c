#include "thin_walls.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "../two_cores.h"
#include "point_grid.h"

namespace cadmedial {

namespace {

double dot3(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

std::int64_t pair_key(int a, int b) { return (static_cast<std::int64_t>(a) << 32) | static_cast<std::uint32_t>(b); }

bool on_face(const Samples& s, std::size_t i) { return s.tag[i] == SampleTag::Face || s.tag[i] == SampleTag::Triplet; }

bool on_edge(const Samples& s, std::size_t i) { return s.tag[i] == SampleTag::Edge || s.tag[i] == SampleTag::Ball; }

// Parallel walls count with a sample up to 5 depths along the other wall (squared: 1 / 25).
constexpr double kParallelSlope2 = 0.04;
// So a parallel-wall radius r = depth / 2 comes from a sample up to sqrt(26) depths, 2 sqrt(26) r,
// away: found with the reach 2 below when r <= below / kParallelReach.
const double kParallelReach = std::sqrt(1.0 + 1.0 / kParallelSlope2);

// Face samples, and edge samples where the solid is not convex.
bool on_wall(const Samples& s, std::size_t i) { return on_face(s, i) || (on_edge(s, i) && s.edge_convex[i] != 1); }

}  // namespace

namespace {

// The shrinking-ball estimate at one sample after another (wall_radii's rule), over grids of the
// walls' samples and of the convex edges' samples built once.
class WallMeter {
 public:
  /// Balls smaller than `below` (at most the spacing) are looked for.
  WallMeter(const Samples& s, double spacing, const std::vector<std::array<int, 2>>& wedges, double wedge_dot,
            double below)
      : s_(s), spacing_(spacing), wedge_dot_(wedge_dot), below_(std::min(below, spacing)), reach_(2.0 * below_),
        // A ball through q tangent at p lies on p's inner side: only the cells that meet the half
        // of the reach's box behind p's tangent plane are searched. Cells of 2/3 of the reach: on
        // NIST CTC 01 this took 0.23 s against 0.39 s with cells of the whole reach around p (one
        // thread, same radii); on the Y-rod mount, with fewer samples near walls, the same (0.09 s).
        grid_(reach_ * 2.0 / 3.0), convex_(spacing) {
    std::vector<std::size_t> cell;  // per wall sample, its cell in grid_
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (on_wall(s, i)) {
        cell.push_back(grid_.insert(s.points[i], static_cast<int>(i)));
        walls_.push_back(static_cast<int>(i));
      }
      if (s.edge_convex[i] == 1) convex_.insert(s.points[i], static_cast<int>(i));
    }
    make_cones(cell);
    for (const auto& [a, b] : wedges) wedge_.push_back(pair_key(a, b)), wedge_.push_back(pair_key(b, a));
    std::sort(wedge_.begin(), wedge_.end());
  }

  /// The samples measured, in order: face samples, and edge samples where the solid is not convex.
  const std::vector<int>& walls() const { return walls_; }

  /// The radius at walls()[w], or infinity when no ball smaller than `below` was found. Balls
  /// above `cap` may be missed (infinity or a larger radius then): a ball through q is at least
  /// half q's depth behind p's tangent plane, so only the slab up to 2 cap deep is searched.
  double radius(std::size_t w, double cap = std::numeric_limits<double>::infinity()) const {
    const Samples& s = s_;
    const std::size_t i = static_cast<std::size_t>(walls_[w]);
    const Point3& p = s.points[i];
    const double spacing2 = spacing_ * spacing_, reach2 = reach_ * reach_;
    const bool by_edge = convex_.any_near(p, spacing_, [&](int j) { return distance2(s.points[j], p) < spacing2; });
    double radius = std::numeric_limits<double>::infinity();
    const double slab = std::min(reach_, 2.0 * cap);
    for (const Point3* n : {&s.normal[i], on_edge(s, i) ? &s.normal2[i] : nullptr}) {
      if (!n) continue;
      Point3 lo, hi;
      for (int a = 0; a < 3; ++a) {
        // The extent along axis a of {x : |x| <= reach, -slab <= x.n <= 0}: x = t n + u with u
        // normal to n, so x_a lies within t n_a +- reach sqrt(1 - n_a^2), and within the reach.
        // (The whole slab, the reach deep: the full reach where the axis points into the solid,
        // the disc's reach sqrt(1 - n_a^2) on the other side.)
        const double na = (*n)[a], disc = reach_ * std::sqrt(std::max(0.0, 1.0 - na * na)), margin = 1e-9 * reach_;
        lo[a] = p[a] - std::min(reach_, std::max(0.0, slab * na) + disc) - margin;
        hi[a] = p[a] + std::min(reach_, std::max(0.0, -slab * na) + disc) + margin;
      }
      // A cell none of whose normals can face n holds no candidate, and most samples the box
      // visits do not face it (14 % do on the Y-rod mount, 32 % on NIST CTC 02).
      const auto cannot_face = [this, n](std::size_t c) {
        const int k = cone_of_[c];
        if (k < 0) return false;
        const Cone& cone = cones_[static_cast<std::size_t>(k)];
        const double cb = dot3(*n, cone.axis), sb = std::sqrt(std::max(0.0, 1.0 - cb * cb));
        // cos(angle(n, axis) + the cone's half-angle), a lower bound of n's dot product with any
        // of the cell's normals; facing() needs -0.5 or less (rounding: a millionth to spare).
        return cb * cone.cos_half - sb * cone.sin_half > -0.5 + 1e-6;
      };
      grid_.any_in_box(lo, hi, [&](int j) {
        if (!facing(*n, j)) return false;
        if (by_edge && s.face[i] >= 0 && s.face[j] >= 0 && s.face[j] != s.face[i] && dot3(*n, s.normal[j]) < wedge_dot_ &&
            std::binary_search(wedge_.begin(), wedge_.end(), pair_key(s.face[i], s.face[j])))
          return false;
        const Point3 d{s.points[j][0] - p[0], s.points[j][1] - p[1], s.points[j][2] - p[2]};
        const double d2 = dot3(d, d);
        const double depth = -dot3(d, *n);  // how far q lies inside p's tangent plane
        if (!(depth > 0 && d2 < reach2) || depth > slab) return false;
        radius = std::min(radius, d2 / (2.0 * depth));
        // Parallel walls: half their distance, with q up to 5 depths along the other wall (the
        // ball through q overestimates by (lateral offset)^2 / (2 depth) when q is not opposite
        // p; farther along, q may be on a wall that only meets p's plane, as where a solid's
        // faces touch at a corner).
        if (dot3(*n, s.normal[j]) < -0.95 && depth * depth >= kParallelSlope2 * (d2 - depth * depth))
          radius = std::min(radius, 0.5 * depth);
        return false;
      }, cannot_face);
    }
    return radius < below_ ? radius : std::numeric_limits<double>::infinity();
  }

 private:
  bool facing(const Point3& n, int j) const {
    return dot3(n, s_.normal[j]) <= -0.5 || (on_edge(s_, j) && dot3(n, s_.normal2[j]) <= -0.5);
  }

  // Per cell of grid_, the cone around its normals' mean that holds them all (an edge sample's
  // two), for the cells whose normals lie within 60 degrees of it: only those can be skipped.
  void make_cones(const std::vector<std::size_t>& cell) {
    cone_of_.assign(grid_.cells(), -1);
    auto for_each_normal = [this](std::size_t w, const auto& fn) {
      const std::size_t i = static_cast<std::size_t>(walls_[w]);
      fn(s_.normal[i]);
      if (on_edge(s_, i)) fn(s_.normal2[i]);
    };
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      int& k = cone_of_[cell[w]];
      if (k < 0) k = static_cast<int>(cones_.size()), cones_.push_back(Cone{});
      Point3& sum = cones_[static_cast<std::size_t>(k)].axis;
      for_each_normal(w, [&sum](const Point3& m) {
        for (int a = 0; a < 3; ++a) sum[a] += m[a];
      });
    }
    for (Cone& cone : cones_) {
      const double len = std::sqrt(dot3(cone.axis, cone.axis));
      for (int a = 0; a < 3; ++a) cone.axis[a] = len > 0 ? cone.axis[a] / len : 0.0;
      cone.cos_half = len > 0 ? 1.0 : -1.0;
    }
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      Cone& cone = cones_[static_cast<std::size_t>(cone_of_[cell[w]])];
      for_each_normal(w, [&cone](const Point3& m) { cone.cos_half = std::min(cone.cos_half, dot3(cone.axis, m)); });
    }
    for (int& k : cone_of_) {
      if (k < 0) continue;
      Cone& cone = cones_[static_cast<std::size_t>(k)];
      if (!(cone.cos_half > 0.5)) {
        k = -1;
        continue;
      }
      cone.sin_half = std::sqrt(std::max(0.0, 1.0 - cone.cos_half * cone.cos_half));
    }
  }

  struct Cone {
    Point3 axis{0, 0, 0};  ///< unit
    double cos_half = 1.0, sin_half = 0.0;
  };

  const Samples& s_;
  double spacing_, wedge_dot_, below_, reach_;
  PointGrid grid_, convex_;
  std::vector<int> walls_;
  std::vector<int> cone_of_;  // per cell of grid_: its cone in cones_, or -1 (not skipped)
  std::vector<Cone> cones_;
  std::vector<std::int64_t> wedge_;  // the wedges' face pairs in both orders, sorted
};

}  // namespace

std::vector<double> wall_radii(const Samples& s, double spacing, const std::vector<std::array<int, 2>>& wedges,
                               double wedge_dot, const Progress& progress, int threads) {
  // The ball tangent at p (outward normal n) through q has radius |q - p|^2 / (2 (p - q).n): the
  // shrinking-ball estimate of the medial radius at p. Only a facing wall counts: across a convex
  // or concave edge the ball shrinks too, but there the axis meets the edge by construction. A
  // ball smaller than the spacing through q lies within two spacings of p. Walls are face
  // samples and samples of concave and smooth edges (a slot's floor edges face its walls; a
  // concave edge sample has both faces' normals).
  std::vector<double> radii(s.size(), std::numeric_limits<double>::infinity());
  const WallMeter meter(s, spacing, wedges, wedge_dot, spacing);
  const std::vector<int>& walls = meter.walls();
  // Each sample on its own: half of the walls' samples on each of two cores (the edge samples
  // come first and are mostly not walls), only this one reporting.
  auto measure = [&](std::size_t begin, std::size_t end, const auto& tick) {
    for (std::size_t w = begin; w < end; ++w) {
      if (w % 4096 == 0 && !tick(w)) return;
      radii[walls[w]] = meter.radius(w);
    }
  };
  if (threads < 2) {
    measure(0, walls.size(), [&](std::size_t w) {
      report(progress, "thin walls", static_cast<double>(w) / std::max<std::size_t>(1, walls.size()));
      return true;
    });
    return radii;
  }
  const std::size_t mid = walls.size() / 2;
  internal::on_two_cores(
      [&] {
        measure(0, mid, [&](std::size_t w) {
          report(progress, "thin walls", static_cast<double>(w) / std::max<std::size_t>(1, mid));
          return true;
        });
      },
      [&](const std::atomic<bool>& stop) { measure(mid, walls.size(), [&](std::size_t) { return !stop; }); });
  return radii;
}

bool any_thin_wall(const Samples& s, double spacing, const std::vector<std::array<int, 2>>& wedges, double wedge_dot,
                   const Progress& progress) {
  const WallMeter meter(s, spacing, wedges, wedge_dot, spacing);
  const std::size_t n = meter.walls().size();
  for (std::size_t w = 0; w < n; ++w) {
    if (w % 4096 == 0) report(progress, "thin walls", static_cast<double>(w) / n);
    if (meter.radius(w) < spacing) return true;
  }
  return false;
}

ThinWall thinnest_wall(const Samples& s, const std::vector<double>& radii) {
  ThinWall w;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    if (!(radii[i] < std::numeric_limits<double>::infinity())) continue;
    ++w.samples;
    if (radii[i] < w.radius) w.radius = radii[i], w.at = s.points[i];
  }
  return w;
}

ThinWall thinnest_wall_near(const Samples& s, double spacing, const std::vector<std::array<int, 2>>& wedges,
                            double guess, const Progress& progress) {
  // Balls below `below`, looked for within 2 below of each sample: every ball-rule radius r < below
  // and every parallel-wall radius r <= below / kParallelReach is found, so the smallest found is
  // the smallest there is when it is that small. Else look again, as far as it says.
  double below = guess > 0 ? std::min(spacing, 1.5 * guess) : spacing;  // it only grows from there
  for (;;) {
    const WallMeter meter(s, spacing, wedges, 1.0, below);
    const std::vector<int>& walls = meter.walls();
    ThinWall w;
    // Only a ball below the thinnest so far can change the answer (the first of equals stays):
    // the search narrows as it goes. On the Y-rod mount's refined samples at spacing 2.849 it
    // took 0.052 to 0.070 s against 0.098 to 0.114 s (a scratch program, runs in turn).
    for (std::size_t k = 0; k < walls.size(); ++k) {
      if (k % 4096 == 0) report(progress, "thin walls", static_cast<double>(k) / walls.size());
      const double r = meter.radius(k, w.radius);
      if (r < w.radius) w.radius = r, w.at = s.points[static_cast<std::size_t>(walls[k])];
    }
    if (below >= spacing || w.radius * kParallelReach <= below) return w;
    below = std::min(spacing, w.radius < below ? w.radius * kParallelReach : 4.0 * below);
  }
}

}  // namespace cadmedial
