#include "inner_axis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "preserve_topology.h"
#include "sample_votes.h"
#include "complete_medial_axis.h"
#include "geometry_3.h"
#include "prefetch.h"
#include "../sampling/point_grid.h"
#include "../two_cores.h"

namespace cadmedial::internal {

namespace {

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// A sample lies on the boundary and inside its own Voronoi cell, so the cell always holds some
// exterior: if every Delaunay cell at the sample is labelled inside, all facets of its Voronoi
// cell are kept and close a void in the axis. That happens at concave edges with an exterior wedge
// under 90 degrees: a cell spanning the wedge has its circumcentre just beyond one face, inside the
// solid, when its samples on the two faces are at unequal distances from the edge. The vertex
// farthest along the sample's outward direction d (the normal; at an edge, the sum of the two
// normals) has the ball holding most of the exterior off the sample: it goes outside, which opens
// the void (with the other facets at that vertex). Samples whose cell is open are left alone.
void open_closed_sample_cells(const MedialComplex& mc, const Samples& samples, std::vector<std::uint8_t>& label) {
  const std::size_t ns = samples.size(), nc = mc.num_cells();
  struct PerSample {
    std::vector<char> open;
    std::vector<int> farthest;
    std::vector<double> best;
  } half[2];
  // Half the cells on each core, each with its own per-sample answers; merged below so that the
  // farthest vertex is the one a single pass in id order finds (the first of equals).
  on_two_halves(nc, [&](int part, std::size_t begin, std::size_t end) {
    std::vector<char>& open = half[part].open;
    std::vector<int>& farthest = half[part].farthest;
    std::vector<double>& best = half[part].best;
    open.assign(ns, 0);
    farthest.assign(ns, -1);
    best.assign(ns, 0.0);
    for (std::size_t id = begin; id < end; ++id) {
      const auto& cs = mc.cell_samples[id];
      // Merged cells (coincident circumcentres) are labelled through their representative.
      const int r = mc.rep.empty() ? static_cast<int>(id) : mc.rep[id];
      for (int j = 0; j < 4; ++j) {
        const int s = cs[j];
        // A sample on the hull has an unbounded Voronoi cell: open already.
        if (!label[r] || mc.cell_neighbors[id][j] < 0) {
          if (!label[r]) open[s] = 1;
          if (mc.cell_neighbors[id][j] < 0)
            for (int k = 0; k < 4; ++k)
              if (k != j) open[cs[k]] = 1;
          continue;
        }
        Point3 d = samples.normal[s];
        const SampleTag tag = samples.tag[s];
        if (tag == SampleTag::Edge || tag == SampleTag::Ball)
          for (int k = 0; k < 3; ++k) d[k] += samples.normal2[s][k];
        const double along = dot(sub(mc.centers[r], samples.points[s]), d);
        if (farthest[s] < 0 || along > best[s]) farthest[s] = r, best[s] = along;
      }
    }
  }, 1 << 14);
  const PerSample &lo = half[0], &hi = half[1];
  for (std::size_t s = 0; s < ns; ++s) {
    const bool upper = hi.farthest[s] >= 0 && (lo.farthest[s] < 0 || hi.best[s] > lo.best[s]);
    const int farthest = upper ? hi.farthest[s] : lo.farthest[s];
    const double best = upper ? hi.best[s] : lo.best[s];
    if (!lo.open[s] && !hi.open[s] && farthest >= 0 && best > 0) label[farthest] = 0;
  }
}

// Near a sharp convex edge (a dihedral angle under about 45 degrees) the sheet that bisects the
// edge is thinner than the samples are apart, and a Delaunay cell with three samples on one face
// and one on the other can have its circumcentre a hair beyond the first face (the other face's
// sample projects into the first face's empty circle): outside, rightly, but in the middle of the
// selected sheet, where dropping its facets cuts a hole, a loop the solid does not have (a prism
// over a triangle with a 35-degree corner: 25 such holes at 20k samples). These vertices come in
// small groups joined through the selected facets they share; the selected facets at such a group
// have all their other corners inside and form a disk, the sheet, and each vertex of the group lies
// beyond one of its samples' tangent planes but on the inner side of another's (it crossed the
// boundary between two faces). Such a group goes inside, each vertex moved along its facet towards
// an inside corner to just behind the planes it lay beyond. The outer axis in a through-hole does
// not pass: its vertices lie beyond all their samples' planes (NIST CTC 02: five hole disks
// otherwise).
//
// Below about 18 degrees such a group can surround inside vertices or a gap (its facets an
// annulus or more: a prism with a 15-degree corner had Euler -2 / -5 / -4 at 10k / 20k / 40k
// samples, with disks only). Moved in, such a group is kept only where the exact classifier
// finds all its vertices inside: there, its few vertices can lie beyond a face that none of their
// samples is on (a 10-degree corner: 3 vertices up to 0.2 h outside at 20k samples).
void fill_sheet_holes(MedialComplex& mc, const Samples& samples, std::vector<std::uint8_t>& label,
                      const InsideTest& inside, MedialAxisStats& st) {
  const std::size_t nf = mc.size(), nc = mc.num_cells();
  auto outside = [&](int node) { return node >= 0 && !label[node]; };
  auto selected = [&](std::size_t f) { return mc.kind[f] == FaceKind::Voronoi && !mc.filler[f]; };
  // Only vertices that crossed the boundary between two faces (straddles: beyond one of their
  // samples' tangent planes, on the inner side of another's) are joined: a group with any other
  // outside vertex stays outside (it fails the test below either way), and the outer axis, one
  // large group otherwise, took as long as the rest of the stage (CTC 01 at 66k samples). Those far
  // outside do not straddle (mark_far_outside).
  std::vector<std::uint8_t> straddling(nc);
  on_two_halves(nc, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c) {
      const int cell = static_cast<int>(c);
      straddling[c] = !mc.surely_outside[c] && outside(cell) && straddles(mc, samples, cell);
    }
  }, 1 << 14);
  auto joins = [&](int node) { return node >= 0 && straddling[node]; };
  // The selected facets with a straddling corner (most of the outer axis's have none: they
  // belong to no group that can go inside), and pairs of straddling corners to join: all of a
  // facet's go in one group. (Joined only along the facet's sides, two that were not neighbours
  // made two groups that spoiled each other: prisms with a 20- or 25-degree corner were at -5 at
  // spacing 0.3, test_hard_inputs.) Half the facets on each core; the second half's lists follow
  // the first's, in facet order.
  struct Found {
    std::vector<int> faces;
    std::vector<std::pair<int, int>> sides;
  } half[2];
  on_two_halves(nf, [&](int part, std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      if (!selected(f)) continue;
      const int b = mc.start[f], e = mc.start[f + 1];
      bool straddled = false;
      int first = -1;
      for (int k = b; k < e; ++k) {
        const int x = mc.nodes[k];
        if (!joins(x)) continue;
        straddled = true;
        if (first < 0)
          first = x;
        else
          half[part].sides.push_back({first, x});
      }
      if (straddled) half[part].faces.push_back(static_cast<int>(f));
    }
  }, 1 << 14);
  std::vector<int> parent(nc);
  std::iota(parent.begin(), parent.end(), 0);
  for (const Found& found : half)
    for (const auto& [x, y] : found.sides) parent[find_root(parent, x)] = find_root(parent, y);
  // Per group (its root): the selected facets with an outside corner; a facet with corners in two
  // groups spoils both. A selected facet that was not built has a corner surely outside, which is in
  // no group: it spoils the groups at its other corners. (Without this, a group on brlcad's c.stp
  // was filled at 20k samples and left a vertex outside the solid.)
  std::vector<std::pair<int, int>> group_face;
  std::vector<char> spoiled(nc, 0);
  for (std::size_t c = 0; c < mc.unbuilt_use.size(); ++c) {
    if (mc.unbuilt_use[c] != 2) continue;
    const int r = mc.rep.empty() ? static_cast<int>(c) : mc.rep[c];
    if (straddling[r]) spoiled[find_root(parent, r)] = 1;
  }
  for (const Found& found : half)
    for (const int f : found.faces) {
      int root = -1;
      bool two = false;
      for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) {
        if (!outside(mc.nodes[k])) continue;
        const int r = find_root(parent, mc.nodes[k]);
        two = two || (root >= 0 && r != root);
        root = r;
      }
      // Every group at the facet, the first one met too (marking only those met after a change
      // let a group be filled without this facet, as if it were whole).
      if (two)
        for (int k = mc.start[f]; k < mc.start[f + 1]; ++k)
          if (outside(mc.nodes[k])) spoiled[find_root(parent, mc.nodes[k])] = 1;
      group_face.push_back({root, f});
    }
  std::sort(group_face.begin(), group_face.end());
  std::unordered_map<std::uint64_t, int> side_count;
  std::vector<int> members;
  for (std::size_t g = 0; g < group_face.size();) {
    std::size_t end = g;
    while (end < group_face.size() && group_face[end].first == group_face[g].first) ++end;
    const int root = group_face[g].first;
    if (!spoiled[root]) {
      side_count.clear();
      members.clear();
      for (std::size_t i = g; i < end; ++i) {
        const int f = group_face[i].second, b = mc.start[f], e = mc.start[f + 1];
        for (int k = b; k < e; ++k) {
          const int x = mc.nodes[k], y = mc.nodes[k + 1 < e ? k + 1 : b];
          if (outside(x)) members.push_back(x);
          if (!outside(x) && !outside(y)) continue;
          const auto key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(x, y))) << 32) |
                           static_cast<std::uint32_t>(std::max(x, y));
          ++side_count[key];
        }
      }
      std::sort(members.begin(), members.end());
      members.erase(std::unique(members.begin(), members.end()), members.end());
      // Every side at a member shared by two of the group's facets: a surface around the members.
      bool manifold = true;
      for (const auto& [key, count] : side_count) manifold = manifold && count == 2;
      for (int x : members) manifold = manifold && straddling[x];
      const long euler = static_cast<long>(members.size()) - static_cast<long>(side_count.size()) +
                         static_cast<long>(end - g);
      if (manifold && euler <= 1) {
        std::vector<Point3> before;
        for (int x : members) before.push_back(mc.centers[x]);
        // Each vertex moves towards an inside corner of one of its facets, to just behind every
        // tangent plane of its samples that it lies beyond: the sheet stays inside the solid.
        for (std::size_t i = g; i < end; ++i) {
          const int f = group_face[i].second;
          int in = -1;
          for (int k = mc.start[f]; k < mc.start[f + 1] && in < 0; ++k)
            if (!outside(mc.nodes[k])) in = mc.nodes[k];
          for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) {
            const int x = mc.nodes[k];
            if (!outside(x) || in < 0) continue;
            const Point3 from = mc.centers[x], to = mc.centers[in];
            double t = 0;
            for (int s : mc.cell_samples[x]) {
              const SampleTag tag = samples.tag[s];
              const bool two = (tag == SampleTag::Edge || tag == SampleTag::Ball) && samples.edge_convex[s] != 0;
              for (const Point3* n : {&samples.normal[s], two ? &samples.normal2[s] : nullptr}) {
                if (!n) continue;
                const double a = dot(sub(from, samples.points[s]), *n), b = dot(sub(to, samples.points[s]), *n);
                if (a > 0 && b < a) t = std::max(t, std::min(1.0, a / (a - b)));
              }
            }
            t = std::min(1.0, t + 1e-6);
            for (int c = 0; c < 3; ++c) mc.centers[x][c] = from[c] + t * (to[c] - from[c]);
          }
        }
        bool all_inside = true;
        if (euler < 1) {
          std::vector<Point3> moved;
          for (int x : members) moved.push_back(mc.centers[x]);
          for (std::uint8_t v : inside(moved)) all_inside = all_inside && v;
          st.exact_inside_tests += moved.size();
        }
        for (std::size_t k = 0; k < members.size(); ++k) {
          const int x = members[k];
          if (!all_inside) {
            mc.centers[x] = before[k];
            continue;
          }
          label[x] = 1;
          // Its radius: the distance to the nearest of its samples from where it is now.
          double r2 = std::numeric_limits<double>::infinity();
          for (int smp : mc.cell_samples[x]) {
            const Point3 d = sub(mc.centers[x], samples.points[smp]);
            r2 = std::min(r2, dot(d, d));
          }
          mc.radii[x] = std::sqrt(r2);
        }
      }
    }
    g = end;
  }
}

// The face-by-face reconstruction is a closed triangle mesh within its sag of the true surface.
// A point farther from it than that sag, whose nearest mesh point lies inside a triangle, is on
// the side of that triangle's outward normal: inside (1), outside (0), or undecided (-1). Its
// triangles are made from the samples when asked: only the vertices the votes leave in doubt ask
// (74 of 1.55 million cells on the Y-rod mount at 250k samples), and a copy of all of them took
// 0.028 s there, which the votes waited for.
class ReconstructionSide {
 public:
  static constexpr int kWithinSag = -2;
  ReconstructionSide(const Samples& s, const Umbrellas& u) : s_(s), u_(u) {}

  /// Against the umbrellas of the given samples only: the nearest samples of a Voronoi vertex are
  /// its cell's, so the nearest mesh point is nearly always on their triangles. (A search of the
  /// whole mesh for the rest settled 5 of 339 such vertices over the 31 parts of
  /// ../shared/data/models at 20k samples, for 0.03-0.1 s of tree building each time: they go to
  /// the exact classifier instead, at up to 0.4 ms each.)
  int side_near(const Point3& x, const std::array<int, 4>& near) const {
    const K::Point_3 q(x[0], x[1], x[2]);
    double best = std::numeric_limits<double>::infinity();
    K::Point_3 closest(0, 0, 0);
    std::size_t best_t = 0;
    const auto project = K().construct_projected_point_3_object();
    for (int v : near)
      for (int k = u_.start[v]; k < u_.start[v + 1]; ++k) {
        const std::size_t t = static_cast<std::size_t>(u_.incident[k]);
        const K::Point_3 c = project(triangle(t), q);
        const double d2 = CGAL::squared_distance(c, q);
        if (d2 < best) best = d2, closest = c, best_t = t;
      }
    return std::isfinite(best) ? side_of(q, closest, best_t) : -1;
  }

 private:
  // Outward unit normal of triangle t (oriented by its samples' exact normals), zero if unknown.
  K::Vector_3 outward(std::size_t t) const {
    const K::Triangle_3 tri = triangle(t);
    const K::Vector_3 n = CGAL::cross_product(tri[1] - tri[0], tri[2] - tri[0]);
    const double len = std::sqrt(n.squared_length());
    Point3 avg{0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) avg[c] += s_.normal[u_.triangles[t][k]][c];
    const double orient = avg[0] * n.x() + avg[1] * n.y() + avg[2] * n.z();
    if (len <= 0 || orient == 0) return {0, 0, 0};
    return n / (orient > 0 ? len : -len);
  }

  // Side of q from its closest mesh point on triangle t (kWithinSag when q lies within the
  // mesh's sag of it): by the triangle's normal when the point is interior, else by the
  // angle-weighted pseudo-normal of the edge or vertex it lies on (Baerentzen and Aanaes), which
  // gives the right sign for any point off a closed mesh.
  int side_of(const K::Point_3& q, const K::Point_3& closest, std::size_t t) const {
    const K::Triangle_3 tri = triangle(t);
    double sag = 0, edge2 = 0;
    for (int k = 0; k < 3; ++k) {
      sag = std::max(sag, static_cast<double>(s_.curvature[u_.triangles[t][k]]));
      edge2 = std::max(edge2, (tri[(k + 1) % 3] - tri[k]).squared_length());
    }
    sag = sag * edge2 / 8.0 + 1e-12 * std::sqrt(edge2);
    const K::Vector_3 d = q - closest;
    if (std::sqrt(d.squared_length()) <= sag) return kWithinSag;
    // Barycentric weights of the closest point; a corner whose weight is ~0 is not touched.
    const K::Vector_3 n = CGAL::cross_product(tri[1] - tri[0], tri[2] - tri[0]);
    const double area2 = n.squared_length();
    if (area2 <= 0) return -1;
    std::array<bool, 3> on{};
    int touched = 0;
    for (int k = 0; k < 3; ++k) {
      const double w = CGAL::cross_product(tri[(k + 2) % 3] - tri[(k + 1) % 3], closest - tri[(k + 1) % 3]) * n / area2;
      on[k] = w > 1e-9;
      touched += on[k];
    }
    K::Vector_3 pseudo(0, 0, 0);
    if (touched == 3) {
      pseudo = outward(t);
    } else if (touched == 2) {
      int a = -1, b = -1;
      for (int k = 0; k < 3; ++k)
        if (on[k]) (a < 0 ? a : b) = u_.triangles[t][k];
      for (int k = u_.start[a]; k < u_.start[a + 1]; ++k) {
        const auto& other = u_.triangles[u_.incident[k]];
        if (other[0] == b || other[1] == b || other[2] == b) pseudo = pseudo + outward(u_.incident[k]);
      }
    } else {
      int v = u_.triangles[t][0];
      for (int k = 0; k < 3; ++k)
        if (on[k]) v = u_.triangles[t][k];
      const K::Point_3 pv = point(v);
      for (int k = u_.start[v]; k < u_.start[v + 1]; ++k) {
        const auto& other = u_.triangles[u_.incident[k]];
        int at = 0;
        while (at < 2 && other[at] != v) ++at;
        K::Vector_3 e1 = point(other[(at + 1) % 3]) - pv, e2 = point(other[(at + 2) % 3]) - pv;
        const double l1 = std::sqrt(e1.squared_length()), l2 = std::sqrt(e2.squared_length());
        if (l1 <= 0 || l2 <= 0) continue;
        const double angle = std::acos(std::clamp((e1 * e2) / (l1 * l2), -1.0, 1.0));
        pseudo = pseudo + angle * outward(u_.incident[k]);
      }
    }
    const double along = d * pseudo;
    if (along == 0) return -1;
    return along < 0 ? 1 : 0;
  }

  K::Point_3 point(int i) const { return {s_.points[i][0], s_.points[i][1], s_.points[i][2]}; }
  K::Triangle_3 triangle(std::size_t t) const {
    const auto& v = u_.triangles[t];
    return {point(v[0]), point(v[1]), point(v[2])};
  }
  const Samples& s_;
  const Umbrellas& u_;
};

// Faces by their sorted corners, each with the index of the first face that had them: open
// addressing over flat keys (a std::map of vectors allocated a key per merged face, 90k at 65k
// samples).
class CornerSets {
 public:
  /// The value stored with the ascending corners key[0..n); if there is none, stores `value` and
  /// returns -1.
  int find_or_add(const int* key, int n, int value) {
    if (2 * (values_.size() + 1) > slots_.size()) grow();
    const std::uint64_t h = hash(key, n);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t s = h & mask;; s = (s + 1) & mask) {
      const int e = slots_[s];
      if (e < 0) {
        slots_[s] = static_cast<int>(values_.size());
        keys_.insert(keys_.end(), key, key + n);
        start_.push_back(static_cast<int>(keys_.size()));
        values_.push_back(value);
        hashes_.push_back(h);
        return -1;
      }
      if (hashes_[e] == h && start_[e + 1] - start_[e] == n && std::equal(key, key + n, keys_.begin() + start_[e]))
        return values_[e];
    }
  }

  /// The number of keys, and the value stored with the k-th one added.
  int size() const { return static_cast<int>(values_.size()); }
  int value(int k) const { return values_[k]; }
  /// The value stored here with the k-th key added to `other`, -1 if none.
  int find(const CornerSets& other, int k) const {
    if (slots_.empty()) return -1;
    const std::uint64_t h = other.hashes_[k];
    const int n = other.start_[k + 1] - other.start_[k];
    const auto key = other.keys_.begin() + other.start_[k];
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t s = h & mask;; s = (s + 1) & mask) {
      const int e = slots_[s];
      if (e < 0) return -1;
      if (hashes_[e] == h && start_[e + 1] - start_[e] == n && std::equal(key, key + n, keys_.begin() + start_[e]))
        return values_[e];
    }
  }

 private:
  static std::uint64_t hash(const int* key, int n) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull ^ static_cast<std::uint64_t>(n);
    for (int k = 0; k < n; ++k) {
      h ^= static_cast<std::uint32_t>(key[k]);
      h *= 0xff51afd7ed558ccdull;
      h ^= h >> 32;
    }
    return h;
  }
  void grow() {
    slots_.assign(std::max<std::size_t>(1024, 2 * slots_.size()), -1);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t e = 0; e < values_.size(); ++e) {
      std::size_t s = hashes_[e] & mask;
      while (slots_[s] >= 0) s = (s + 1) & mask;
      slots_[s] = static_cast<int>(e);
    }
  }
  std::vector<int> slots_;  ///< entry per slot, -1 empty; a power of two, at most half full
  std::vector<int> start_{0}, keys_, values_;
  std::vector<std::uint64_t> hashes_;
};

// One part of the faces (a range of them) rewritten in place by rewrite_faces.
struct MergedPart {
  std::size_t faces = 0, nodes = 0;  ///< kept, from the part's first face and node on
  std::vector<int> points;
  std::vector<std::array<int, 3>> segments;
  CornerSets seen;  ///< sorted corners of the merged faces -> face (from the part's first)
};

// Rewrites faces [begin, end) of mc in place, each corner replaced by its group's (rep): repeated
// corners go, then faces left with fewer than three, then copies of an earlier face of the part.
// The faces kept move down over those that go (nothing is allocated: mc's arrays are a million
// entries at 65k samples, and fresh pages cost more than the rewrite). `base` is mc.start[begin]
// as it was: the part before may rewrite that entry meanwhile, and it is all this part writes
// outside its own entries (begin, end] and nodes. `tick(f)` before each face: false stops.
template <class Tick>
void rewrite_faces(MedialComplex& mc, const std::vector<int>& rep, const std::vector<std::uint8_t>& in_group,
                   std::size_t begin, std::size_t end, int base, MergedPart& out, const Tick& tick) {
  int* const nodes = mc.nodes.data() + base;
  std::size_t kept = begin, at = 0;  // next face and node written
  int next = base;                   // where the face being read starts (mc.start moves under us)
  std::vector<int> key_nodes;
  for (std::size_t f = begin; f < end; ++f) {
    if (!tick(f)) return;
    const int from = next, to = mc.start[f + 1];
    next = to;
    // Written over the face's own corners or earlier ones: never ahead of what is read.
    const std::size_t first_node = at;
    // Only faces with a corner in a merged group can repeat one or duplicate another face.
    bool merged = false;
    for (int k = from; k < to; ++k) {
      int node = mc.nodes[k];
      if (node >= 0) merged = merged || in_group[node], node = rep[node];
      if (at == first_node || nodes[at - 1] != node) nodes[at++] = node;
    }
    while (at > first_node + 1 && nodes[first_node] == nodes[at - 1]) --at;
    const int* face = nodes + first_node;
    const std::size_t size = at - first_node;
    // A sphere's facets all shrink to its centre: keep the point.
    if (size == 1 && face[0] >= 0) out.points.push_back(face[0]);
    // A Voronoi facet whose corners merged into two is a segment now: where the axis is a curve,
    // cospherical samples (a circle of edge samples around it) make these, and they may be all
    // that joins the axis across that circle.
    if (size == 2 && face[0] >= 0 && face[1] >= 0 && mc.kind[f] == FaceKind::Voronoi)
      out.segments.push_back({std::min(face[0], face[1]), std::max(face[0], face[1]), mc.filler[f]});
    bool keep = size >= 3;
    if (keep && merged) {
      key_nodes.assign(face, face + size);
      std::sort(key_nodes.begin(), key_nodes.end());
      int first = -1;
      if (std::unique(key_nodes.begin(), key_nodes.end()) != key_nodes.end() ||
          (first = out.seen.find_or_add(key_nodes.data(), static_cast<int>(size), static_cast<int>(kept - begin))) >=
              0) {
        // One face: it is part of the axis proper if any of its copies is.
        if (first >= 0) mc.filler[begin + first] = mc.filler[begin + first] && mc.filler[f];
        keep = false;
      }
    }
    if (!keep) {
      at = first_node;
      continue;
    }
    mc.kind[kept] = mc.kind[f];
    mc.dual[kept] = mc.dual[f];
    mc.filler[kept] = mc.filler[f];
    mc.start[++kept] = base + static_cast<int>(at);
  }
  out.faces = kept - begin;
  out.nodes = at;
}

}  // namespace

// Cospherical samples (regular edge samples and their triplets form right prisms, which are
// inscribed in spheres) give several Delaunay cells with one circumcentre: the true Voronoi
// diagram has a single vertex there. Merging them removes zero-length Voronoi edges, which would
// otherwise leave pinholes wherever the perturbation picked one selected facet over another.
// Neighbours merge when their five samples are exactly cospherical (CGAL's exact predicate) or
// their centres are the same doubles (settle_flat_cells copies a neighbour's). Samples cospherical
// only to rounding (a torus's tube circles, whose centres make its core circle a curve) merge when
// their centres lie within `eps` and the group they form is isolated: no other neighbour's centre
// within 1000 eps. Samples within the B-rep's tolerance of a sphere are not: on NIST FTC 06 a ball
// face's edge lies 1e-5 off it, and the centres about the ball's centre scatter over 2e-4. Merged
// within eps, that cluster fell into pieces at random; each piece's faces, rewritten, pinched or
// doubled, and left a loop: six extra loops on FTC 06, two to ten on a ball on a filleted neck.
std::vector<int> coincident_cells(const MedialComplex& mc, const std::vector<Point3>& points, double eps) {
  const size_t n = mc.num_cells();
  auto point = [&points](int s) { return K::Point_3(points[s][0], points[s][1], points[s][2]); };
  auto cospherical = [&](int a, int b) {
    const std::array<int, 4>& va = mc.cell_samples[a];
    int far = -1;
    for (int s : mc.cell_samples[b])
      if (s != va[0] && s != va[1] && s != va[2] && s != va[3]) far = s;
    if (far < 0) return false;
    const K::Point_3 p[4] = {point(va[0]), point(va[1]), point(va[2]), point(va[3])};
    if (CGAL::orientation(p[0], p[1], p[2], p[3]) == CGAL::COPLANAR) return false;
    return CGAL::side_of_bounded_sphere(p[0], p[1], p[2], p[3], point(far)) == CGAL::ON_BOUNDARY;
  };
  // Union-find with the smallest id as each group's root.
  auto join = [](std::vector<int>& parent, int a, int b) {
    a = find_root(parent, a), b = find_root(parent, b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  std::vector<int> exact(n), near(n);
  std::iota(exact.begin(), exact.end(), 0);
  std::iota(near.begin(), near.end(), 0);
  const double isolation = 1000.0 * eps;
  struct Close {
    int a, b;
    bool within_eps;
  };
  // Neighbours within `isolation`, each pair once, in id order: half the cells on each core (the
  // pass over every cell's neighbours was this function's time, 0.08 s at 250k samples), then
  // joined here. The groups and their roots (smallest ids) do not depend on the order of joins.
  std::vector<Close> close, close_upper;
  on_two_halves(n, [&](int part, std::size_t begin, std::size_t end) {
    std::vector<Close>& found = part ? close_upper : close;
    for (size_t id = begin; id < end; ++id) {
      if (id + kPrefetchAhead < end)
        for (const int b : mc.cell_neighbors[id + kPrefetchAhead])
          if (b > static_cast<int>(id + kPrefetchAhead)) prefetch(mc.centers[b]);
      const int a = static_cast<int>(id);
      for (int b : mc.cell_neighbors[id]) {
        if (b < a) continue;  // also the infinite side (-1)
        const Point3 &ca = mc.centers[a], &cb = mc.centers[b];
        const double d = ca == cb ? 0.0 : norm(sub(ca, cb));
        if (!(d <= isolation)) continue;  // also for the NaN centre of a flat cell
        found.push_back({a, b, d <= eps});
      }
    }
  }, 1 << 14);
  close.insert(close.end(), close_upper.begin(), close_upper.end());
  for (const Close& c : close)
    if (c.within_eps) join(near, c.a, c.b);
  // A group joined through centres within eps keeps together only if no neighbour outside it lies
  // within `isolation`; otherwise its cells fall back to their exact groups. The exact predicate
  // runs only there: on every close pair it doubled the completion stage, where this runs beside
  // it (the Y-rod at 66k: 0.130 s against 0.057 s).
  std::vector<char> crowded(n, 0);
  for (const Close& c : close) {
    const int ra = find_root(near, c.a), rb = find_root(near, c.b);
    if (ra != rb) crowded[ra] = crowded[rb] = 1;
  }
  for (const Close& c : close)
    if (c.within_eps && crowded[find_root(near, c.a)] &&
        (mc.centers[c.a] == mc.centers[c.b] || cospherical(c.a, c.b)))
      join(exact, c.a, c.b);
  std::vector<int> rep(n);
  for (size_t id = 0; id < n; ++id) {
    const int r = find_root(near, static_cast<int>(id));
    rep[id] = crowded[r] ? find_root(exact, static_cast<int>(id)) : r;
  }
  return rep;
}

void merge_coincident_cells(MedialComplex& mc, std::vector<int> rep, const Progress& progress) {
  const size_t n = mc.num_cells();
  // The merged vertex takes the smallest of its members' positions: CGAL visits edges in an order
  // that depends on memory addresses, so "the first member" would differ from run to run.
  for (size_t id = 0; id < n; ++id) {
    const int r = rep[id];
    if (r != static_cast<int>(id) && std::tie(mc.centers[id], mc.radii[id]) < std::tie(mc.centers[r], mc.radii[r])) {
      mc.centers[r] = mc.centers[id];
      mc.radii[r] = mc.radii[id];
    }
  }
  for (int& c : mc.star_cells) c = rep[c];
  std::vector<int> group_size(n, 0);
  for (size_t id = 0; id < n; ++id) ++group_size[rep[id]];
  std::vector<std::uint8_t> in_group(n);
  for (size_t id = 0; id < n; ++id) in_group[id] = group_size[rep[id]] > 1;
  // Rewrite faces: drop repeated corners, then faces left with fewer than three, then duplicates;
  // each half of the faces on one core, then the second half's copies of the first's go.
  const std::size_t nf = mc.size(), mid = nf / 2;
  const int upper_base = mc.start[mid];
  MergedPart lower, upper;
  on_two_cores(
      [&] {
        rewrite_faces(mc, rep, in_group, 0, mid, 0, lower, [&](std::size_t f) {
          if (f % 65536 == 0) report(progress, "inner", 0.15 * static_cast<double>(f) / (mid + 1));
          return true;
        });
      },
      [&](const std::atomic<bool>& stop) {
        rewrite_faces(mc, rep, in_group, mid, nf, upper_base, upper,
                      [&](std::size_t f) { return f % 16384 != 0 || !stop; });
      });
  // The second half's merged faces that copy one of the first half's: each is its key's entry in
  // upper.seen, in face order.
  std::vector<std::size_t> copies;
  for (int k = 0; k < upper.seen.size(); ++k) {
    const int first = lower.seen.find(upper.seen, k);
    if (first < 0) continue;
    const std::size_t u = mid + static_cast<std::size_t>(upper.seen.value(k));
    mc.filler[first] = mc.filler[first] && mc.filler[u];
    copies.push_back(u);
  }
  copies.push_back(mid + upper.faces);
  // The second half's faces down after the first's, in runs between the copies (mc.start[mid] is
  // the first half's now).
  std::size_t faces = lower.faces, nodes = static_cast<std::size_t>(mc.start[lower.faces]);
  for (std::size_t r = 0, u = mid; r < copies.size(); u = copies[r++] + 1) {
    const std::size_t end = copies[r];
    if (u >= end) continue;
    const int from = u == mid ? upper_base : mc.start[u];
    const int shift = static_cast<int>(nodes) - from;
    std::copy(mc.nodes.begin() + from, mc.nodes.begin() + mc.start[end], mc.nodes.begin() + nodes);
    std::copy(mc.kind.begin() + u, mc.kind.begin() + end, mc.kind.begin() + faces);
    std::copy(mc.dual.begin() + u, mc.dual.begin() + end, mc.dual.begin() + faces);
    std::copy(mc.filler.begin() + u, mc.filler.begin() + end, mc.filler.begin() + faces);
    for (std::size_t k = u; k < end; ++k) mc.start[faces + (k - u) + 1] = mc.start[k + 1] + shift;
    faces += end - u;
    nodes = static_cast<std::size_t>(mc.start[faces]);
  }
  mc.start.resize(faces + 1);
  mc.nodes.resize(nodes);
  mc.kind.resize(faces);
  mc.dual.resize(faces);
  mc.filler.resize(faces);
  mc.points.insert(mc.points.end(), lower.points.begin(), lower.points.end());
  mc.points.insert(mc.points.end(), upper.points.begin(), upper.points.end());
  mc.segments.insert(mc.segments.end(), lower.segments.begin(), lower.segments.end());
  mc.segments.insert(mc.segments.end(), upper.segments.begin(), upper.segments.end());
  mc.rep = std::move(rep);
  // One segment per pair, selected if any of its facets was.
  std::sort(mc.segments.begin(), mc.segments.end());
  std::vector<std::array<int, 3>> unique_segments;
  for (const auto& sg : mc.segments) {
    if (!unique_segments.empty() && unique_segments.back()[0] == sg[0] && unique_segments.back()[1] == sg[1])
      unique_segments.back()[2] = unique_segments.back()[2] && sg[2];
    else
      unique_segments.push_back(sg);
  }
  mc.segments = std::move(unique_segments);
}

std::vector<std::uint8_t> label_inside(MedialComplex& mc, const Samples& samples, const Umbrellas& umbrellas,
                                       const InsideTest& inside, MedialAxisStats& st, const Progress& progress) {
  const size_t n = mc.num_cells(), nf = mc.size();
  std::vector<std::uint8_t> label(n, 0);
  // 2: a corner of the axis proper; 1: of filler faces only, whose doubtful corners are called
  // outside without asking the B-rep (they lie within the sampling's sag of the surface, where
  // the Voronoi complex meets the boundary anyway). The largest over a cell's faces: each core
  // takes half the faces, and the larger of their two answers counts.
  std::vector<char> used(n, 0), used_upper(n, 0);
  auto mark_used = [&mc](std::vector<char>& u, std::size_t begin, std::size_t end) {
    for (size_t f = begin; f < end; ++f)
      for (int k = mc.start[f]; k < mc.start[f + 1]; ++k)
        if (mc.nodes[k] >= 0) u[mc.nodes[k]] = std::max<char>(u[mc.nodes[k]], mc.filler[f] ? 1 : 2);
  };
  on_two_cores([&] { mark_used(used, 0, nf / 2); },
               [&](const std::atomic<bool>&) {
                 mark_used(used_upper, nf / 2, nf);
                 for (int node : mc.points) used_upper[node] = 2;
                 for (const auto& sg : mc.segments)
                   for (int k = 0; k < 2; ++k) used_upper[sg[k]] = std::max<char>(used_upper[sg[k]], sg[2] ? 1 : 2);
                 // The facets not built (a corner surely outside) count at their other corners too.
                 for (size_t id = 0; id < mc.unbuilt_use.size(); ++id) {
                   if (!mc.unbuilt_use[id]) continue;
                   const int r = mc.rep.empty() ? static_cast<int>(id) : mc.rep[id];
                   used_upper[r] = std::max<char>(used_upper[r], static_cast<char>(mc.unbuilt_use[id]));
                 }
               });
  // The samples' votes, half the cells on each core; the cells they leave in doubt in id order.
  const auto [lo, hi] = bounding_box(samples.points);
  const double diag = norm(sub(hi, lo));
  // Where mark_voted_outside counted a cell's votes, at the centre it still has, they are read.
  const bool voted = mc.voted.size() == n;
  auto votes = [&](std::size_t begin, std::size_t end, std::vector<int>& unsure, auto&& tick) {
    for (size_t id = begin; id < end; ++id) {
      if (!tick(id)) return;
      used[id] = std::max(used[id], used_upper[id]);
      if (!used[id]) continue;
      const Point3& x = mc.centers[id];
      if (beyond_box(x, mc.radii[id], lo, hi, diag, 0.0)) continue;  // label 0
      int settled = voted ? mc.voted[id] : MedialComplex::kNotVoted;
      if (settled == MedialComplex::kNotVoted) {
        int in = 0, out = 0;
        for (int j = 0; j < 4; ++j) {
          const int v = vote(samples, mc.cell_samples[id][j], x);
          in += v > 0;
          out += v < 0;
        }
        settled = votes_settle(in, out);
      }
      if (settled >= 0)
        label[id] = static_cast<std::uint8_t>(settled);
      else
        unsure.push_back(static_cast<int>(id));
    }
  };
  std::vector<int> unsure, unsure_upper;
  on_two_cores(
      [&] {
        votes(0, n / 2, unsure, [&](std::size_t id) {
          if (id % 65536 == 0) report(progress, "inner", 0.2 + 0.4 * static_cast<double>(id) / n);
          return true;
        });
      },
      [&](const std::atomic<bool>& stop) {
        votes(n / 2, n, unsure_upper, [&](std::size_t id) { return id % 16384 != 0 || !stop; });
      });
  unsure.insert(unsure.end(), unsure_upper.begin(), unsure_upper.end());
  if (!unsure.empty()) {
    // Then the reconstruction mesh near the cell's samples; what it cannot settle goes to the
    // exact B-rep classifier.
    const ReconstructionSide mesh(samples, umbrellas);
    std::vector<int> still;
    for (size_t k = 0; k < unsure.size(); ++k) {
      if (k % 16384 == 0) report(progress, "inner", 0.4 + 0.1 * static_cast<double>(k) / unsure.size());
      const int id = unsure[k];
      std::array<int, 4> near;
      for (int j = 0; j < 4; ++j) near[j] = mc.cell_samples[id][j];
      const int side = mesh.side_near(mc.centers[id], near);
      if (side >= 0)
        label[id] = static_cast<std::uint8_t>(side);
      else if (used[id] == 2)
        still.push_back(id);
    }
    unsure.swap(still);
  }
  // The exact classifier takes up to 0.4 ms a point on a core (SOT23's revolved faces; 2 to 6 ms
  // where its rays leave a point to OpenCASCADE's classifier): in batches, between progress checks.
  constexpr size_t kBatch = 256;
  for (size_t b = 0; b < unsure.size(); b += kBatch) {
    report(progress, "inner", 0.5 + 0.2 * static_cast<double>(b) / unsure.size());
    const size_t e = std::min(unsure.size(), b + kBatch);
    std::vector<Point3> pts;
    for (size_t k = b; k < e; ++k) pts.push_back(mc.centers[unsure[k]]);
    const std::vector<std::uint8_t> exact = inside(pts);
    for (size_t k = b; k < e; ++k) label[unsure[k]] = exact[k - b];
  }
  st.exact_inside_tests += unsure.size();
  fill_sheet_holes(mc, samples, label, inside, st);
  open_closed_sample_cells(mc, samples, label);
  return label;
}

// Per piece root: 1 where every corner of the piece lies in the zone of a sharp convex edge
// (kSharpWedgeDot) where its two faces are closer than about two spacings, h / sin(angle / 2)
// from the edge. There the Voronoi diagram of the two faces' samples breaks into fragments that
// are no sheet of the axis (a random polytope's 15.8-degree wedge: a second piece of 66 Voronoi
// faces, refined 31k -> 64k samples though the axis was right).
static std::vector<char> pieces_at_sharp_wedges(
    const MedialComplex& mc, const Samples& samples, const std::vector<int>& root,
    const std::function<std::pair<const int*, const int*>(size_t)>& corners_of, const std::vector<char>& candidate) {
  std::vector<char> at(root.size(), 0);
  std::vector<double> reach(samples.size(), 0.0);
  double max_reach = 0.0;
  std::vector<int> sharp;
  for (size_t i = 0; i < samples.size(); ++i) {
    if (samples.edge_convex[i] != 1) continue;
    const double d = samples.normals_dot(i);
    if (d >= kSharpWedgeDot) continue;
    // The wedge's angle is pi - acos(d); sin of half of it is sqrt((1 + d) / 2).
    reach[i] = samples.spacing / std::sqrt(std::max((1.0 + d) / 2.0, 1e-6));
    max_reach = std::max(max_reach, reach[i]);
    sharp.push_back(static_cast<int>(i));
  }
  if (sharp.empty() || samples.spacing <= 0) return at;
  PointGrid grid(max_reach);
  for (int i : sharp) grid.insert(samples.points[i], i);
  auto position = [&](int node) -> const Point3& {
    return node >= 0 ? mc.centers[node] : samples.points[-node - 1];
  };
  auto near_wedge = [&](const Point3& p) {
    return grid.any_near(p, max_reach, [&](int i) {
      const Point3& q = samples.points[i];
      const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
      return dx * dx + dy * dy + dz * dz <= reach[i] * reach[i];
    });
  };
  for (size_t r = 0; r < root.size(); ++r)
    if (candidate[r]) at[r] = 1;
  for (size_t i = 0; i < root.size(); ++i) {
    const int r = root[i];
    if (!at[r]) continue;
    const auto [begin, end] = corners_of(i);
    for (const int* node = begin; node != end && at[r]; ++node)
      if (!near_wedge(position(*node))) at[r] = 0;
  }
  return at;
}

// Keeps faces whose Voronoi vertices are all inside, repairs the topology, then keeps the
// largest connected piece (the inner medial axis of a connected solid is connected, homotopy
// equivalent to the solid) and any other piece that reaches the boundary.
MedialMesh extract_inner(MedialComplex& mc, const std::vector<std::uint8_t>& inside, const Samples& samples,
                         int solid_index, MedialAxisStats& st, const Progress& progress) {
  // Half the faces on each core.
  auto inner_faces = [&](std::size_t begin, std::size_t end, std::vector<int>& out) {
    for (size_t f = begin; f < end; ++f) {
      bool in = true;
      for (int k = mc.start[f]; k < mc.start[f + 1] && in; ++k)
        if (mc.nodes[k] >= 0 && !inside[mc.nodes[k]]) in = false;
      if (in) out.push_back(static_cast<int>(f));
    }
  };
  std::vector<int> inner, inner_upper;
  on_two_halves(mc.size(), [&](int part, std::size_t begin, std::size_t end) {
    inner_faces(begin, end, part ? inner_upper : inner);
  });
  inner.insert(inner.end(), inner_upper.begin(), inner_upper.end());
  // The Voronoi part first, its topology repaired; then the completion triangles that keep it,
  // the paper's before the fans that close their rims. The fans on the second core meanwhile
  // (both only read mc).
  report(progress, "inner", 0.72);
  std::vector<int> voronoi, completion;
  for (int f : inner) (mc.kind[f] == FaceKind::Voronoi ? voronoi : completion).push_back(f);
  std::vector<std::array<int, 3>> segments;
  for (const auto& sg : mc.segments)
    if (inside[sg[0]] && inside[sg[1]]) segments.push_back(sg);
  AxisCells repaired;
  std::vector<std::array<int, 3>> fans;
  on_two_cores([&] { repaired = collapse_fillers(mc, voronoi, segments, st); },
               [&](const std::atomic<bool>&) { fans = fan_completions(mc, inner, inside); });
  for (const auto& t : fans) {
    completion.push_back(static_cast<int>(mc.size()));
    mc.add({t[0], t[1], t[2]}, FaceKind::Edge);
  }
  st.fan_triangles += fans.size();
  report(progress, "inner", 0.85);
  const AxisCells cells = attach_by_expansion(mc, std::move(repaired), completion, st);
  report(progress, "inner", 0.9);

  // Pieces: union-find over faces and edges (items) sharing a corner. A stray piece floats
  // inside; a piece that reaches the boundary (8 or more completion triangles at convex edges and
  // corners) is medial axis that a too coarse sampling cut off from the rest (a neck thinner than
  // the spacing): it is kept.
  const size_t nf = cells.faces.size(), items = nf + cells.edges.size();
  auto corners_of = [&](size_t i) -> std::pair<const int*, const int*> {
    if (i < nf) return {mc.nodes.data() + mc.start[cells.faces[i]], mc.nodes.data() + mc.start[cells.faces[i] + 1]};
    const auto& e = cells.edges[i - nf];
    return {e.data(), e.data() + 2};
  };
  NodeMap<int> node_owner(mc.num_cells(), samples.size(), -1);
  std::vector<int> parent(items);
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < items; ++i) {
    const auto [begin, end] = corners_of(i);
    for (const int* node = begin; node != end; ++node) {
      int& owner = node_owner[*node];
      if (owner < 0)
        owner = static_cast<int>(i);
      else
        parent[find_root(parent, static_cast<int>(i))] = find_root(parent, owner);
    }
  }
  // Per root: its piece's items, completion faces and Voronoi faces (flat arrays over the items).
  std::vector<int> root(items), piece_items(items, 0), piece_completion(items, 0), piece_voronoi(items, 0);
  for (size_t i = 0; i < items; ++i) {
    root[i] = find_root(parent, static_cast<int>(i));
    ++piece_items[root[i]];
    const bool completion = i < nf && mc.kind[cells.faces[i]] != FaceKind::Voronoi;
    piece_completion[root[i]] += completion;
    piece_voronoi[root[i]] += i < nf && !completion;
  }
  // A piece without a Voronoi face (completion triangles of a fan, loose 1-D edges) is a speck
  // where the fans of a sharp wedge or a rim cross, not a sheet that broke off: it is not counted
  // as a piece (a random 8-face polytope's 19-degree wedge: its right axis was refined once for
  // them, 30,736 -> 62,700 samples). So is a piece of Voronoi faces wholly inside the thin zone
  // of a sharp wedge (pieces_at_sharp_wedges).
  int best = -1, best_size = 0;  // the largest piece; of equal ones, the smallest root
  for (size_t r = 0; r < items; ++r)
    if (piece_items[r] > best_size) best = static_cast<int>(r), best_size = piece_items[r];
  std::vector<char> stray_voronoi(items, 0);
  for (size_t r = 0; r < items; ++r)
    stray_voronoi[r] = piece_items[r] > 0 && piece_voronoi[r] > 0 && static_cast<int>(r) != best;
  const std::vector<char> at_wedge = pieces_at_sharp_wedges(mc, samples, root, corners_of, stray_voronoi);
  st.components = 0;
  st.specks = 0;
  for (size_t r = 0; r < items; ++r) {
    if (piece_items[r] == 0) continue;
    // An axis of 1-D edges only (a torus's circle) is one piece all the same.
    if ((piece_voronoi[r] > 0 && !at_wedge[r]) || static_cast<int>(r) == best)
      ++st.components;
    else
      ++st.specks;
  }
  std::vector<char> keep(items, 0);
  if (best >= 0) keep[best] = 1;
  for (size_t r = 0; r < items; ++r)
    if (piece_items[r] > 0 && piece_completion[r] >= 8 && piece_items[r] >= best_size / 100) keep[r] = 1;
  st.kept_components = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 1));

  report(progress, "inner", 0.95);
  // The kept items' corners numbered in the order they come, then the mesh's arrays filled at
  // their final sizes, the vertices on two cores (grown by doubling, the inner stage took 0.025 s
  // longer at 250k samples: 738k vertices, 538k faces).
  MedialMesh mesh;
  AxisCells out;
  NodeMap<int> out_index = std::move(node_owner);  // the pieces are found: its arrays again
  out_index.fill(-1);
  std::vector<int> node_of;
  std::size_t kept_faces = 0, kept_corners = 0, kept_edges = 0;
  for (size_t i = 0; i < items; ++i) {
    if (!keep[root[i]]) continue;
    const auto [begin, end] = corners_of(i);
    (i < nf ? kept_faces : kept_edges) += 1;
    if (i < nf) kept_corners += static_cast<std::size_t>(end - begin);
    for (const int* node = begin; node != end; ++node) {
      int& index = out_index[*node];
      if (index < 0) index = static_cast<int>(node_of.size()), node_of.push_back(*node);
    }
  }
  mesh.face_vertices.reserve(kept_corners);
  mesh.face_start.reserve(kept_faces + 1);
  mesh.kind.reserve(kept_faces);
  mesh.solid.reserve(kept_faces);
  out.faces.reserve(kept_faces);
  mesh.edges.reserve(kept_edges);
  mesh.edge_solid.reserve(kept_edges);
  out.edges.reserve(kept_edges);
  for (size_t i = 0; i < items; ++i) {
    if (!keep[root[i]]) continue;
    const auto [begin, end] = corners_of(i);
    if (i < nf) {
      out.faces.push_back(cells.faces[i]);
      for (const int* node = begin; node != end; ++node) mesh.face_vertices.push_back(out_index[*node]);
      mesh.face_start.push_back(static_cast<int>(mesh.face_vertices.size()));
      mesh.kind.push_back(mc.kind[cells.faces[i]]);
      mesh.solid.push_back(solid_index);
    } else {
      out.edges.push_back(cells.edges[i - nf]);
      mesh.edges.push_back({out_index[begin[0]], out_index[begin[1]]});
      mesh.edge_solid.push_back(solid_index);
    }
  }
  // A medial axis that is a point (a sphere's centre) has no faces: keep its vertex.
  if (mesh.num_faces() == 0 && mesh.num_edges() == 0) {
    for (int node : mc.points) {
      if (!inside[node] || out_index[node] >= 0) continue;
      out_index[node] = static_cast<int>(node_of.size());
      node_of.push_back(node);
    }
  }
  // The vertices: Voronoi vertices with their radius, samples on the boundary with 0 (their
  // medial ball).
  mesh.vertices.resize(node_of.size());
  mesh.radius.resize(node_of.size());
  on_two_halves(node_of.size(), [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const int node = node_of[k];
      mesh.vertices[k] = node >= 0 ? mc.centers[node] : samples.points[-node - 1];
      mesh.radius[k] = node >= 0 ? mc.radii[node] : 0.0;
    }
  }, 1 << 14);
  st.dropped_faces = 0;
  for (size_t f = 0; f < mc.size(); ++f) st.dropped_faces += !mc.filler[f];
  st.filler_faces = 0;
  for (int f : out.faces) st.dropped_faces -= !mc.filler[f], st.filler_faces += mc.filler[f];
  st.bare_edges = out.edges.size();
  return mesh;
}

}  // namespace cadmedial::internal
