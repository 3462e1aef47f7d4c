#include "reconstruct_faces.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <list>

#include "../errors.h"

namespace cadmedial {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
// Vertices CGAL adds where constraints cross keep id -1.
struct LocalId {
  int id = -1;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<LocalId, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>;  // nesting level
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Nesting level of every face: 0 outside, 1 inside the outer loop, 2 in a hole, ... (the
// flood fill of CGAL's polygon-with-holes example).
void mark_domains(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::list<Cdt::Edge> border;
  auto flood = [&](Cdt::Face_handle start, int level) {
    if (start->info() != -1) return;
    std::list<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      Cdt::Face_handle fh = queue.front();
      queue.pop_front();
      if (fh->info() != -1) continue;
      fh->info() = level;
      for (int i = 0; i < 3; ++i) {
        Cdt::Edge e(fh, i);
        Cdt::Face_handle n = fh->neighbor(i);
        if (n->info() != -1) continue;
        if (cdt.is_constrained(e))
          border.push_back(e);
        else
          queue.push_back(n);
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    Cdt::Edge e = border.front();
    border.pop_front();
    Cdt::Face_handle n = e.first->neighbor(e.second);
    if (n->info() == -1) flood(n, e.first->info() + 1);
  }
}

}  // namespace

Umbrellas reconstruct_faces(const Samples& samples, const Progress& progress) {
  Umbrellas out;
  const int nfaces = static_cast<int>(samples.faces.size());
  for (int fi = 0; fi < nfaces; ++fi) {
    if (fi % 16 == 0) report(progress, "reconstruction", static_cast<double>(fi) / std::max(1, nfaces));
    const FaceDomain& dom = samples.faces[fi];
    if (dom.sample.size() < 3) continue;
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> handle(dom.sample.size());
    std::vector<std::pair<K::Point_2, LocalId>> pts;
    pts.reserve(dom.sample.size());
    for (size_t k = 0; k < dom.sample.size(); ++k)
      pts.push_back({K::Point_2(dom.uv[k][0] * dom.u_scale, dom.uv[k][1] * dom.v_scale), LocalId{static_cast<int>(k)}});
    cdt.insert(pts.begin(), pts.end());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[v->info().id] = v;
    // Points that coincide in the plane (a duplicate) share the handle of the one kept.
    for (size_t k = 0; k < dom.sample.size(); ++k)
      if (handle[k] == Cdt::Vertex_handle()) {
        Cdt::Locate_type lt;
        int li = 0;
        Cdt::Face_handle fh = cdt.locate(pts[k].first, lt, li);
        if (lt == Cdt::VERTEX) handle[k] = fh->vertex(li);
      }
    for (const auto& seg : dom.boundary) {
      Cdt::Vertex_handle a = handle[seg[0]], b = handle[seg[1]];
      if (a != Cdt::Vertex_handle() && b != Cdt::Vertex_handle() && a != b) cdt.insert_constraint(a, b);
    }
    mark_domains(cdt);
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (f->info() % 2 != 1) continue;
      std::array<int, 3> tri;
      bool ok = true;
      for (int i = 0; i < 3; ++i) {
        const int local = f->vertex(i)->info().id;
        if (local < 0 || local >= static_cast<int>(dom.sample.size())) { ok = false; break; }
        tri[i] = dom.sample[local];
      }
      // Copies of a pole or apex make triangles that collapse in space.
      if (!ok || tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
      out.triangles.push_back(tri);
      out.face.push_back(fi);
    }
  }
  // CSR: triangles around each sample.
  const size_t n = samples.size();
  out.start.assign(n + 1, 0);
  for (const auto& t : out.triangles)
    for (int s : t) ++out.start[s + 1];
  for (size_t i = 0; i < n; ++i) out.start[i + 1] += out.start[i];
  out.incident.resize(out.start[n]);
  std::vector<int> fill(out.start.begin(), out.start.end() - 1);
  for (size_t t = 0; t < out.triangles.size(); ++t)
    for (int s : out.triangles[t]) out.incident[fill[s]++] = static_cast<int>(t);
  return out;
}

}  // namespace cadmedial
