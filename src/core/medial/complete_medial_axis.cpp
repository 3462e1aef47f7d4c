#include "complete_medial_axis.h"

#include <array>
#include <cmath>
#include <set>

#include "geometry_3.h"

namespace cadmedial::internal {

// 4.2.2 ProcConvexEdges: triangle s v1 v2 for the Voronoi edge dual to each triplet triangle,
// and the fill triangles s s' v where v is a Voronoi vertex of s' too.
void complete_convex_edges(const Delaunay& dt, const std::vector<Vertex>& handle, const Samples& samples,
                           MedialComplex& mc, MedialAxisStats& st) {
  std::set<std::array<int, 3>> fills;
  for (const Triplet& t : samples.triplets) {
    Vertex vs = handle[t.s], vl = handle[t.sl], vr = handle[t.sr];
    if (vs == Vertex() || vl == Vertex() || vr == Vertex()) continue;
    Cell c;
    int i, j, k;
    if (!dt.is_facet(vs, vl, vr, c, i, j, k)) continue;  // the sampling did not make it Delaunay
    const Cell n = c->neighbor(6 - i - j - k);
    if (dt.is_infinite(c) || dt.is_infinite(n)) continue;
    const int v1 = mc.cell_id(c), v2 = mc.cell_id(n);
    mc.add({MedialComplex::sample_node(t.s), v1, v2}, FaceKind::Edge);
    ++st.edge_triangles;
    for (int nb : {t.prev, t.next}) {
      if (nb < 0 || handle[nb] == Vertex()) continue;
      for (const Cell& cell : {c, n}) {
        // v in V_s' means s' is among v's nearest samples; with cospherical samples that need
        // not make s' a vertex of this very cell, so ask the distance.
        const int id = mc.cell_id(cell);
        const double to_nb = norm(sub(mc.centers[id], samples.points[nb]));
        if (!cell->has_vertex(handle[nb]) && std::abs(to_nb - mc.radii[id]) > 1e-9 * mc.radii[id]) continue;
        std::array<int, 3> key{std::min(t.s, nb), std::max(t.s, nb), mc.cell_id(cell)};
        if (!fills.insert(key).second) continue;
        mc.add({MedialComplex::sample_node(t.s), MedialComplex::sample_node(nb), mc.cell_id(cell)}, FaceKind::Edge);
        ++st.edge_triangles;
      }
    }
  }
}

// 4.2.3 ProcNonconcaveCorners: join corner p to each Voronoi edge of V_p on the medial axis whose
// incident facets of V_p are all unselected. The Voronoi edge dual to Delaunay triangle pab lies
// on facets dual to pa, pb and ab; so it is joined when ab is selected and pa, pb are not.
void complete_corners(const Delaunay& dt, const std::vector<Vertex>& handle, const Samples& samples,
                      const Selection& sel, MedialComplex& mc, MedialAxisStats& st) {
  std::vector<Delaunay::Facet> facets;
  for (size_t p = 0; p < samples.size(); ++p) {
    if (samples.tag[p] != SampleTag::Corner || !samples.nonconcave[p] || handle[p] == Vertex()) continue;
    facets.clear();
    dt.finite_incident_facets(handle[p], std::back_inserter(facets));
    for (const auto& [c, i] : facets) {
      int ab[2], k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i && c->vertex(j) != handle[p]) ab[k++] = c->vertex(j)->info();
      if (k != 2) continue;
      if (!sel.selected(ab[0], ab[1]) || sel.selected(static_cast<int>(p), ab[0]) ||
          sel.selected(static_cast<int>(p), ab[1]))
        continue;
      const Cell n = c->neighbor(i);
      if (dt.is_infinite(c) || dt.is_infinite(n)) continue;
      mc.add({MedialComplex::sample_node(static_cast<int>(p)), mc.cell_id(c), mc.cell_id(n)}, FaceKind::Corner);
      ++st.corner_triangles;
    }
  }
}

}  // namespace cadmedial::internal
