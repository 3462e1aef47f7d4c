// The compact medial mesh (issue 35, item 2): the axis simplified within a stated tolerance by
// contracting sides into one of their ends, so that its vertices stay vertices of the full axis
// (exact positions and radii), while
//  - every removed vertex's ball stays within `tolerance` of the compact mesh's ball at the
//    nearest point (|dc| + |dr|, which bounds how much the union of balls moves: the
//    reconstruction error), and every point of the compact mesh within it of the full mesh
//    (checked on a lattice of its triangles, half a median side of the full mesh apart),
//  - the topology stays (link condition: components and Euler characteristic unchanged),
//  - the structure stays: a border (rim) or seam side keeps its kind and a vertex of one moves
//    only along it; junctions (where seams meet or end), vertices pinching sheets and the
//    vertices of 1-D edges with a branch stay.
// Chains of 1-D edges are thinned within the same tolerance.
#pragma once

#include <cstddef>

#include "../progress.h"
#include "../types.h"

namespace cadmedial {

struct SimplifyStats {
  double tolerance = 0.0;
  std::size_t vertices_before = 0, faces_before = 0, edges_before = 0;
  std::size_t vertices_after = 0, faces_after = 0, edges_after = 0;
  /// The largest |dc| + |dr| of a removed vertex's ball to the compact mesh (at most tolerance),
  /// and of a ball of the compact mesh to the full one, measured on a lattice of its triangles a
  /// median side of the full mesh apart (the simplifier checks twice as densely: between its
  /// points this may exceed the tolerance a little).
  double max_error = 0.0;
  double max_containment = 0.0;
  long euler_before = 0, euler_after = 0;
  std::size_t components_before = 0, components_after = 0;
  double seconds = 0.0;
};

/// The compact mesh of `mesh` (faces become triangles; each keeps the kind and solid of the
/// polygon it lies in). tolerance >= 0 in model units; 0 removes only what moves no ball.
/// Deterministic. Reports progress as stage "compact"; throws Cancelled when it returns false.
MedialMesh simplify_axis(const MedialMesh& mesh, double tolerance, SimplifyStats* stats = nullptr,
                         const Progress& progress = {});

}  // namespace cadmedial
