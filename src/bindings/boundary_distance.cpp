// The engine's exact point-to-boundary distance for Python (the thickness refinement shrinks a
// ball tangent at each surface point until the boundary's nearest point lies on it).
#include <pybind11/numpy.h>

#include <TopAbs_ShapeEnum.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shape.hxx>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>

#include "bindings.h"
#include "core/errors.h"
#include "core/exact/boundary_distance.h"
#include "core/two_cores.h"

namespace py = pybind11;

namespace cadmedial::bindings {

void bind_boundary_distance(py::module_& m) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  m.def(
      "boundary_distance",
      [](const TopoDS_Shape& shape, const Array& points, const Array& bound) {
        if (shape.IsNull() || shape.ShapeType() != TopAbs_SOLID)
          throw InvalidInput("shape must be a solid");
        if (points.ndim() != 2 || points.shape(1) != 3)
          throw InvalidInput("points must have shape (N, 3)");
        const py::ssize_t n = points.shape(0);
        if (bound.ndim() != 1 || bound.shape(0) != n)
          throw InvalidInput("bound must have shape (N,), one per point");
        auto p = points.unchecked<2>();
        auto b = bound.unchecked<1>();
        py::array_t<double> distance(n), nearest({n, py::ssize_t{3}}), normal({n, py::ssize_t{3}});
        py::array_t<std::int32_t> face(n);
        auto d = distance.mutable_unchecked<1>();
        auto q = nearest.mutable_unchecked<2>();
        auto nm = normal.mutable_unchecked<2>();
        auto f = face.mutable_unchecked<1>();
        {
          py::gil_scoped_release release;
          const TopoDS_Solid& solid = TopoDS::Solid(shape);
          BoundaryDistance dist[2] = {BoundaryDistance(solid), BoundaryDistance(solid)};
          internal::on_two_halves(static_cast<std::size_t>(n), [&](int part, std::size_t lo, std::size_t hi) {
            for (std::size_t i = lo; i < hi; ++i) {
              const double bi = std::isfinite(b(i)) && b(i) > 0 ? b(i) : std::numeric_limits<double>::max();
              const BoundaryDistance::Nearest r = dist[part].nearest({p(i, 0), p(i, 1), p(i, 2)}, bi);
              d(i) = r.distance;
              for (int k = 0; k < 3; ++k) {
                q(i, k) = r.point[k];
                nm(i, k) = r.normal[k];
              }
              f(i) = r.face >= 0 ? dist[part].face_index(r.face) : -1;
            }
          }, 64);
        }
        return std::make_tuple(distance, nearest, face, normal);
      },
      py::arg("shape"), py::arg("points"), py::arg("bound"),
      "(distance (N,), nearest (N, 3), face (N,) int32, normal (N, 3)) from each point (N, 3) to "
      "the boundary of a solid, exact (its B-rep faces and edges). bound (N,): an upper bound of "
      "each distance (inf or <= 0: none); where nothing lies within it, distance is the bound "
      "and face -1. face: the nearest point's face in the solid's map of faces "
      "(TopExp::MapShapes order, from 0), -1 when it lies on an edge or vertex; normal: the "
      "face's outward unit normal there (zero on an edge). Two threads.");
}

}  // namespace cadmedial::bindings
