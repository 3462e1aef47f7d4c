// CGAL first: this file includes no OpenCASCADE header.
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "support/mesh_measures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <unordered_map>

namespace cadmedial::test {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = K::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
using Segment = K::Segment_3;
using SegmentPrimitive = CGAL::AABB_segment_primitive<K, std::vector<Segment>::const_iterator>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<K, SegmentPrimitive>>;

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

bool in_solid(const MedialMesh& mesh, std::size_t f, int solid) {
  return solid < 0 || (f < mesh.solid.size() && mesh.solid[f] == solid);
}

bool edge_in_solid(const MedialMesh& mesh, std::size_t e, int solid) {
  return solid < 0 || (e < mesh.edge_solid.size() && mesh.edge_solid[e] == solid);
}

// Vertices no face and no 1-D edge uses: a medial axis that is a point (a sphere's centre) is one
// such vertex. They carry no solid index, so they count only when all solids are asked for.
std::vector<int> isolated_vertices(const MedialMesh& mesh, int solid) {
  if (solid >= 0) return {};
  std::vector<char> used(mesh.vertices.size(), 0);
  for (int v : mesh.face_vertices) used[v] = 1;
  for (const auto& e : mesh.edges) used[e[0]] = used[e[1]] = 1;
  std::vector<int> out;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (!used[v]) out.push_back(static_cast<int>(v));
  return out;
}

}  // namespace

struct MeshDistance::Impl {
  std::vector<Triangle> triangles;
  Tree tree;
  std::vector<Segment> segments;  // 1-D edges
  SegmentTree segment_tree;
  std::vector<Vec3> points;  // isolated vertices, and the ends of zero-length 1-D edges
};

MeshDistance::MeshDistance(const MedialMesh& mesh, double scale, int solid) : impl_(std::make_unique<Impl>()) {
  const double min_area2 = std::pow(1e-12 * scale * scale, 2);  // squared area threshold
  auto point = [&](int v) {
    const auto& p = mesh.vertices[v];
    return K::Point_3(p[0], p[1], p[2]);
  };
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (!in_solid(mesh, f, solid)) continue;
    const int* poly = mesh.face(f);
    for (int k = 1; k + 1 < mesh.face_size(f); ++k) {
      Triangle t(point(poly[0]), point(poly[k]), point(poly[k + 1]));
      if (CGAL::to_double(t.squared_area()) > min_area2) impl_->triangles.push_back(t);
    }
  }
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    if (!edge_in_solid(mesh, e, solid)) continue;
    const Segment s(point(mesh.edges[e][0]), point(mesh.edges[e][1]));
    // CGAL's segment distance divides by the length: a point stands for a zero-length edge.
    if (s.is_degenerate()) impl_->points.push_back(mesh.vertices[mesh.edges[e][0]]);
    else impl_->segments.push_back(s);
  }
  for (int v : isolated_vertices(mesh, solid)) impl_->points.push_back(mesh.vertices[v]);
  impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
  if (!impl_->triangles.empty()) impl_->tree.accelerate_distance_queries();
  impl_->segment_tree.insert(impl_->segments.cbegin(), impl_->segments.cend());
  if (!impl_->segments.empty()) impl_->segment_tree.accelerate_distance_queries();
}

MeshDistance::~MeshDistance() = default;

double MeshDistance::distance(const Vec3& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec3& q : impl_->points) best = std::min(best, norm(p - q));
  const K::Point_3 q(p[0], p[1], p[2]);
  if (!impl_->triangles.empty()) best = std::min(best, std::sqrt(CGAL::to_double(impl_->tree.squared_distance(q))));
  if (!impl_->segments.empty())
    best = std::min(best, std::sqrt(CGAL::to_double(impl_->segment_tree.squared_distance(q))));
  return best;
}

std::size_t MeshDistance::num_triangles() const { return impl_->triangles.size(); }

double mesh_bbox_diagonal(const MedialMesh& mesh) {
  if (mesh.vertices.empty()) return 0.0;
  Vec3 lo = mesh.vertices[0], hi = lo;
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  return norm(hi - lo);
}

std::vector<int> weld_vertices(const MedialMesh& mesh, double scale) {
  const std::size_t n = mesh.vertices.size();
  UnionFind uf(n);
  const double eps = 1e-12 * scale;
  if (eps > 0) {
    // Hash grid of cell eps: coincident vertices are in the same or a neighbouring cell.
    struct Hash {
      std::size_t operator()(const std::array<long long, 3>& c) const {
        // Unsigned: the products wrap instead of overflowing (undefined for signed).
        const auto u = [](long long v) { return static_cast<unsigned long long>(v); };
        return std::hash<unsigned long long>()(u(c[0]) * 73856093ULL ^ u(c[1]) * 19349663ULL ^ u(c[2]) * 83492791ULL);
      }
    };
    std::unordered_map<std::array<long long, 3>, std::vector<int>, Hash> grid;
    auto cell = [&](const Point3& p) {
      return std::array<long long, 3>{static_cast<long long>(std::floor(p[0] / eps)),
                                      static_cast<long long>(std::floor(p[1] / eps)),
                                      static_cast<long long>(std::floor(p[2] / eps))};
    };
    for (std::size_t v = 0; v < n; ++v) grid[cell(mesh.vertices[v])].push_back(static_cast<int>(v));
    for (std::size_t v = 0; v < n; ++v) {
      const auto c = cell(mesh.vertices[v]);
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy)
          for (long long dz = -1; dz <= 1; ++dz) {
            auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
            if (it == grid.end()) continue;
            for (int w : it->second)
              if (norm(mesh.vertices[v] - mesh.vertices[w]) <= eps) uf.unite(static_cast<int>(v), w);
          }
    }
  } else {
    // All vertices at one position (or none): one cluster.
    for (std::size_t v = 1; v < n; ++v) uf.unite(0, static_cast<int>(v));
  }
  std::vector<int> rep(n);
  for (std::size_t v = 0; v < n; ++v) rep[v] = uf.find(static_cast<int>(v));
  return rep;
}

int connected_pieces(const MedialMesh& mesh, double scale, int solid, std::vector<int>* face_piece) {
  const std::vector<int> rep = weld_vertices(mesh, scale);
  UnionFind uf(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (!in_solid(mesh, f, solid)) continue;
    const int* poly = mesh.face(f);
    for (int k = 1; k < mesh.face_size(f); ++k) uf.unite(rep[poly[0]], rep[poly[k]]);
  }
  for (std::size_t e = 0; e < mesh.num_edges(); ++e)
    if (edge_in_solid(mesh, e, solid)) uf.unite(rep[mesh.edges[e][0]], rep[mesh.edges[e][1]]);
  std::unordered_map<int, int> piece_of_root;
  std::vector<int> pieces(mesh.num_faces(), -1);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (!in_solid(mesh, f, solid) || mesh.face_size(f) == 0) continue;
    const int root = uf.find(rep[mesh.face(f)[0]]);
    auto it = piece_of_root.emplace(root, static_cast<int>(piece_of_root.size())).first;
    pieces[f] = it->second;
  }
  if (face_piece) *face_piece = pieces;
  // Pieces of 1-D edges alone (a closed curve of edges, say) come after those with faces.
  for (std::size_t e = 0; e < mesh.num_edges(); ++e)
    if (edge_in_solid(mesh, e, solid))
      piece_of_root.emplace(uf.find(rep[mesh.edges[e][0]]), static_cast<int>(piece_of_root.size()));
  std::set<int> lone;
  for (int v : isolated_vertices(mesh, solid))
    if (!piece_of_root.count(uf.find(rep[v]))) lone.insert(uf.find(rep[v]));
  return static_cast<int>(piece_of_root.size() + lone.size());
}

long euler_characteristic(const MedialMesh& mesh, double scale, int solid, int* degenerate) {
  const std::vector<int> rep = weld_vertices(mesh, scale);
  std::set<int> vertices;
  std::set<std::pair<int, int>> edges;
  std::set<std::vector<int>> faces;
  int bad = 0;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (!in_solid(mesh, f, solid)) continue;
    std::vector<int> ring;
    for (int k = 0; k < mesh.face_size(f); ++k) {
      const int v = rep[mesh.face(f)[k]];
      if (ring.empty() || ring.back() != v) ring.push_back(v);
    }
    while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    for (int v : ring) vertices.insert(v);
    if (ring.size() == 2) edges.insert({std::min(ring[0], ring[1]), std::max(ring[0], ring[1])});
    if (ring.size() < 3) {
      ++bad;
      continue;
    }
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const int a = ring[k], b = ring[(k + 1) % ring.size()];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
    std::vector<int> key = ring;
    std::sort(key.begin(), key.end());
    if (std::adjacent_find(key.begin(), key.end()) != key.end()) ++bad;  // pinched polygon
    faces.insert(key);
  }
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    if (!edge_in_solid(mesh, e, solid)) continue;
    const int a = rep[mesh.edges[e][0]], b = rep[mesh.edges[e][1]];
    vertices.insert(a);
    vertices.insert(b);
    if (a != b) edges.insert({std::min(a, b), std::max(a, b)});  // the set keeps a face side once
  }
  for (int v : isolated_vertices(mesh, solid)) vertices.insert(rep[v]);
  if (degenerate) *degenerate = bad;
  return static_cast<long>(vertices.size()) - static_cast<long>(edges.size()) + static_cast<long>(faces.size());
}

}  // namespace cadmedial::test
