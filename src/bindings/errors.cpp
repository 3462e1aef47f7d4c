// The engine's exceptions as Python classes, and the translation of C++ exceptions into them.
// A C++ exception that crossed into FreeCAD would end the user's session: everything becomes a
// Python exception with the engine's message.
#include <Standard_Failure.hxx>
#include <Standard_Type.hxx>

#include <string>

#include "bindings.h"
#include "core/errors.h"

namespace py = pybind11;

namespace cadmedial::bindings {
namespace {

// Python exception classes. Module-lifetime references: the module attributes own them too, and
// a translator may run at any time while the module is loaded.
PyObject* error_type = nullptr;
PyObject* invalid_input_type = nullptr;
PyObject* geometry_error_type = nullptr;
PyObject* cancelled_type = nullptr;

PyObject* new_exception(py::module_& m, const char* name, const char* doc, PyObject* bases) {
  // Named "cadmedial.X" so tracebacks show the public name, not the private module.
  std::string qualified = std::string("cadmedial.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.add_object(name, py::reinterpret_borrow<py::object>(type));
  return type;
}

std::string failure_text(const Standard_Failure& failure) {
  std::string type = failure.DynamicType().IsNull() ? "Standard_Failure" : failure.DynamicType()->Name();
  const char* message = failure.GetMessageString();
  if (message == nullptr || *message == '\0') return "OpenCASCADE " + type;
  return "OpenCASCADE " + type + ": " + message;
}

}  // namespace

void bind_errors(py::module_& m) {
  error_type = new_exception(m, "Error", "Base of the errors raised by the cadmedial engine.",
                             PyExc_Exception);
  py::tuple invalid_bases = py::make_tuple(py::handle(error_type), py::handle(PyExc_ValueError));
  invalid_input_type = new_exception(
      m, "InvalidInput", "A bad file, shape or parameter: the caller can fix the input.",
      invalid_bases.ptr());
  py::tuple geometry_bases = py::make_tuple(py::handle(error_type), py::handle(PyExc_RuntimeError));
  geometry_error_type = new_exception(
      m, "GeometryError", "A stage of the engine cannot proceed on valid-looking input.",
      geometry_bases.ptr());
  cancelled_type = new_exception(m, "Cancelled", "The progress callback asked to stop.", error_type);

  // Most derived first: the first matching catch wins.
  py::register_exception_translator([](std::exception_ptr pending) {
    try {
      if (pending) std::rethrow_exception(pending);
    } catch (const cadmedial::Cancelled& e) {
      PyErr_SetString(cancelled_type, e.what());
    } catch (const cadmedial::InvalidInput& e) {
      PyErr_SetString(invalid_input_type, e.what());
    } catch (const cadmedial::GeometryError& e) {
      PyErr_SetString(geometry_error_type, e.what());
    } catch (const cadmedial::Error& e) {
      PyErr_SetString(error_type, e.what());
    } catch (const Standard_Failure& e) {
      // The engine should have wrapped it with context; if one escapes, it is still a geometry
      // failure, never a crash.
      PyErr_SetString(geometry_error_type, failure_text(e).c_str());
    }
    // Anything else falls through to pybind11's own translators (std::exception -> RuntimeError,
    // std::bad_alloc -> MemoryError, unknown -> RuntimeError).
  });
}

}  // namespace cadmedial::bindings
