// 4.2.4 Umbrellas from a face-by-face reconstruction: each face is triangulated from its own
// samples in its parameter plane (constrained by its boundary chains, holes included), and a
// sample's umbrella is the set of its triangles over every face that holds it.
#pragma once

#include <array>
#include <vector>

#include "../progress.h"
#include "../sampling/samples.h"

namespace cadmedial {

struct Umbrellas {
  std::vector<std::array<int, 3>> triangles;  ///< #T global sample indices
  std::vector<int> face;                      ///< #T face of each triangle
  std::vector<int> start;                     ///< #samples+1 CSR offsets into `incident`
  std::vector<int> incident;                  ///< triangle indices around each sample

  int size(int sample) const { return start[sample + 1] - start[sample]; }
};

/// Triangulates every face domain (CGAL constrained Delaunay in isotropically scaled parameters,
/// keeping the triangles inside the boundary loops) and gathers umbrellas.
Umbrellas reconstruct_faces(const Samples& samples, const Progress& progress = {});

}  // namespace cadmedial
