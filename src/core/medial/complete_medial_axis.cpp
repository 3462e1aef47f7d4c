#include "complete_medial_axis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <unordered_map>

#include "geometry_3.h"
#include "../two_cores.h"

namespace cadmedial::internal {

namespace {

// Records sample s once, for star_cells to find its Voronoi vertices.
void record_star(int s, MedialComplex& mc, std::vector<char>& recorded) {
  if (recorded[s]) return;
  recorded[s] = 1;
  mc.star_sample.push_back(s);
}

std::vector<char> recorded_stars(const MedialComplex& mc, std::size_t samples) {
  std::vector<char> recorded(samples, 0);
  for (int s : mc.star_sample) recorded[s] = 1;
  return recorded;
}

// The finite cells (ids) that hold each of `wanted` (samples), CSR: start[i]..start[i + 1] for
// wanted[i], in id order. One pass over the cells on two cores, each half's after the other's
// (CGAL's incident_cells walks each star apart: 30 ms at 65k samples for the stars, and 0.3 s
// for the triplets' is_facet on tail_turbine, whose edge samples hold hundreds of slivers).
void cells_holding(const MedialComplex& mc, const std::vector<int>& wanted, std::size_t samples,
                   std::vector<int>& start, std::vector<int>& cells) {
  std::vector<int> slot(samples, -1);
  for (std::size_t i = 0; i < wanted.size(); ++i) slot[wanted[i]] = static_cast<int>(i);
  const std::size_t nc = mc.num_cells(), ns = wanted.size();
  auto for_each_incidence = [&](std::size_t begin, std::size_t end, auto&& fn) {
    for (std::size_t c = begin; c < end; ++c)
      for (int s : mc.cell_samples[c])
        if (slot[s] >= 0) fn(slot[s], static_cast<int>(c));
  };
  std::vector<int> lower_count(ns, 0), upper_count(ns, 0);
  on_two_halves(nc, [&](int part, std::size_t begin, std::size_t end) {
    std::vector<int>& count = part ? upper_count : lower_count;
    for_each_incidence(begin, end, [&](int i, int) { ++count[i]; });
  });
  start.assign(ns + 1, 0);
  for (std::size_t i = 0; i < ns; ++i) start[i + 1] = start[i] + lower_count[i] + upper_count[i];
  cells.resize(start[ns]);
  for (std::size_t i = 0; i < ns; ++i) upper_count[i] = start[i] + lower_count[i], lower_count[i] = start[i];
  on_two_halves(nc, [&](int part, std::size_t begin, std::size_t end) {
    std::vector<int>& next = part ? upper_count : lower_count;
    for_each_incidence(begin, end, [&](int i, int c) { cells[next[i]++] = c; });
  });
}

bool holds(const MedialComplex& mc, int cell, int s) {
  const auto& v = mc.cell_samples[cell];
  return v[0] == s || v[1] == s || v[2] == s || v[3] == s;
}

}  // namespace

// 4.2.2 ProcConvexEdges: triangle s v1 v2 for the Voronoi edge dual to each triplet triangle,
// and the fill triangles s s' v where v is a Voronoi vertex of s' too. The triangle s sl sr is a
// Delaunay facet when two finite cells hold all three (one: a facet of the hull; none: the
// sampling did not make it Delaunay); v1 is the one with the smaller id.
void complete_convex_edges(const std::vector<Vertex>& handle, const Samples& samples, MedialComplex& mc,
                           MedialAxisStats& st) {
  std::set<std::array<int, 3>> fills;
  std::vector<char> recorded = recorded_stars(mc, samples.size());
  std::vector<int> centre;
  for (const Triplet& t : samples.triplets) centre.push_back(t.s);
  std::sort(centre.begin(), centre.end());
  centre.erase(std::unique(centre.begin(), centre.end()), centre.end());
  std::vector<int> start, cells;
  cells_holding(mc, centre, samples.size(), start, cells);
  for (const Triplet& t : samples.triplets) {
    if (handle[t.s] == Vertex() || handle[t.sl] == Vertex() || handle[t.sr] == Vertex()) continue;
    const std::size_t at = static_cast<std::size_t>(std::lower_bound(centre.begin(), centre.end(), t.s) - centre.begin());
    int two[2], found = 0;
    for (int k = start[at]; k < start[at + 1] && found < 2; ++k) {
      const int c = cells[k];
      if (holds(mc, c, t.sl) && holds(mc, c, t.sr)) two[found++] = c;
    }
    if (found != 2) continue;
    const int v1 = two[0], v2 = two[1];
    mc.add({MedialComplex::sample_node(t.s), v1, v2}, FaceKind::Edge);
    record_star(t.s, mc, recorded);
    ++st.edge_triangles;
    for (int nb : {t.prev, t.next}) {
      if (nb < 0 || handle[nb] == Vertex()) continue;
      for (const int id : {v1, v2}) {
        // v in V_s' means s' is among v's nearest samples; with cospherical samples that need
        // not make s' a vertex of this very cell, so ask the distance.
        const double to_nb = norm(sub(mc.centers[id], samples.points[nb]));
        if (!holds(mc, id, nb) && std::abs(to_nb - mc.radii[id]) > 1e-9 * mc.radii[id]) continue;
        std::array<int, 3> key{std::min(t.s, nb), std::max(t.s, nb), id};
        if (!fills.insert(key).second) continue;
        mc.add({MedialComplex::sample_node(t.s), MedialComplex::sample_node(nb), id}, FaceKind::Edge);
        record_star(nb, mc, recorded);
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
  std::vector<std::array<int, 2>> edges;  // Voronoi edges joined to p, by their cell ids
  std::vector<char> recorded = recorded_stars(mc, samples.size());
  for (size_t p = 0; p < samples.size(); ++p) {
    if (samples.tag[p] != SampleTag::Corner || !samples.nonconcave[p] || handle[p] == Vertex()) continue;
    facets.clear();
    edges.clear();
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
      edges.push_back({std::min(mc.cell_id(c), mc.cell_id(n)), std::max(mc.cell_id(c), mc.cell_id(n))});
    }
    // CGAL lists a facet from whichever of its two cells lies lower in memory, in an order that
    // follows: sorted by cell ids, the triangles (and so the output) are the same in every run.
    std::sort(edges.begin(), edges.end());
    for (const auto& [a, b] : edges) {
      mc.add({MedialComplex::sample_node(static_cast<int>(p)), a, b}, FaceKind::Corner);
      record_star(static_cast<int>(p), mc, recorded);
      ++st.corner_triangles;
    }
  }
}

// The finite cells incident to a sample are those with it among their samples. Only the set of
// cells matters: they are listed by id.
void star_cells(MedialComplex& mc, std::size_t samples) {
  cells_holding(mc, mc.star_sample, samples, mc.star_start, mc.star_cells);
}

}  // namespace cadmedial::internal

namespace cadmedial::internal {

// The completion joins a sample s to Voronoi edges of its cell V_s: the triangles at s form a fan
// whose rim (the link of s) should be one path, the edge of the medial sheet as seen from s. Where
// the sheet's edge runs through further vertices of V_s between two joined Voronoi edges, the rim
// breaks and every break closes a loop around s that the solid does not have. Each break is
// bridged by the shortest path of axis edges between vertices of V_s, coned to s: the triangles
// lie in the convex cell V_s, so they cross nothing.
std::vector<std::array<int, 3>> fan_completions(const MedialComplex& mc, const std::vector<int>& faces,
                                                const std::vector<std::uint8_t>& inside) {
  std::vector<char> in_star(mc.num_cells(), 0);
  for (int c : mc.star_cells) in_star[c] = 1;
  // Per sample, its completion faces; per star cell, its selected Voronoi faces (CSR over node
  // - lo, in the order of `faces`).
  int lo = 0;
  for (int f : faces)
    if (mc.kind[f] != FaceKind::Voronoi)
      for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) lo = std::min(lo, mc.nodes[k]);
  const std::size_t span = mc.num_cells() + static_cast<std::size_t>(-lo);
  std::vector<int> at_start(span + 1, 0), at;
  auto for_each_at = [&](auto&& fn) {
    for (int f : faces) {
      const bool completion = mc.kind[f] != FaceKind::Voronoi;
      if (!completion && mc.filler[f]) continue;
      for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) {
        const int node = mc.nodes[k];
        if ((node < 0 && completion) || (node >= 0 && !completion && in_star[node])) fn(node - lo, f);
      }
    }
  };
  for_each_at([&](int r, int) { ++at_start[r + 1]; });
  for (std::size_t r = 0; r < span; ++r) at_start[r + 1] += at_start[r];
  at.resize(at_start[span]);
  {
    std::vector<int> fill(at_start.begin(), at_start.end() - 1);
    for_each_at([&](int r, int f) { at[fill[r]++] = f; });
  }
  auto at_node = [&](int node) {
    const int r = node - lo;
    return std::make_pair(at.begin() + at_start[r], at.begin() + at_start[r + 1]);
  };
  std::vector<std::array<int, 3>> added;
  std::unordered_map<int, int> parent;  // union-find over rim nodes
  auto root = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::unordered_map<int, std::vector<std::pair<int, bool>>> adj;  // node -> (node, rim edge)
  for (size_t i = 0; i < mc.star_sample.size(); ++i) {
    const int s = MedialComplex::sample_node(mc.star_sample[i]);
    if (s < lo) continue;  // no completion face at s
    const auto [fs_begin, fs_end] = at_node(s);
    if (fs_begin == fs_end) continue;
    parent.clear();
    adj.clear();
    for (auto fs = fs_begin; fs != fs_end; ++fs) {
      const int f = *fs;
      int ends[2], k2 = 0;
      for (int k = mc.start[f]; k < mc.start[f + 1]; ++k)
        if (mc.nodes[k] != s && k2 < 2) ends[k2++] = mc.nodes[k];
      if (k2 != 2) continue;
      for (int x : ends) parent.emplace(x, x);
      parent[root(ends[0])] = root(ends[1]);
      adj[ends[0]].push_back({ends[1], true});
      adj[ends[1]].push_back({ends[0], true});
    }
    std::set<int> star;
    for (int k = mc.star_start[i]; k < mc.star_start[i + 1]; ++k)
      if (inside[mc.star_cells[k]]) star.insert(mc.star_cells[k]);
    for (int a : star) {
      const auto [fa_begin, fa_end] = at_node(a);
      for (auto fa = fa_begin; fa != fa_end; ++fa) {
        const int f = *fa;
        for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) {
          const int next = k + 1 < mc.start[f + 1] ? mc.nodes[k + 1] : mc.nodes[mc.start[f]];
          if (mc.nodes[k] == a && next != a && star.count(next)) {
            adj[a].push_back({next, false});
            adj[next].push_back({a, false});
          }
        }
      }
    }
    // Join the rim's pieces one at a time along shortest paths.
    for (;;) {
      std::set<int> roots;
      for (auto& [x, p] : parent) roots.insert(root(x));
      if (roots.size() < 2) break;
      const int from = *roots.begin();
      std::unordered_map<int, int> came;
      std::vector<int> queue;
      for (auto& [x, p] : parent)
        if (root(x) == from) queue.push_back(x), came[x] = x;
      int hit = -1;
      for (size_t h = 0; h < queue.size() && hit < 0; ++h)
        for (const auto& [y, rim] : adj[queue[h]]) {
          if (came.count(y)) continue;
          came[y] = queue[h];
          if (parent.count(y) && root(y) != from) {
            hit = y;
            break;
          }
          queue.push_back(y);
        }
      if (hit < 0) break;  // no path of axis edges inside V_s: leave the break
      for (int y = hit; came[y] != y; y = came[y]) {
        const int x = came[y];
        bool rim = false;
        for (const auto& [z, r] : adj[x]) rim = rim || (z == y && r);
        if (!rim) {
          added.push_back({s, x, y});
        }
        parent.emplace(x, x);
        parent.emplace(y, y);
        parent[root(x)] = root(y);
      }
    }
  }
  return added;
}

}  // namespace cadmedial::internal
