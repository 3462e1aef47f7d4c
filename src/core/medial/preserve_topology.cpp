#include "preserve_topology.h"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <unordered_set>
#include <cstdint>

namespace cadmedial::internal {

namespace {

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
int key_low(std::uint64_t key) { return static_cast<int>(static_cast<std::uint32_t>(key >> 32)); }
int key_high(std::uint64_t key) { return static_cast<int>(static_cast<std::uint32_t>(key)); }

// The faces' edges: ids per face corner (CSR like the faces), and per edge its faces.
struct EdgeIncidence {
  std::vector<int> face_start{0};  ///< per face slot (index into `faces`), into face_edge
  std::vector<int> face_edge;      ///< edge id of corner k -> k+1
  std::vector<int> edge_start{0};  ///< per edge, into edge_face
  std::vector<int> edge_face;      ///< face slots
  std::vector<std::uint64_t> key;  ///< per edge, its two corners
};

EdgeIncidence edge_incidence(const MedialComplex& mc, const std::vector<int>& faces) {
  EdgeIncidence g;
  struct Entry {
    std::uint64_t key;
    int slot, pos;
  };
  std::vector<Entry> entries;
  for (size_t i = 0; i < faces.size(); ++i) {
    const int b = mc.start[faces[i]], e = mc.start[faces[i] + 1];
    for (int k = b; k < e; ++k) {
      const int next = k + 1 < e ? k + 1 : b;
      entries.push_back({edge_key(mc.nodes[k], mc.nodes[next]), static_cast<int>(i),
                         g.face_start.back() + (k - b)});
    }
    g.face_start.push_back(g.face_start.back() + (e - b));
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& x, const Entry& y) { return x.key < y.key || (x.key == y.key && x.slot < y.slot); });
  g.face_edge.resize(entries.size());
  g.edge_face.reserve(entries.size());
  for (size_t k = 0; k < entries.size(); ++k) {
    if (k > 0 && entries[k].key != entries[k - 1].key) g.edge_start.push_back(static_cast<int>(k));
    if (k == 0 || entries[k].key != entries[k - 1].key) g.key.push_back(entries[k].key);
    g.face_edge[entries[k].pos] = static_cast<int>(g.key.size()) - 1;
    g.edge_face.push_back(entries[k].slot);
  }
  g.edge_start.push_back(static_cast<int>(entries.size()));
  return g;
}

// Edges no face holds any more but which no collapse removed either: the complex keeps them as
// 1-cells. Those with a free end collapse in turn; the count left is the 1-D part of the axis.
std::size_t essential_bare_edges(const EdgeIncidence& g, const std::vector<int>& count,
                                 const std::vector<char>& removed) {
  const size_t ne = g.key.size();
  // Per corner: its live edges (held by a face, or bare).
  std::vector<std::pair<int, int>> ends;  // (corner, edge)
  for (size_t e = 0; e < ne; ++e) {
    if (removed[e]) continue;
    ends.push_back({key_low(g.key[e]), static_cast<int>(e)});
    ends.push_back({key_high(g.key[e]), static_cast<int>(e)});
  }
  std::sort(ends.begin(), ends.end());
  std::vector<char> bare_alive(ne, 0);
  std::vector<int> degree;     // per run of equal corners
  std::vector<int> run_of(ends.size());
  for (size_t k = 0; k < ends.size(); ++k) {
    if (k == 0 || ends[k].first != ends[k - 1].first) degree.push_back(0);
    run_of[k] = static_cast<int>(degree.size()) - 1;
    ++degree.back();
  }
  std::vector<std::array<int, 2>> edge_runs(ne, {-1, -1});
  for (size_t k = 0; k < ends.size(); ++k) {
    auto& r = edge_runs[ends[k].second];
    r[r[0] < 0 ? 0 : 1] = run_of[k];
  }
  std::vector<int> stack;
  std::vector<std::vector<int>> bare_at(degree.size());
  for (size_t e = 0; e < ne; ++e) {
    if (removed[e] || count[e] > 0) continue;
    bare_alive[e] = 1;
    for (int r : edge_runs[e]) bare_at[r].push_back(static_cast<int>(e));
  }
  for (size_t r = 0; r < degree.size(); ++r)
    if (degree[r] == 1) stack.push_back(static_cast<int>(r));
  std::size_t left = 0;
  for (size_t e = 0; e < ne; ++e) left += bare_alive[e];
  while (!stack.empty()) {
    const int r = stack.back();
    stack.pop_back();
    if (degree[r] != 1) continue;
    for (int e : bare_at[r]) {
      if (!bare_alive[e]) continue;
      bare_alive[e] = 0;
      --left;
      for (int s : edge_runs[e])
        if (--degree[s] == 1) stack.push_back(s);
    }
  }
  return left;
}

}  // namespace

std::vector<int> collapse_fillers(const MedialComplex& mc, const std::vector<int>& faces, MedialAxisStats& st) {
  const EdgeIncidence g = edge_incidence(mc, faces);
  const size_t ne = g.key.size();
  std::vector<int> count(ne);
  for (size_t e = 0; e < ne; ++e) count[e] = g.edge_start[e + 1] - g.edge_start[e];
  std::vector<char> alive(faces.size(), 1), removed(ne, 0);
  std::vector<int> queue;
  for (size_t i = 0; i < faces.size(); ++i)
    if (mc.filler[faces[i]]) queue.push_back(static_cast<int>(i));
  // Elementary collapse: a filler face with an edge that no other face holds goes, with that edge.
  // FIFO from the outermost fillers inward, so what stays hugs the selected facets.
  for (size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    if (!alive[i]) continue;
    int free_edge = -1;
    for (int k = g.face_start[i]; k < g.face_start[i + 1] && free_edge < 0; ++k)
      if (count[g.face_edge[k]] == 1) free_edge = g.face_edge[k];
    if (free_edge < 0) continue;  // queued again if a neighbour's collapse frees an edge
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
  std::vector<int> kept;
  for (size_t i = 0; i < faces.size(); ++i)
    if (alive[i]) kept.push_back(faces[i]);
  st.bare_edges = essential_bare_edges(g, count, removed);
  return kept;
}

std::vector<int> attach_by_expansion(const MedialComplex& mc, const std::vector<int>& base,
                                     const std::vector<int>& candidates, MedialAxisStats& st) {
  std::unordered_set<int> corners;
  std::unordered_set<std::uint64_t> edges;
  auto add_face = [&](int f) {
    const int b = mc.start[f], e = mc.start[f + 1];
    for (int k = b; k < e; ++k) {
      corners.insert(mc.nodes[k]);
      edges.insert(edge_key(mc.nodes[k], mc.nodes[k + 1 < e ? k + 1 : b]));
    }
  };
  for (int f : base) add_face(f);
  // A triangle keeps the homotopy type when what it shares with the complex is contractible: one
  // corner, one edge, or two edges. Two corners without their edge would close a loop; all three
  // edges would close a void or fill a loop the Voronoi part does not have.
  auto attaches = [&](int f) {
    const int b = mc.start[f], e = mc.start[f + 1];
    if (e - b != 3) return false;
    int shared_corners = 0, shared_edges = 0;
    for (int k = b; k < e; ++k) {
      shared_corners += corners.count(mc.nodes[k]) > 0;
      shared_edges += edges.count(edge_key(mc.nodes[k], mc.nodes[k + 1 < e ? k + 1 : b])) > 0;
    }
    return (shared_corners == 1 && shared_edges == 0) || (shared_corners == 2 && shared_edges == 1) ||
           (shared_corners == 3 && shared_edges == 2);
  };
  std::vector<int> kept = base;
  // Whether a face attaches changes only when a face at one of its corners is added: faces that
  // do not attach yet wait at their corners.
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
    kept.push_back(f);
    for (int k = mc.start[f]; k < mc.start[f + 1]; ++k) {
      auto it = waiting.find(mc.nodes[k]);
      if (it == waiting.end()) continue;
      for (int j : it->second)
        if (!done[j]) queue.push_back(j);
      waiting.erase(it);
    }
  }
  for (char d : done) st.unattached_faces += !d;
  return kept;
}

long euler_characteristic(const MedialComplex& mc, const std::vector<int>& faces) {
  std::vector<int> corners;
  std::vector<std::uint64_t> edges;
  for (int f : faces) {
    const int b = mc.start[f], e = mc.start[f + 1];
    for (int k = b; k < e; ++k) {
      corners.push_back(mc.nodes[k]);
      edges.push_back(edge_key(mc.nodes[k], mc.nodes[k + 1 < e ? k + 1 : b]));
    }
  }
  std::sort(corners.begin(), corners.end());
  std::sort(edges.begin(), edges.end());
  const long v = std::unique(corners.begin(), corners.end()) - corners.begin();
  const long ed = std::unique(edges.begin(), edges.end()) - edges.begin();
  return v - ed + static_cast<long>(faces.size());
}

}  // namespace cadmedial::internal
