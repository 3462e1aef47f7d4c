// The compact mesh: snap_to_axis (the vertices onto the exact axis of a shape's solids) and
// simplify_mesh (within a tolerance), each returning a new mesh and a dict of figures.
#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>

#include "bindings.h"
#include "core/compact/simplify_axis.h"
#include "core/errors.h"
#include "core/exact/snap_to_axis.h"
#include "core/io/extract_solids.h"
#include "core/types.h"
#include "python_progress.h"

namespace py = pybind11;

namespace cadmedial::bindings {

void bind_compact(py::module_& m) {
  m.def(
      "simplify_mesh",
      [](const MedialMesh& mesh, double tolerance, const py::object& progress) {
        if (!(tolerance >= 0) || !std::isfinite(tolerance))
          throw InvalidInput("tolerance must be a finite number >= 0, got " + std::to_string(tolerance));
        SimplifyStats st;
        MedialMesh out = with_python_progress(progress, [&](const Progress& p) {
          return simplify_axis(mesh, tolerance, &st, p);
        });
        py::dict d;
        d["tolerance"] = st.tolerance;
        d["vertices_before"] = st.vertices_before, d["faces_before"] = st.faces_before;
        d["edges_before"] = st.edges_before;
        d["vertices_after"] = st.vertices_after, d["faces_after"] = st.faces_after;
        d["edges_after"] = st.edges_after;
        d["max_error"] = st.max_error;
        d["max_containment"] = st.max_containment;
        d["euler_before"] = st.euler_before, d["euler_after"] = st.euler_after;
        d["components_before"] = st.components_before, d["components_after"] = st.components_after;
        d["seconds"] = st.seconds;
        return py::make_tuple(std::move(out), d);
      },
      py::arg("mesh"), py::arg("tolerance"), py::arg("progress") = py::none(),
      "The compact mesh within `tolerance` (model units) and a dict of figures (see "
      "simplify_axis.h). progress(stage, fraction) as for compute_medial_axis.");

  m.def(
      "snap_to_axis",
      [](const TopoDS_Shape& shape, const MedialMesh& mesh, double reach) {
        if (!(reach > 0) || !std::isfinite(reach))
          throw InvalidInput("reach must be a finite number > 0, got " + std::to_string(reach));
        MedialMesh out = mesh;
        SnapStats all;
        {
          py::gil_scoped_release release;
          // The solids in the order compute_medial_axis numbers them (MedialMesh::solid).
          const std::vector<TopoDS_Solid> solids = extract_solids(shape);
          Bnd_Box box;
          for (const TopoDS_Solid& s : solids) BRepBndLib::Add(s, box);
          const double diag = box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
          double moved = 0;
          for (std::size_t i = 0; i < solids.size(); ++i) {
            const SnapStats st = snap_to_axis(solids[i], static_cast<int>(i), diag, reach, out);
            all.vertices += st.vertices;
            all.snapped += st.snapped;
            all.max_move = std::max(all.max_move, st.max_move);
            moved += st.mean_move * static_cast<double>(st.snapped);
          }
          all.mean_move = all.snapped ? moved / static_cast<double>(all.snapped) : 0.0;
          // As compute_medial_axis orders its output (it snaps before): the same compact mesh.
          out.sort_canonically();
        }
        py::dict d;
        d["vertices"] = all.vertices, d["snapped"] = all.snapped;
        d["max_move"] = all.max_move, d["mean_move"] = all.mean_move;
        return py::make_tuple(std::move(out), d);
      },
      py::arg("shape"), py::arg("mesh"), py::arg("reach"),
      "The mesh with its vertices moved onto the exact medial axis of the shape's solids (at most "
      "`reach` away; see snap_to_axis.h) and a dict of figures.");
}

}  // namespace cadmedial::bindings
