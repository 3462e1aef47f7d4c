// A medial mesh as a mutable 2-complex of triangles (each polygon fanned) and bare edges, with
// the one operation a simplifier needs: contracting a side into one of its ends (half-edge
// collapse) where that keeps the complex's homotopy type and the kind of every side.
#pragma once

#include <array>
#include <vector>

#include "../types.h"

namespace cadmedial::compact {

/// The polygons of `mesh` as triangles with the same topology: each fanned from the first of its
/// vertices whose fan adds no side that another polygon (or fan) has, else (rare: a polygon
/// folded onto others) from a vertex added at its centre, with the mean radius; `added` gets
/// one flag per vertex of the result, set for those. Each triangle keeps its polygon's kind
/// and solid; the 1-D edges stay.
MedialMesh triangulated(const MedialMesh& mesh, std::vector<char>& added);

class TriangleComplex {
 public:
  /// The triangles of `mesh` (faces of other sizes are left out, as are triangles with a
  /// repeated vertex) and its 1-D edges.
  explicit TriangleComplex(const MedialMesh& mesh);

  int num_vertices() const { return static_cast<int>(at_.size()); }
  int num_triangles() const { return static_cast<int>(tri_.size()); }
  const std::array<int, 3>& triangle(int t) const { return tri_[static_cast<std::size_t>(t)]; }
  bool alive(int t) const { return alive_[static_cast<std::size_t>(t)]; }
  /// The live triangles at vertex v.
  const std::vector<int>& triangles_at(int v) const { return at_[static_cast<std::size_t>(v)]; }
  /// Whether v is a vertex of two triangles with the same three vertices (two polygons of the
  /// input over them): the complex is not simplicial there and the link condition does not hold
  /// its topology, so v stays.
  bool pinned(int v) const { return pinned_[static_cast<std::size_t>(v)] != 0; }
  void pin(int v) { pinned_[static_cast<std::size_t>(v)] = 1; }
  /// The vertices joined to v by a bare edge (no triangle carries it).
  const std::vector<int>& bare_at(int v) const { return bare_[static_cast<std::size_t>(v)]; }

  /// The vertices sharing a triangle or a bare edge with v, each once, in no fixed order.
  void neighbours(int v, std::vector<int>& out) const;
  /// How many live triangles hold side uv: 2 inside a sheet, 1 at a border, 3 or more at a seam.
  int side_count(int u, int v) const;
  /// The same for every neighbour of u at once: counts[k] for nb[k] (nb from neighbours(u)).
  void side_counts(int u, const std::vector<int>& nb, std::vector<int>& counts) const;
  /// Whether the link of v (the sides opposite v in its triangles) is connected: else v pinches
  /// sheets that meet only there, and it must stay.
  bool link_connected(int v) const;
  bool link_connected(int v, const std::vector<int>& nb) const;

  /// Whether contracting u into v (u's triangles take v, those holding side uv vanish) keeps the
  /// homotopy type (link condition: the vertices next to both u and v are those of the triangles
  /// on uv, and no side is opposite both) and the kind of every side at v (a side of two triangles
  /// stays one, a border or seam side keeps its count). u must have no bare edge.
  bool can_contract(int u, int v) const;
  /// The same with u's neighbours (neighbours(u)) at hand.
  bool can_contract(int u, int v, const std::vector<int>& nu) const;
  /// Contracts u into v (can_contract must hold). `vanished` gets the triangles that held uv,
  /// `moved` those of u that now hold v.
  void contract(int u, int v, std::vector<int>& vanished, std::vector<int>& moved);
  /// Removes u, a vertex with no triangle and bare edges to exactly a and b, joining a to b.
  void bypass_bare(int u);

  /// The live triangles and bare edges over the vertices they use (renumbered, in their order),
  /// with the radii and each triangle's kind and solid from `original`.
  MedialMesh to_mesh(const MedialMesh& original) const;

 private:
  void unlink(int t, int v);
  /// Marks (per vertex, an epoch) for set tests in time linear in the sets.
  unsigned next_epoch() const;

  mutable std::vector<unsigned> mark_, slot_;
  mutable unsigned epoch_ = 0;
  std::vector<std::array<int, 3>> tri_;
  std::vector<char> alive_, pinned_;
  std::vector<int> face_of_;  ///< the polygon of `original` a triangle comes from
  std::vector<std::vector<int>> at_, bare_;
  std::vector<int> bare_solid_;  ///< per vertex with bare edges: the solid of its first edge
};

/// V - E + F and the number of connected pieces (triangles and bare edges) of a complex's live part.
struct ComplexTopology {
  long euler = 0;
  std::size_t components = 0;
};
ComplexTopology topology_of(const TriangleComplex& complex);

}  // namespace cadmedial::compact
