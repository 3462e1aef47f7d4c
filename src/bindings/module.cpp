// Entry point of the pybind11 module cadmedial._core (see python/cadmedial for the public API).
#include "bindings.h"

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "Compiled core of cadmedial: the CAD_MEDIAL engine (Dey & Zhao) behind numpy arrays.\n"
      "Use the plain-Python API in `cadmedial` rather than this module directly.";
  cadmedial::bindings::bind_errors(m);
  cadmedial::bindings::bind_mesh(m);
  cadmedial::bindings::bind_compute(m);
  cadmedial::bindings::bind_boundary_distance(m);
  cadmedial::bindings::bind_compact(m);
}
