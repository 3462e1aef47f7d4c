// Declarations shared by the translation units of the pybind11 module cadmedial._core.
// The module holds conversions and exceptions only: every function forwards to the engine.
#pragma once

#include <pybind11/pybind11.h>

namespace cadmedial::bindings {

/// Creates cadmedial.Error and its subclasses on the module and registers the C++ -> Python
/// translation of the engine's exceptions and of OpenCASCADE's Standard_Failure.
void bind_errors(pybind11::module_& m);

/// The MedialMesh class: numpy views of its arrays, construction from arrays, save, BREP export.
void bind_mesh(pybind11::module_& m);

/// Shapes (read from files or BREP text), solids, parameter checks, sampling plans and compute.
void bind_compute(pybind11::module_& m);

/// simplify_mesh and snap_to_axis: the compact mesh.
void bind_compact(pybind11::module_& m);

/// boundary_distance: the engine's exact point-to-B-rep distance over an array of points.
void bind_boundary_distance(pybind11::module_& m);

}  // namespace cadmedial::bindings
