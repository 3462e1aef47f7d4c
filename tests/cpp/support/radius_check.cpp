#include "support/radius_check.h"

#include <algorithm>

namespace cadmedial::test {

std::vector<std::size_t> spread(std::size_t size, std::size_t n) {
  std::vector<std::size_t> idx;
  const std::size_t step = std::max<std::size_t>(1, size / n);
  for (std::size_t i = 0; i < size; i += step) idx.push_back(i);
  return idx;
}

RadiusGaps radius_gaps(const MedialMesh& mesh, const BoundaryDistance& boundary, std::size_t count, double eps,
                       double h) {
  std::vector<double> below, above;
  std::vector<Vec3> at;
  for (std::size_t v : spread(mesh.num_vertices(), count)) {
    const double D = boundary.distance(mesh.vertices[v]);
    below.push_back(D - mesh.radius[v]);
    above.push_back(mesh.radius[v] - D);
    at.push_back(mesh.vertices[v]);
  }
  return {summarize(below, at, eps), summarize(above, at, h + eps)};
}

}  // namespace cadmedial::test
