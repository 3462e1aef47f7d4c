// Shapes, parameters and the pipeline. Long calls release the GIL; the progress callback takes it
// back to call Python. A Python exception raised in the callback cancels the engine and is then
// raised again, unchanged, to the caller.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <BRepClass3d_SolidClassifier.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <gp_Pnt.hxx>
#include <TopoDS_Shape.hxx>

#include <cstdint>
#include <sstream>

#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "python_progress.h"
#include "core/errors.h"
#include "core/io/read_shape.h"
#include "core/pipeline/compute_medial_axis.h"
#include "core/progress.h"
#include "core/types.h"

namespace py = pybind11;

namespace cadmedial::bindings {
namespace {

const char* shape_type_name(const TopoDS_Shape& shape) {
  if (shape.IsNull()) return "null";
  switch (shape.ShapeType()) {
    case TopAbs_COMPOUND: return "compound";
    case TopAbs_COMPSOLID: return "compsolid";
    case TopAbs_SOLID: return "solid";
    case TopAbs_SHELL: return "shell";
    case TopAbs_FACE: return "face";
    case TopAbs_WIRE: return "wire";
    case TopAbs_EDGE: return "edge";
    case TopAbs_VERTEX: return "vertex";
    default: return "shape";
  }
}

ComputeParams make_params(double spacing, long long samples, double theta, double rho,
                          bool plain_medial = false, bool adapt = true, bool refine = false,
                          double min_feature = 0.0) {
  // size_t would turn -1 into a huge count; say what is wrong instead.
  if (samples < 0) throw InvalidInput("samples must be >= 0, got " + std::to_string(samples));
  ComputeParams params;
  params.sampling.spacing = spacing;
  params.sampling.target_samples = static_cast<std::size_t>(samples);
  params.medial.theta_deg = theta;
  params.medial.rho = rho;
  params.medial.plain_medial = plain_medial;
  params.sampling.adapt_to_walls = adapt;
  params.sampling.refine_topology = refine;
  params.sampling.min_feature = min_feature;
  return params;
}

// Runs the pipeline without the GIL. `callback` is None or callable(stage: str, fraction: float)
// returning a falsy value other than None to cancel.
ComputeResult compute_with_callback(const TopoDS_Shape& shape, const ComputeParams& params,
                                    const py::object& callback) {
  return with_python_progress(callback, [&](const Progress& progress) {
    return compute_medial_axis(shape, params, progress);
  });
}

}  // namespace

void bind_compute(py::module_& m) {
  py::class_<TopoDS_Shape>(m, "Shape", "An OpenCASCADE shape, read by read_shape_file or read_brep_string.")
      .def_property_readonly("shape_type", &shape_type_name,
                             "compound, compsolid, solid, shell, face, wire, edge, vertex or null")
      .def("__repr__", [](const TopoDS_Shape& shape) {
        return std::string("<cadmedial._core.Shape ") + shape_type_name(shape) + ">";
      });

  m.def(
      "read_shape_file",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return read_shape_file(path);
      },
      py::arg("path"), "Reads a STEP, IGES or BREP file (by extension); raises InvalidInput.");

  m.def(
      "read_brep_string",
      [](const std::string& text) {
        py::gil_scoped_release release;
        return read_brep_string(text);
      },
      py::arg("text"), "Reads OpenCASCADE BREP text (FreeCAD's Shape.exportBrepToString()).");

  m.def(
      "extract_solids",
      [](const TopoDS_Shape& shape) {
        std::vector<TopoDS_Solid> solids;
        {
          py::gil_scoped_release release;
          solids = extract_solids(shape);
        }
        return std::vector<TopoDS_Shape>(solids.begin(), solids.end());
      },
      py::arg("shape"), "The checked, closed solids of a shape; raises InvalidInput when there is none.");

  m.def(
      "check_params",
      [](double spacing, long long samples, double theta, double rho) {
        check_params(make_params(spacing, samples, theta, rho));
      },
      py::arg("spacing") = 0.0, py::arg("samples") = 0, py::arg("theta") = 5.0, py::arg("rho") = 8.0,
      "Raises InvalidInput naming the first bad parameter (0 spacing / samples means derive).");

  m.def(
      "plan_sampling",
      [](const TopoDS_Shape& shape, double spacing, long long samples, double min_feature) {
        ComputeParams params = make_params(spacing, samples, 5.0, 8.0, false, true, false, min_feature);
        SamplingPlan plan;
        {
          py::gil_scoped_release release;
          plan = plan_sampling(shape, params.sampling);
        }
        return std::make_pair(plan.spacing, plan.estimated_samples);
      },
      py::arg("shape"), py::arg("spacing") = 0.0, py::arg("samples") = 0, py::arg("min_feature") = 0.0,
      "(spacing, estimated number of samples) that these parameters give for the shape.");

  m.def(
      "compute_medial_axis",
      [](const TopoDS_Shape& shape, double spacing, long long samples, double theta, double rho,
         const py::object& progress, bool plain_medial, bool adapt, bool refine, double min_feature,
         double simplify, bool simplify_relative) {
        ComputeParams params = make_params(spacing, samples, theta, rho, plain_medial, adapt, refine, min_feature);
        params.compact.tolerance = simplify;
        params.compact.relative = simplify_relative;
        ComputeResult result = compute_with_callback(shape, params, progress);
        std::string stats = stats_to_json(result.stats);
        return std::make_pair(std::move(result.mesh), std::move(stats));
      },
      py::arg("shape"), py::arg("spacing") = 0.0, py::arg("samples") = 0, py::arg("theta") = 5.0,
      py::arg("rho") = 8.0, py::arg("progress") = py::none(), py::arg("plain_medial") = false,
      py::arg("adapt") = true, py::arg("refine") = false, py::arg("min_feature") = 0.0,
      py::arg("simplify") = 0.0, py::arg("simplify_relative") = false,
      "Inner medial axis of every solid of the shape: (MedialMesh, stats as JSON text).\n"
      "simplify > 0: the compact mesh within that tolerance (model units, or a share of the "
      "diagonal with simplify_relative), its vertices first moved onto the exact axis.\n"
      "plain_medial runs the paper's plain MEDIAL (section 3: pole umbrellas, no edge or corner "
      "completion) instead of CAD_MEDIAL; theta is not changed (the paper uses 22.5 for it).\n"
      "adapt=False samples at one spacing everywhere (no refinement of thin walls).\n"
      "refine=True samples a solid again, finer, where its axis's Euler characteristic is not the "
      "solid's (at most twice, 2.5 times the samples each time).\n"
      "min_feature > 0: walls thinner than it are not sampled finer than it needs (a warning names "
      "them).\n"
      "progress(stage, fraction) is called with the GIL held; returning a falsy value other than "
      "None raises Cancelled, and an exception it raises cancels the work and propagates.");

  m.def(
      "classify_points",
      [](const TopoDS_Shape& shape, const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
         double tol) {
        if (shape.IsNull() || shape.ShapeType() != TopAbs_SOLID)
          throw InvalidInput(std::string("shape must be a solid, got a ") + shape_type_name(shape));
        if (points.ndim() != 2 || points.shape(1) != 3) {
          std::ostringstream got;
          got << "(";
          for (py::ssize_t i = 0; i < points.ndim(); ++i) got << (i ? ", " : "") << points.shape(i);
          throw InvalidInput("points must have shape (N, 3), got " + got.str() + (points.ndim() == 1 ? ",)" : ")"));
        }
        if (!(tol > 0)) throw InvalidInput("tol must be > 0, got " + std::to_string(tol));
        auto p = points.unchecked<2>();
        py::array_t<std::uint8_t> out(points.shape(0));
        auto o = out.mutable_unchecked<1>();
        {
          py::gil_scoped_release release;
          BRepClass3d_SolidClassifier classifier(shape);
          for (py::ssize_t i = 0; i < points.shape(0); ++i) {
            classifier.Perform(gp_Pnt(p(i, 0), p(i, 1), p(i, 2)), tol);
            const TopAbs_State state = classifier.State();
            o(i) = state == TopAbs_IN ? 1 : state == TopAbs_ON ? 2 : 0;
          }
        }
        return out;
      },
      py::arg("shape"), py::arg("points"), py::arg("tol"),
      "uint8 array over points (N, 3): 1 inside the solid, 2 on its boundary (within tol), 0 "
      "outside. OpenCASCADE's solid classifier, built once for all the points (FreeCAD's "
      "Shape.isInside(p, tol, checkFace) computes the same, building it for every point).");

  m.def("peak_rss_mb", &peak_rss_mb, "Peak resident set size of this process so far, MiB.");
}

}  // namespace cadmedial::bindings
