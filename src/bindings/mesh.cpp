// MedialMesh <-> numpy. Reading a mesh's arrays costs no copy: they are read-only views that keep
// the C++ mesh alive. Building a mesh from arrays checks every shape and index at the boundary.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.h"
#include "core/errors.h"
#include "core/io/medial_mesh_to_brep.h"
#include "core/io/write_medial_mesh.h"
#include "core/types.h"

namespace py = pybind11;

namespace cadmedial::bindings {
namespace {

static_assert(sizeof(Point3) == 3 * sizeof(double), "Point3 must be three packed doubles");
static_assert(sizeof(FaceKind) == sizeof(std::uint8_t), "FaceKind must be one byte");
static_assert(sizeof(std::array<int, 2>) == 2 * sizeof(int), "an edge must be two packed ints");

// A read-only numpy array over `data`, owned by `owner` (the Python MedialMesh).
template <class T>
py::array readonly_view(const T* data, std::vector<py::ssize_t> shape, py::handle owner) {
  static const T empty{};
  py::array view(py::dtype::of<T>(), std::move(shape), {}, data ? data : &empty, owner);
  view.attr("flags").attr("writeable") = false;
  return view;
}

std::string shape_text(const py::array& a) {
  std::ostringstream s;
  s << "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s << (i ? ", " : "") << a.shape(i);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

[[noreturn]] void bad(const std::string& message) { throw InvalidInput(message); }

template <class T>
using CArray = py::array_t<T, py::array::c_style | py::array::forcecast>;

MedialMesh mesh_from_arrays(const CArray<double>& vertices, const CArray<double>& radius,
                            const CArray<std::int64_t>& face_start,
                            const CArray<std::int64_t>& face_vertices,
                            const CArray<std::int64_t>& kind, const CArray<std::int64_t>& solid,
                            const std::optional<CArray<std::int64_t>>& edges,
                            const std::optional<CArray<std::int64_t>>& edge_solid) {
  if (vertices.ndim() != 2 || vertices.shape(1) != 3)
    bad("vertices must have shape (N, 3), got " + shape_text(vertices));
  const py::ssize_t n = vertices.shape(0);
  if (radius.ndim() != 1 || radius.shape(0) != n)
    bad("radius must have shape (" + std::to_string(n) + ",) like vertices, got " + shape_text(radius));
  if (face_start.ndim() != 1 || face_start.shape(0) < 1)
    bad("face_start must have shape (F+1,), got " + shape_text(face_start));
  const py::ssize_t f = face_start.shape(0) - 1;
  if (face_vertices.ndim() != 1)
    bad("face_vertices must have shape (M,), got " + shape_text(face_vertices));
  if (kind.ndim() != 1 || kind.shape(0) != f)
    bad("kind must have shape (" + std::to_string(f) + ",) (one per face), got " + shape_text(kind));
  if (solid.ndim() != 1 || solid.shape(0) != f)
    bad("solid must have shape (" + std::to_string(f) + ",) (one per face), got " + shape_text(solid));

  auto start = face_start.unchecked<1>();
  if (start(0) != 0) bad("face_start[0] must be 0, got " + std::to_string(start(0)));
  if (start(f) != face_vertices.shape(0))
    bad("face_start[-1] must equal len(face_vertices) = " + std::to_string(face_vertices.shape(0)) +
        ", got " + std::to_string(start(f)));

  MedialMesh mesh;
  auto v = vertices.unchecked<2>();
  auto r = radius.unchecked<1>();
  mesh.vertices.resize(n);
  mesh.radius.resize(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    mesh.vertices[i] = {v(i, 0), v(i, 1), v(i, 2)};
    mesh.radius[i] = r(i);
  }
  auto fv = face_vertices.unchecked<1>();
  auto k = kind.unchecked<1>();
  auto s = solid.unchecked<1>();
  std::vector<int> polygon;
  for (py::ssize_t face = 0; face < f; ++face) {
    if (start(face + 1) < start(face) + 3)
      bad("face " + std::to_string(face) + " has " + std::to_string(start(face + 1) - start(face)) +
          " vertices; a face needs at least 3 (face_start must increase by >= 3)");
    polygon.clear();
    for (auto j = start(face); j < start(face + 1); ++j) {
      if (fv(j) < 0 || fv(j) >= n)
        bad("face " + std::to_string(face) + " refers to vertex " + std::to_string(fv(j)) +
            ", outside [0, " + std::to_string(n) + ")");
      polygon.push_back(static_cast<int>(fv(j)));
    }
    if (k(face) < 0 || k(face) > 2)
      bad("kind[" + std::to_string(face) + "] must be 0 (voronoi), 1 (edge) or 2 (corner), got " +
          std::to_string(k(face)));
    mesh.add_face(polygon, static_cast<FaceKind>(k(face)), static_cast<int>(s(face)));
  }

  // 1-D edges: both arrays or neither (a mesh without edges).
  if (edges.has_value() != edge_solid.has_value()) bad("edges and edge_solid must be given together");
  if (edges) {
    if (edges->ndim() != 2 || edges->shape(1) != 2)
      bad("edges must have shape (E, 2), got " + shape_text(*edges));
    const py::ssize_t ne = edges->shape(0);
    if (edge_solid->ndim() != 1 || edge_solid->shape(0) != ne)
      bad("edge_solid must have shape (" + std::to_string(ne) + ",) (one per edge), got " + shape_text(*edge_solid));
    auto e = edges->unchecked<2>();
    auto es = edge_solid->unchecked<1>();
    for (py::ssize_t i = 0; i < ne; ++i) {
      for (int j = 0; j < 2; ++j)
        if (e(i, j) < 0 || e(i, j) >= n)
          bad("edge " + std::to_string(i) + " refers to vertex " + std::to_string(e(i, j)) + ", outside [0, " +
              std::to_string(n) + ")");
      mesh.edges.push_back({static_cast<int>(e(i, 0)), static_cast<int>(e(i, 1))});
      mesh.edge_solid.push_back(static_cast<int>(es(i)));
    }
  }
  return mesh;
}

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<MedialMesh>(m, "MedialMesh",
                         "The medial mesh: polygons in CSR form (face f has the vertices "
                         "face_vertices[face_start[f]:face_start[f+1]]), a radius per vertex, a "
                         "kind (0 voronoi, 1 edge, 2 corner) and a solid index per face; 1-D edges "
                         "(vertex pairs, with a solid index each) where the axis is a curve that no "
                         "face carries.\n"
                         "Array attributes are read-only views into this object.")
      .def(py::init(&mesh_from_arrays), py::arg("vertices"), py::arg("radius"),
           py::arg("face_start"), py::arg("face_vertices"), py::arg("kind"), py::arg("solid"),
           py::arg("edges") = py::none(), py::arg("edge_solid") = py::none(),
           "Builds a mesh from arrays; raises InvalidInput naming the first array that is wrong.")
      .def_property_readonly("num_vertices", &MedialMesh::num_vertices)
      .def_property_readonly("num_faces", &MedialMesh::num_faces)
      .def_property_readonly("num_edges", &MedialMesh::num_edges)
      .def_property_readonly(
          "vertices",
          [](py::object self) {
            const auto& mesh = self.cast<const MedialMesh&>();
            return readonly_view(reinterpret_cast<const double*>(mesh.vertices.data()),
                                 {static_cast<py::ssize_t>(mesh.vertices.size()), 3}, self);
          },
          "(V, 3) float64 vertex positions")
      .def_property_readonly(
          "radius",
          [](py::object self) {
            const auto& mesh = self.cast<const MedialMesh&>();
            return readonly_view(mesh.radius.data(), {static_cast<py::ssize_t>(mesh.radius.size())}, self);
          },
          "(V,) float64 medial radius per vertex")
      .def_property_readonly(
          "face_start",
          [](py::object self) {
            const auto& mesh = self.cast<const MedialMesh&>();
            return readonly_view(mesh.face_start.data(),
                                 {static_cast<py::ssize_t>(mesh.face_start.size())}, self);
          },
          "(F+1,) int32 offsets into face_vertices")
      .def_property_readonly(
          "face_vertices",
          [](py::object self) {
            const auto& mesh = self.cast<const MedialMesh&>();
            return readonly_view(mesh.face_vertices.data(),
                                 {static_cast<py::ssize_t>(mesh.face_vertices.size())}, self);
          },
          "(M,) int32 vertex indices of all polygons")
      .def_property_readonly(
          "kind",
          [](py::object self) {
            const auto& mesh = self.cast<const MedialMesh&>();
            return readonly_view(reinterpret_cast<const std::uint8_t*>(mesh.kind.data()),
                                 {static_cast<py::ssize_t>(mesh.kind.size())}, self);
          },
          "(F,) uint8 face kind: 0 voronoi, 1 edge, 2 corner")
      .def_property_readonly(
          "solid",
          [](py::object self) {
            const auto& mesh = self.cast<const MedialMesh&>();
            return readonly_view(mesh.solid.data(), {static_cast<py::ssize_t>(mesh.solid.size())}, self);
          },
          "(F,) int32 index of the input solid of each face")
      .def_property_readonly(
          "edges",
          [](py::object self) {
            const auto& mesh = self.cast<const MedialMesh&>();
            return readonly_view(reinterpret_cast<const int*>(mesh.edges.data()),
                                 {static_cast<py::ssize_t>(mesh.edges.size()), 2}, self);
          },
          "(E, 2) int32 vertex indices of the 1-D edges (segments of the axis no face carries)")
      .def_property_readonly(
          "edge_solid",
          [](py::object self) {
            const auto& mesh = self.cast<const MedialMesh&>();
            return readonly_view(mesh.edge_solid.data(), {static_cast<py::ssize_t>(mesh.edge_solid.size())}, self);
          },
          "(E,) int32 index of the input solid of each 1-D edge")
      .def(
          "save",
          [](const MedialMesh& mesh, const std::string& path) {
            py::gil_scoped_release release;
            write_medial_mesh(mesh, path);
          },
          py::arg("path"),
          "Writes the mesh by extension (.ply, .obj, .ma); raises InvalidInput on an unknown "
          "extension or an unwritable path.")
      .def(
          "to_brep",
          [](const MedialMesh& mesh) {
            std::string text;
            {
              py::gil_scoped_release release;
              text = medial_mesh_to_brep(mesh);
            }
            return py::str(text);
          },
          "BREP text of a compound with one planar face per polygon (degenerate ones skipped) and "
          "one straight edge per 1-D edge.")
      .def("__repr__", [](const MedialMesh& mesh) {
        return "<cadmedial._core.MedialMesh " + std::to_string(mesh.num_vertices()) +
               " vertices, " + std::to_string(mesh.num_faces()) + " faces, " + std::to_string(mesh.num_edges()) +
               " edges>";
      });

  m.def(
      "read_medial_mesh",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return read_medial_mesh(path);
      },
      py::arg("path"), "Reads a .ply, .obj or .ma file written by MedialMesh.save or the CLI.");
}

}  // namespace cadmedial::bindings
