#include "mesh_euler.h"

#include <algorithm>
#include <vector>

namespace cadmedial {

long euler_characteristic(const MedialMesh& mesh) {
  // Distinct sides by their smaller vertex (buckets), not by sorting: a million sides at 65k
  // samples.
  const std::size_t nv = mesh.num_vertices();
  std::vector<int> start(nv + 1, 0), other;
  auto for_each_side = [&](auto&& fn) {
    for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
      const int* c = mesh.face(f);
      const int n = static_cast<int>(mesh.face_size(f));
      for (int k = 0; k < n; ++k) fn(c[k], c[(k + 1) % n]);
    }
    for (const auto& e : mesh.edges) fn(e[0], e[1]);
  };
  for_each_side([&](int a, int b) { ++start[std::min(a, b) + 1]; });
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  other.resize(start[nv]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for_each_side([&](int a, int b) { other[fill[std::min(a, b)]++] = std::max(a, b); });
  std::vector<int> seen(nv, -1);
  long edges = 0;
  for (std::size_t v = 0; v < nv; ++v)
    for (int k = start[v]; k < start[v + 1]; ++k)
      if (seen[other[k]] != static_cast<int>(v)) seen[other[k]] = static_cast<int>(v), ++edges;
  return static_cast<long>(nv) - edges + static_cast<long>(mesh.num_faces());
}

}  // namespace cadmedial
