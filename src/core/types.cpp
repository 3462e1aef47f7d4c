// Small helpers of the shared plain-data types.
#include "types.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

#include "two_cores.h"

namespace cadmedial {

const char* face_kind_name(FaceKind kind) {
  switch (kind) {
    case FaceKind::Voronoi: return "voronoi";
    case FaceKind::Edge: return "edge";
    case FaceKind::Corner: return "corner";
  }
  return "unknown";
}

std::size_t MedialMesh::add_face(const std::vector<int>& polygon, FaceKind face_kind, int solid_index) {
  face_vertices.insert(face_vertices.end(), polygon.begin(), polygon.end());
  face_start.push_back(static_cast<int>(face_vertices.size()));
  kind.push_back(face_kind);
  solid.push_back(solid_index);
  return kind.size() - 1;
}

void MedialMesh::append(const MedialMesh& other) {
  const int offset = static_cast<int>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  radius.insert(radius.end(), other.radius.begin(), other.radius.end());
  // Offsets of the other mesh's polygons shift by what we already hold; a default-constructed
  // mesh has face_start == {0}, so both sides always start at 0.
  const int base = face_start.empty() ? 0 : face_start.back();
  if (face_start.empty()) face_start.push_back(0);
  for (std::size_t f = 1; f < other.face_start.size(); ++f) face_start.push_back(base + other.face_start[f]);
  face_vertices.reserve(face_vertices.size() + other.face_vertices.size());
  for (int v : other.face_vertices) face_vertices.push_back(v + offset);
  kind.insert(kind.end(), other.kind.begin(), other.kind.end());
  solid.insert(solid.end(), other.solid.begin(), other.solid.end());
  for (const auto& e : other.edges) edges.push_back({e[0] + offset, e[1] + offset});
  edge_solid.insert(edge_solid.end(), other.edge_solid.begin(), other.edge_solid.end());
}

namespace {

// Fewer items than this are sorted or rewritten on one thread: a thread costs more.
constexpr std::size_t kMinSplit = 8192;

// Sorts v by `less` on two cores when it is long: each half, then one merge. `less` must be a
// strict weak order; elements it finds equal may end up in another order than std::sort's.
template <class T, class Less>
void sort_on_two_cores(std::vector<T>& v, const Less& less) {
  if (v.size() < kMinSplit) {
    std::sort(v.begin(), v.end(), less);
    return;
  }
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  internal::on_two_cores([&] { std::sort(v.begin(), mid, less); },
                         [&](const std::atomic<bool>&) { std::sort(mid, v.end(), less); });
  std::vector<T> out(v.size());
  std::merge(v.begin(), mid, mid, v.end(), out.begin(), less);
  v.swap(out);
}

// Sorts v by `less` when each key's bucket (bucket(key) < nb) is monotone in that order: a
// counting pass into the buckets, then each bucket on its own, the buckets split between two
// cores by their keys. Returns false, leaving v as it was, when a bucket holds more than a quarter
// of the keys (one core would sort most of them; sort_on_two_cores is faster there). The
// canonical order's two sorts took 0.05 s of 0.094 at 250k samples as halves and a merge.
template <class T, class Bucket, class Less>
bool sort_by_buckets(std::vector<T>& v, std::size_t nb, const Bucket& bucket, const Less& less) {
  const std::size_t n = v.size();
  std::vector<int> which(n);
  std::vector<std::size_t> start(nb + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    which[i] = static_cast<int>(bucket(v[i]));
    ++start[static_cast<std::size_t>(which[i]) + 1];
  }
  for (std::size_t b = 0; b < nb; ++b) {
    if (start[b + 1] > n / 4) return false;
    start[b + 1] += start[b];
  }
  std::vector<T> out(n);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) out[next[static_cast<std::size_t>(which[i])]++] = v[i];
  }
  // The buckets before the one that starts past the middle on this core, the rest on a second.
  const auto split = static_cast<std::size_t>(std::upper_bound(start.begin(), start.end() - 1, n / 2) - start.begin());
  const auto sort_buckets = [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; ++b)
      if (start[b + 1] - start[b] > 1)
        std::sort(out.begin() + static_cast<std::ptrdiff_t>(start[b]),
                  out.begin() + static_cast<std::ptrdiff_t>(start[b + 1]), less);
  };
  if (n < kMinSplit) {
    sort_buckets(0, nb);
  } else {
    internal::on_two_cores([&] { sort_buckets(0, split); },
                           [&](const std::atomic<bool>&) { sort_buckets(split, nb); });
  }
  v.swap(out);
  return true;
}

}  // namespace

std::vector<int> MedialMesh::vertices_of_solid(int solid_index) const {
  std::vector<std::uint8_t> mine(num_vertices(), 0);
  for (std::size_t f = 0; f < num_faces(); ++f)
    if (solid[f] == solid_index)
      for (int k = 0; k < face_size(f); ++k) mine[static_cast<std::size_t>(face(f)[k])] = 1;
  for (std::size_t e = 0; e < num_edges(); ++e)
    if (edge_solid[e] == solid_index)
      mine[static_cast<std::size_t>(edges[e][0])] = mine[static_cast<std::size_t>(edges[e][1])] = 1;
  std::vector<int> out;
  for (std::size_t v = 0; v < mine.size(); ++v)
    if (mine[v]) out.push_back(static_cast<int>(v));
  return out;
}

void MedialMesh::sort_canonically() {
  const std::size_t nv = vertices.size();
  // Vertices by (position, radius), the keys side by side rather than behind indices.
  struct VertexKey {
    Point3 p;
    double r;
    int index;
  };
  auto vertex_less = [](const VertexKey& a, const VertexKey& b) { return a.p < b.p || (a.p == b.p && a.r < b.r); };
  std::vector<VertexKey> keys(nv);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < nv; ++i) {
    keys[i] = {vertices[i], radius[i], static_cast<int>(i)};
    lo = std::min(lo, vertices[i][0]);
    hi = std::max(hi, vertices[i][0]);
  }
  // By x into about nv / 8 buckets (x - lo times a positive scale rounds monotonically).
  const std::size_t nb = std::max<std::size_t>(1, nv / 8);
  const double scale = hi > lo ? static_cast<double>(nb) / (hi - lo) : 0.0;
  const auto x_bucket = [&](const VertexKey& k) {
    return std::min(nb - 1, static_cast<std::size_t>((k.p[0] - lo) * scale));
  };
  // Min and max skip a NaN, which has no bucket: the comparisons alone then.
  bool numbers = true;
  for (const Point3& v : vertices) numbers = numbers && v[0] == v[0];
  if (!(numbers && std::isfinite(scale) && scale > 0 && std::isfinite(lo)) ||
      !sort_by_buckets(keys, nb, x_bucket, vertex_less))
    sort_on_two_cores(keys, vertex_less);
  std::vector<int> order(nv);
  bool ties = false;
  for (std::size_t i = 0; i < nv; ++i) {
    order[i] = keys[i].index;
    ties = ties || (i > 0 && !vertex_less(keys[i - 1], keys[i]));
  }
  if (ties) {
    // Equal vertices (position and radius) go in std::sort's order, as they always have: which of
    // them a face uses is in the file.
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return vertices[a] < vertices[b] || (vertices[a] == vertices[b] && radius[a] < radius[b]);
    });
  }
  std::vector<int> new_index(nv);
  for (std::size_t i = 0; i < nv; ++i) new_index[order[i]] = static_cast<int>(i);
  std::vector<Point3> v2(nv);
  std::vector<double> r2(nv);
  for (std::size_t i = 0; i < nv; ++i) v2[i] = vertices[order[i]], r2[i] = radius[order[i]];
  vertices.swap(v2);
  radius.swap(r2);

  // Renumber and rotate each polygon in place, then sort face indices by (solid, corners, kind)
  // over the flat arrays: no per-polygon allocation (half a million faces at 250k samples).
  const std::size_t nf = num_faces();
  internal::on_two_halves(nf, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      int* b = face_vertices.data() + face_start[f];
      int* e = face_vertices.data() + face_start[f + 1];
      for (int* k = b; k != e; ++k) *k = new_index[*k];
      std::rotate(b, std::min_element(b, e), e);
      // Polygons are not oriented (the triangulation's circulators run either way): walk towards
      // the smaller neighbour.
      if (e - b > 2 && *(e - 1) < b[1]) std::reverse(b + 1, e);
    }
  }, kMinSplit);
  // The solid and first three corners beside the index decide most comparisons; equal ones look
  // at the whole polygons (equal faces are equal in the file, in whichever order).
  struct FaceKey {
    int solid;
    std::array<int, 3> head;  ///< first corners, -1 past a shorter polygon's end
    int index;
  };
  std::vector<FaceKey> fkeys(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const int n = face_size(f);
    const int* c = face(f);
    fkeys[f] = {solid[f], {n > 0 ? c[0] : -1, n > 1 ? c[1] : -1, n > 2 ? c[2] : -1}, static_cast<int>(f)};
  }
  auto face_less = [&](const FaceKey& x, const FaceKey& y) {
    if (x.solid != y.solid) return x.solid < y.solid;
    if (x.head != y.head) return x.head < y.head;
    const int a = x.index, b = y.index;
    const int *pa = face(a), *pb = face(b);
    if (std::lexicographical_compare(pa, pa + face_size(a), pb, pb + face_size(b))) return true;
    if (std::lexicographical_compare(pb, pb + face_size(b), pa, pa + face_size(a))) return false;
    return kind[a] < kind[b];
  };
  // By first corner (each polygon's smallest vertex) when all faces are one solid's; by the
  // comparisons alone otherwise.
  bool one_solid = true;
  for (std::size_t f = 1; f < nf && one_solid; ++f) one_solid = solid[f] == solid[0];
  const auto first_corner = [](const FaceKey& k) { return static_cast<std::size_t>(k.head[0] + 1); };
  if (!one_solid || !sort_by_buckets(fkeys, nv + 1, first_corner, face_less)) sort_on_two_cores(fkeys, face_less);
  std::vector<int> sorted_start(nf + 1, 0);
  for (std::size_t i = 0; i < nf; ++i) sorted_start[i + 1] = sorted_start[i] + face_size(fkeys[i].index);
  std::vector<int> sorted_vertices(face_vertices.size());
  std::vector<FaceKind> sorted_kind(nf);
  std::vector<int> sorted_solid(nf);
  internal::on_two_halves(nf, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const int f = fkeys[i].index;
      std::copy(face(f), face(f) + face_size(f), sorted_vertices.begin() + sorted_start[i]);
      sorted_kind[i] = kind[f];
      sorted_solid[i] = solid[f];
    }
  }, kMinSplit);
  face_start.swap(sorted_start);
  face_vertices.swap(sorted_vertices);
  kind.swap(sorted_kind);
  solid.swap(sorted_solid);

  std::vector<std::array<int, 3>> segs(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int a = new_index[edges[e][0]], b = new_index[edges[e][1]];
    segs[e] = {edge_solid[e], std::min(a, b), std::max(a, b)};
  }
  std::sort(segs.begin(), segs.end());
  for (std::size_t e = 0; e < segs.size(); ++e) edges[e] = {segs[e][1], segs[e][2]}, edge_solid[e] = segs[e][0];
}

}  // namespace cadmedial
