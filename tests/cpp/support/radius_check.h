// The radius of a medial vertex against its distance to the boundary, over a spread of vertices:
// shared by the shape and hard-input suites.
#pragma once

#include <cstddef>
#include <vector>

#include "core/types.h"
#include "support/shape_measures.h"
#include "support/summary.h"

namespace cadmedial::test {

/// At most n indices spread evenly over [0, size).
std::vector<std::size_t> spread(std::size_t size, std::size_t n);

/// Over `count` vertices spread over the mesh: by how much the distance D to the boundary exceeds
/// the radius (`below`, against `eps`) and the radius exceeds D (`above`, against `h + eps`).
struct RadiusGaps {
  Summary below, above;
};
RadiusGaps radius_gaps(const MedialMesh& mesh, const BoundaryDistance& boundary, std::size_t count, double eps,
                       double h);

}  // namespace cadmedial::test
