#include "triangle_complex.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <unordered_set>

namespace cadmedial::compact {

namespace {

bool holds(const std::array<int, 3>& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

void erase_one(std::vector<int>& list, int x) {
  const auto it = std::find(list.begin(), list.end(), x);
  if (it != list.end()) *it = list.back(), list.pop_back();
}

bool contains(const std::vector<int>& list, int x) { return std::find(list.begin(), list.end(), x) != list.end(); }

// Union-find over small index ranges.
int root(std::vector<int>& parent, int a) {
  while (parent[static_cast<std::size_t>(a)] != a)
    a = parent[static_cast<std::size_t>(a)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
  return a;
}

}  // namespace

MedialMesh triangulated(const MedialMesh& mesh, std::vector<char>& added) {
  const auto key = [](int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  };
  std::unordered_set<std::uint64_t> sides;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const int* c = mesh.face(f);
    const int n = mesh.face_size(f);
    for (int k = 0; k < n; ++k) sides.insert(key(c[k], c[(k + 1) % n]));
  }
  MedialMesh out;
  out.vertices = mesh.vertices;
  out.radius = mesh.radius;
  out.edges = mesh.edges;
  out.edge_solid = mesh.edge_solid;
  added.assign(mesh.num_vertices(), 0);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const int* c = mesh.face(f);
    const int n = mesh.face_size(f);
    const FaceKind kind = mesh.kind[f];
    const int solid = mesh.solid[f];
    int apex = n <= 3 ? 0 : -1;
    for (int s = 0; s < n && apex < 0; ++s) {
      bool clean = true;
      for (int j = 2; j <= n - 2 && clean; ++j) clean = !sides.count(key(c[s], c[(s + j) % n]));
      if (clean) apex = s;
    }
    if (apex >= 0) {
      for (int j = 2; j <= n - 2; ++j) sides.insert(key(c[apex], c[(apex + j) % n]));
      for (int j = 1; j + 1 < n; ++j) out.add_face({c[apex], c[(apex + j) % n], c[(apex + j + 1) % n]}, kind, solid);
      continue;
    }
    Point3 centre{0, 0, 0};
    double r = 0;
    for (int k = 0; k < n; ++k) {
      for (int a = 0; a < 3; ++a) centre[a] += mesh.vertices[static_cast<std::size_t>(c[k])][a] / n;
      r += mesh.radius[static_cast<std::size_t>(c[k])] / n;
    }
    const int m = static_cast<int>(out.vertices.size());
    out.vertices.push_back(centre);
    out.radius.push_back(r);
    added.push_back(1);
    for (int k = 0; k < n; ++k) out.add_face({m, c[k], c[(k + 1) % n]}, kind, solid);
  }
  return out;
}

TriangleComplex::TriangleComplex(const MedialMesh& mesh) : at_(mesh.num_vertices()), bare_(mesh.num_vertices()) {
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const int* c = mesh.face(f);
    if (mesh.face_size(f) != 3) continue;
    {
      const int k = 1;
      const std::array<int, 3> t{c[0], c[k], c[k + 1]};
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
      const int id = static_cast<int>(tri_.size());
      tri_.push_back(t);
      alive_.push_back(1);
      face_of_.push_back(static_cast<int>(f));
      for (int v : t) at_[static_cast<std::size_t>(v)].push_back(id);
    }
  }
  pinned_.assign(mesh.num_vertices(), 0);
  std::vector<std::array<int, 3>> sorted(tri_);
  for (auto& t : sorted) std::sort(t.begin(), t.end());
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k] == sorted[k - 1])
      for (int v : sorted[k]) pinned_[static_cast<std::size_t>(v)] = 1;
  bare_solid_.assign(mesh.num_vertices(), 0);
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    const auto [a, b] = mesh.edges[e];
    if (a == b || contains(bare_[static_cast<std::size_t>(a)], b)) continue;
    for (int v : {a, b}) {
      if (bare_[static_cast<std::size_t>(v)].empty() && e < mesh.edge_solid.size())
        bare_solid_[static_cast<std::size_t>(v)] = mesh.edge_solid[e];
    }
    bare_[static_cast<std::size_t>(a)].push_back(b);
    bare_[static_cast<std::size_t>(b)].push_back(a);
  }
}

unsigned TriangleComplex::next_epoch() const {
  if (mark_.size() != at_.size()) mark_.assign(at_.size(), 0), slot_.assign(at_.size(), 0), epoch_ = 0;
  if (++epoch_ == 0) std::fill(mark_.begin(), mark_.end(), 0), epoch_ = 1;
  return epoch_;
}

void TriangleComplex::neighbours(int v, std::vector<int>& out) const {
  out.clear();
  const unsigned e = next_epoch();
  mark_[static_cast<std::size_t>(v)] = e;
  for (int t : triangles_at(v))
    for (int x : triangle(t))
      if (mark_[static_cast<std::size_t>(x)] != e) mark_[static_cast<std::size_t>(x)] = e, out.push_back(x);
  for (int x : bare_at(v))
    if (mark_[static_cast<std::size_t>(x)] != e) mark_[static_cast<std::size_t>(x)] = e, out.push_back(x);
}

int TriangleComplex::side_count(int u, int v) const {
  int n = 0;
  for (int t : triangles_at(u)) n += holds(triangle(t), v);
  return n;
}

void TriangleComplex::side_counts(int u, const std::vector<int>& nb, std::vector<int>& counts) const {
  const unsigned e = next_epoch();
  counts.assign(nb.size(), 0);
  for (std::size_t k = 0; k < nb.size(); ++k) {
    mark_[static_cast<std::size_t>(nb[k])] = e;
    slot_[static_cast<std::size_t>(nb[k])] = static_cast<unsigned>(k);
  }
  for (int t : triangles_at(u))
    for (int x : triangle(t))
      if (x != u && mark_[static_cast<std::size_t>(x)] == e) ++counts[slot_[static_cast<std::size_t>(x)]];
}

bool TriangleComplex::link_connected(int v) const {
  std::vector<int> nb;
  neighbours(v, nb);
  return link_connected(v, nb);
}

bool TriangleComplex::link_connected(int v, const std::vector<int>& nb) const {
  if (nb.size() < 2) return true;
  std::vector<int> parent(nb.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto index = [&](int x) { return static_cast<int>(std::find(nb.begin(), nb.end(), x) - nb.begin()); };
  std::size_t pieces = nb.size();
  for (int t : triangles_at(v)) {
    int a = -1, b = -1;
    for (int x : triangle(t))
      if (x != v) (a < 0 ? a : b) = x;
    const int ra = root(parent, index(a)), rb = root(parent, index(b));
    if (ra != rb) parent[static_cast<std::size_t>(ra)] = rb, --pieces;
  }
  return pieces == 1;
}

bool TriangleComplex::can_contract(int u, int v) const {
  std::vector<int> nu;
  neighbours(u, nu);
  return can_contract(u, v, nu);
}

bool TriangleComplex::can_contract(int u, int v, const std::vector<int>& nu) const {
  if (!bare_at(u).empty() || u == v) return false;
  // W: the third vertices of the triangles on uv.
  std::vector<int> wings;
  for (int t : triangles_at(u))
    if (holds(triangle(t), v))
      for (int x : triangle(t))
        if (x != u && x != v) wings.push_back(x);
  if (wings.empty()) return false;
  std::vector<int> nv;
  neighbours(v, nv);  // its marks stay until the next query
  const unsigned e = epoch_;
  for (int x : nu)
    if (x != v && mark_[static_cast<std::size_t>(x)] == e && !contains(wings, x)) return false;
  // A side ab opposite both u and v (triangles uab and vab): the contraction would double it.
  for (int t : triangles_at(u)) {
    const auto& tr = triangle(t);
    if (holds(tr, v)) continue;
    int a = -1, b = -1;
    for (int x : tr)
      if (x != u) (a < 0 ? a : b) = x;
    if (!contains(wings, a) || !contains(wings, b)) continue;
    for (int s : triangles_at(v))
      if (holds(triangle(s), a) && holds(triangle(s), b)) return false;
  }
  // The sides vx that a wing x's two sides ux and vx become: as many triangles as the border or
  // seam among them had, else two.
  for (int x : wings) {
    const int cu = side_count(u, x), cv = side_count(v, x);
    const int wing_triangles = static_cast<int>(std::count(wings.begin(), wings.end(), x));
    const int after = cu + cv - 2 * wing_triangles;
    if (after != (cu != 2 ? cu : cv)) return false;
  }
  return true;
}

void TriangleComplex::unlink(int t, int v) { erase_one(at_[static_cast<std::size_t>(v)], t); }

void TriangleComplex::contract(int u, int v, std::vector<int>& vanished, std::vector<int>& moved) {
  vanished.clear();
  moved.clear();
  const std::vector<int> star = at_[static_cast<std::size_t>(u)];
  for (int t : star) {
    auto& tr = tri_[static_cast<std::size_t>(t)];
    if (holds(tr, v)) {
      alive_[static_cast<std::size_t>(t)] = 0;
      for (int x : tr)
        if (x != u) unlink(t, x);
      vanished.push_back(t);
    } else {
      for (int& x : tr)
        if (x == u) x = v;
      at_[static_cast<std::size_t>(v)].push_back(t);
      moved.push_back(t);
    }
  }
  at_[static_cast<std::size_t>(u)].clear();
}

void TriangleComplex::bypass_bare(int u) {
  auto& nb = bare_[static_cast<std::size_t>(u)];
  const int a = nb[0], b = nb[1];
  erase_one(bare_[static_cast<std::size_t>(a)], u);
  erase_one(bare_[static_cast<std::size_t>(b)], u);
  bare_[static_cast<std::size_t>(a)].push_back(b);
  bare_[static_cast<std::size_t>(b)].push_back(a);
  nb.clear();
}

MedialMesh TriangleComplex::to_mesh(const MedialMesh& original) const {
  MedialMesh out;
  std::vector<int> index(at_.size(), -1);
  for (std::size_t v = 0; v < at_.size(); ++v) {
    if (at_[v].empty() && bare_[v].empty()) continue;
    index[v] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(original.vertices[v]);
    out.radius.push_back(original.radius[v]);
  }
  for (std::size_t t = 0; t < tri_.size(); ++t) {
    if (!alive_[t]) continue;
    const auto& tr = tri_[t];
    const int f = face_of_[t];
    out.add_face({index[static_cast<std::size_t>(tr[0])], index[static_cast<std::size_t>(tr[1])],
                  index[static_cast<std::size_t>(tr[2])]},
                 original.kind[static_cast<std::size_t>(f)], original.solid[static_cast<std::size_t>(f)]);
  }
  for (std::size_t a = 0; a < bare_.size(); ++a)
    for (int b : bare_[a])
      if (static_cast<int>(a) < b) {
        out.edges.push_back({index[a], index[static_cast<std::size_t>(b)]});
        out.edge_solid.push_back(bare_solid_[a]);
      }
  return out;
}

ComplexTopology topology_of(const TriangleComplex& c) {
  ComplexTopology top;
  const int n = c.num_vertices();
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  const auto join = [&](int a, int b) {
    const int ra = root(parent, a), rb = root(parent, b);
    if (ra != rb) parent[static_cast<std::size_t>(ra)] = rb;
  };
  long vertices = 0, sides = 0, triangles = 0;
  std::vector<int> nb;
  for (int v = 0; v < n; ++v) {
    if (c.triangles_at(v).empty() && c.bare_at(v).empty()) continue;
    ++vertices;
    c.neighbours(v, nb);
    for (int x : nb)
      if (x > v) ++sides, join(v, x);
    for (int t : c.triangles_at(v)) triangles += c.triangle(t)[0] == v;
  }
  top.euler = vertices - sides + triangles;
  for (int v = 0; v < n; ++v)
    if ((!c.triangles_at(v).empty() || !c.bare_at(v).empty()) && root(parent, v) == v) ++top.components;
  return top;
}

}  // namespace cadmedial::compact
