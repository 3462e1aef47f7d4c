#include "preserve_topology.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "../two_cores.h"

namespace cadmedial::internal {

namespace {

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
int key_low(std::uint64_t key) { return static_cast<int>(static_cast<std::uint32_t>(key >> 32)); }
int key_high(std::uint64_t key) { return static_cast<int>(static_cast<std::uint32_t>(key)); }

template <class F>
void for_each_side(const MedialComplex& mc, int f, F&& fn) {
  const int b = mc.start[f], e = mc.start[f + 1];
  for (int k = b; k < e; ++k) fn(k - b, mc.nodes[k], mc.nodes[k + 1 < e ? k + 1 : b]);
}

// The complex's edges (sides of faces and lone edges): ids per face side (CSR like the faces),
// and per edge the faces that hold it.
struct EdgeIncidence {
  std::vector<int> face_start{0};  ///< per face slot (index into `faces`), into face_edge
  std::vector<int> face_edge;      ///< edge id of side k (corner k -> k+1)
  std::vector<int> edge_start{0};  ///< per edge, into edge_face
  std::vector<int> edge_face;      ///< face slots
  std::vector<std::uint64_t> key;  ///< per edge, its two corners
};

// Only the face sides for which keep_side(slot, a, b) holds are indexed (face_edge -1 for the
// others).
template <class KeepSide>
EdgeIncidence edge_incidence(const MedialComplex& mc, const std::vector<int>& faces,
                             const std::vector<std::array<int, 3>>& lone, KeepSide&& keep_side) {
  EdgeIncidence g;
  struct Entry {
    std::uint64_t key;
    int slot, pos;  ///< -1 for a lone edge
  };
  std::vector<Entry> entries;
  {
    std::size_t sides = lone.size();
    for (int f : faces) sides += mc.start[f + 1] - mc.start[f];
    entries.reserve(sides);
  }
  for (size_t i = 0; i < faces.size(); ++i) {
    for_each_side(mc, faces[i], [&](int k, int a, int b) {
      if (keep_side(static_cast<int>(i), a, b))
        entries.push_back({edge_key(a, b), static_cast<int>(i), g.face_start.back() + k});
    });
    g.face_start.push_back(g.face_start.back() + (mc.start[faces[i] + 1] - mc.start[faces[i]]));
  }
  for (const auto& e : lone) entries.push_back({edge_key(e[0], e[1]), -1, -1});
  // Sorted by (key, slot): a counting sort on the low corner (cells 0.., then samples, whose
  // negative node numbers come last as unsigned keys), then each small bucket (a million entries
  // at 65k samples: three times faster than one std::sort).
  int min_low = 0;
  for (const Entry& e : entries) min_low = std::min(min_low, key_low(e.key));
  const int nc = static_cast<int>(mc.num_cells());
  auto bucket = [&](const Entry& e) {
    const int low = key_low(e.key);
    return low >= 0 ? low : nc + (low - min_low);
  };
  std::vector<int> bucket_start(static_cast<std::size_t>(nc) - min_low + 1, 0);
  for (const Entry& e : entries) ++bucket_start[bucket(e) + 1];
  for (std::size_t b = 1; b < bucket_start.size(); ++b) bucket_start[b] += bucket_start[b - 1];
  {
    std::vector<Entry> sorted(entries.size());
    std::vector<int> fill(bucket_start.begin(), bucket_start.end() - 1);
    for (const Entry& e : entries) sorted[fill[bucket(e)]++] = e;
    entries.swap(sorted);
  }
  // The buckets on two cores, half the entries each.
  auto sort_buckets = [&](std::size_t begin, std::size_t end) {
    for (std::size_t b = begin; b < end; ++b)
      std::sort(entries.begin() + bucket_start[b], entries.begin() + bucket_start[b + 1],
                [](const Entry& x, const Entry& y) { return x.key < y.key || (x.key == y.key && x.slot < y.slot); });
  };
  const std::size_t buckets = bucket_start.size() - 1;
  const std::size_t mid = static_cast<std::size_t>(
      std::lower_bound(bucket_start.begin(), bucket_start.end(), bucket_start.back() / 2) - bucket_start.begin());
  on_two_cores([&] { sort_buckets(0, std::min(mid, buckets)); },
               [&](const std::atomic<bool>&) { sort_buckets(std::min(mid, buckets), buckets); });
  g.face_edge.assign(g.face_start.back(), -1);
  g.edge_face.reserve(entries.size());
  for (size_t k = 0; k < entries.size(); ++k) {
    if (k == 0 || entries[k].key != entries[k - 1].key) {
      if (k > 0) g.edge_start.push_back(static_cast<int>(g.edge_face.size()));
      g.key.push_back(entries[k].key);
    }
    if (entries[k].slot < 0) continue;
    g.face_edge[entries[k].pos] = static_cast<int>(g.key.size()) - 1;
    g.edge_face.push_back(entries[k].slot);
  }
  g.edge_start.push_back(static_cast<int>(g.edge_face.size()));
  return g;
}

// Edges no face holds any more but which no collapse removed either stay as 1-cells. Those with a
// free end collapse in turn (with the end); what is left carries the topology. A pinned(node) is
// the corner of a face that stays, whose sides g may leave out: it never has a free end.
template <class Pinned>
std::vector<std::array<int, 2>> essential_bare_edges(const EdgeIncidence& g, const std::vector<int>& count,
                                                     const std::vector<char>& removed,
                                                     const std::vector<char>& kept_segment, Pinned&& pinned) {
  const size_t ne = g.key.size();
  // Per corner (indexed by node from the smallest, a sample's negative number, up): the live
  // edges at it, and the bare ones (in edge order). Flat arrays, not a sort of a million ends.
  int lo = 0, hi = -1;
  for (size_t e = 0; e < ne; ++e) {
    if (removed[e]) continue;
    lo = std::min(lo, key_low(g.key[e]));
    hi = std::max(hi, key_high(g.key[e]));
  }
  const std::size_t span = static_cast<std::size_t>(hi - lo + 1);
  std::vector<int> degree(span, 0), bare_start(span + 1, 0);
  std::vector<char> bare(ne, 0);
  for (size_t e = 0; e < ne; ++e) {
    if (removed[e]) continue;
    const int a = key_low(g.key[e]) - lo, b = key_high(g.key[e]) - lo;
    ++degree[a], ++degree[b];
    if (count[e] > 0) continue;
    bare[e] = 1;
    ++bare_start[a + 1], ++bare_start[b + 1];
  }
  for (std::size_t r = 0; r < span; ++r) bare_start[r + 1] += bare_start[r];
  std::vector<int> bare_at(bare_start[span]);
  {
    std::vector<int> fill(bare_start.begin(), bare_start.end() - 1);
    for (size_t e = 0; e < ne; ++e)
      if (bare[e]) bare_at[fill[key_low(g.key[e]) - lo]++] = static_cast<int>(e), bare_at[fill[key_high(g.key[e]) - lo]++] = static_cast<int>(e);
  }
  for (size_t r = 0; r < span; ++r)
    if (pinned(static_cast<int>(r) + lo)) degree[r] += 2;
  std::vector<int> stack;
  for (size_t r = 0; r < span; ++r)
    if (degree[r] == 1) stack.push_back(static_cast<int>(r));
  while (!stack.empty()) {
    const int r = stack.back();
    stack.pop_back();
    if (degree[r] != 1) continue;
    for (int k = bare_start[r]; k < bare_start[r + 1]; ++k) {
      const int e = bare_at[k];
      if (!bare[e] || kept_segment[e]) continue;
      bare[e] = 0;
      for (int s : {key_low(g.key[e]) - lo, key_high(g.key[e]) - lo})
        if (--degree[s] == 1) stack.push_back(s);
    }
  }
  std::vector<std::array<int, 2>> left;
  for (size_t e = 0; e < ne; ++e)
    if (bare[e]) left.push_back({key_low(g.key[e]), key_high(g.key[e])});
  return left;
}

}  // namespace

AxisCells collapse_fillers(const MedialComplex& mc, const std::vector<int>& faces,
                           const std::vector<std::array<int, 3>>& segments, MedialAxisStats& st) {
  // Only the sides of filler faces and the segments can come free or bare: the incidence holds
  // those, and the other faces' sides between two such corners (the only ones that can be the
  // same edges). The selected faces' corners are pinned.
  int lo = 0, hi = -1;
  for (int f : faces)
    for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) lo = std::min(lo, mc.nodes[k]), hi = std::max(hi, mc.nodes[k]);
  for (const auto& sg : segments) lo = std::min({lo, sg[0], sg[1]}), hi = std::max({hi, sg[0], sg[1]});
  // 1: a filler's or a segment's corner; 2: a selected face's; 3: both.
  std::vector<std::uint8_t> role(static_cast<std::size_t>(hi - lo + 1), 0);
  for (int f : faces)
    for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) role[mc.nodes[k] - lo] |= mc.filler[f] ? 1 : 2;
  for (const auto& sg : segments) role[sg[0] - lo] |= 1, role[sg[1] - lo] |= 1;
  const EdgeIncidence g = edge_incidence(mc, faces, segments, [&](int slot, int a, int b) {
    return mc.filler[faces[slot]] || ((role[a - lo] & 1) && (role[b - lo] & 1));
  });
  const size_t ne = g.key.size();
  // A segment of a selected facet is axis proper: it stays even with a free end.
  std::vector<char> kept_segment(ne, 0);
  for (const auto& sg : segments) {
    if (sg[2]) continue;
    const auto it = std::lower_bound(g.key.begin(), g.key.end(), edge_key(sg[0], sg[1]));
    kept_segment[it - g.key.begin()] = 1;
  }
  std::vector<int> count(ne);
  for (size_t e = 0; e < ne; ++e) count[e] = g.edge_start[e + 1] - g.edge_start[e];
  std::vector<char> alive(faces.size(), 1), removed(ne, 0);
  std::vector<int> queue;
  for (size_t i = 0; i < faces.size(); ++i)
    if (mc.filler[faces[i]]) queue.push_back(static_cast<int>(i));
  // Elementary collapse: a filler face with a side no other face holds goes, with that side.
  // FIFO from the outermost fillers inward, so what stays hugs the selected facets.
  for (size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    if (!alive[i]) continue;
    int free_edge = -1;
    for (int k = g.face_start[i]; k < g.face_start[i + 1] && free_edge < 0; ++k)
      if (count[g.face_edge[k]] == 1) free_edge = g.face_edge[k];
    if (free_edge < 0) continue;  // queued again if a neighbour's collapse frees a side
    alive[i] = 0;
    removed[free_edge] = 1;
    for (int k = g.face_start[i]; k < g.face_start[i + 1]; ++k) {
      const int e = g.face_edge[k];
      if (--count[e] != 1) continue;
      for (int j = g.edge_start[e]; j < g.edge_start[e + 1]; ++j) {
        const int other = g.edge_face[j];
        if (alive[other] && mc.filler[faces[other]]) queue.push_back(other);
      }
    }
  }
  AxisCells left;
  for (size_t i = 0; i < faces.size(); ++i)
    if (alive[i]) left.faces.push_back(faces[i]);
  left.edges = essential_bare_edges(g, count, removed, kept_segment,
                                    [&](int node) { return node >= lo && node <= hi && (role[node - lo] & 2); });
  return left;
}

AxisCells attach_by_expansion(const MedialComplex& mc, AxisCells base, const std::vector<int>& candidates,
                              MedialAxisStats& st) {
  // Only corners and sides of the candidates matter: the sets hold the complex's cells among them.
  // Corners in flat arrays over the candidates' range of nodes (the base has a million sides).
  int lo = 0, hi = -1;
  for (int f : candidates)
    for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) lo = std::min(lo, mc.nodes[k]), hi = std::max(hi, mc.nodes[k]);
  const std::size_t span = static_cast<std::size_t>(hi - lo + 1);
  // 1 a candidate's corner, 2 also one of the complex's.
  std::vector<std::uint8_t> corner(span, 0);
  for (int f : candidates)
    for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) corner[mc.nodes[k] - lo] = 1;
  auto candidate_corner = [&](int a) { return a >= lo && a <= hi && corner[a - lo] != 0; };
  auto in_complex = [&](int a) { return a >= lo && a <= hi && corner[a - lo] == 2; };
  std::unordered_set<std::uint64_t> edges;
  auto add_side = [&](int a, int b) {
    const bool ca = candidate_corner(a), cb = candidate_corner(b);
    if (ca) corner[a - lo] = 2;
    if (cb) corner[b - lo] = 2;
    if (ca && cb) edges.insert(edge_key(a, b));
  };
  auto add_face = [&](int f) { for_each_side(mc, f, [&](int, int a, int b) { add_side(a, b); }); };
  for (int f : base.faces) add_face(f);
  for (const auto& e : base.edges) add_side(e[0], e[1]);
  // A triangle keeps the homotopy type when what it shares with the complex is contractible: one
  // corner, one side, or two sides. Two corners without their side would close a loop; all three
  // sides would close a void or fill a loop the Voronoi part does not have.
  auto attaches = [&](int f) {
    if (mc.start[f + 1] - mc.start[f] != 3) return false;
    int shared_corners = 0, shared_edges = 0;
    for_each_side(mc, f, [&](int, int a, int b) {
      shared_corners += in_complex(a);
      shared_edges += edges.count(edge_key(a, b)) > 0;
    });
    return (shared_corners == 1 && shared_edges == 0) || (shared_corners == 2 && shared_edges == 1) ||
           (shared_corners == 3 && shared_edges == 2);
  };
  // Whether a face attaches changes only when a face at one of its corners is added: faces that
  // do not attach yet wait at their corners (few do: a table by corner, not an array over the
  // span, which took 14 ms to allocate at 250k samples for 1.6 million nodes).
  std::unordered_map<int, std::vector<int>> waiting;
  std::vector<char> done(candidates.size(), 0);
  std::vector<int> queue(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i) queue[i] = static_cast<int>(i);
  for (size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    if (done[i]) continue;
    const int f = candidates[i];
    if (!attaches(f)) {
      for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) waiting[mc.nodes[k]].push_back(i);
      continue;
    }
    done[i] = 1;
    add_face(f);
    base.faces.push_back(f);
    if (waiting.empty()) continue;
    for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) {
      const auto w = waiting.find(mc.nodes[k]);
      if (w == waiting.end()) continue;
      for (int j : w->second)
        if (!done[j]) queue.push_back(j);
      waiting.erase(w);
    }
  }
  for (char d : done) st.unattached_faces += !d;
  return base;
}

}  // namespace cadmedial::internal
