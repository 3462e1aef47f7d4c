// A Python progress callback as the engine's Progress: called with the GIL held; a falsy answer
// (other than None), Ctrl-C or an exception it raises cancels, and the Python exception comes
// back to the caller unchanged.
#pragma once

#include <exception>
#include <string>

#include <pybind11/pybind11.h>

#include "core/progress.h"

namespace cadmedial::bindings {

/// Runs work(progress) without the GIL, progress calling `callback` (None: only Ctrl-C).
template <class Work>
auto with_python_progress(const pybind11::object& callback, Work&& work) {
  namespace py = pybind11;
  if (!callback.is_none() && !PyCallable_Check(callback.ptr()))
    throw py::type_error("progress must be callable(stage, fraction) or None");
  std::exception_ptr python_error;  // written with the GIL held
  Progress progress = [&](const std::string& stage, double fraction) -> bool {
    py::gil_scoped_acquire gil;
    if (python_error) return false;  // another thread of the engine already failed
    try {
      // Ctrl-C in a console (main thread only) cancels too.
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (callback.is_none()) return true;
      py::object answer = callback(stage, fraction);
      if (answer.is_none()) return true;
      int truth = PyObject_IsTrue(answer.ptr());
      if (truth < 0) throw py::error_already_set();
      return truth != 0;
    } catch (...) {
      python_error = std::current_exception();
      return false;
    }
  };
  try {
    py::gil_scoped_release release;
    auto out = work(progress);
    if (python_error) {
      py::gil_scoped_acquire gil;
      std::rethrow_exception(python_error);
    }
    return out;
  } catch (...) {
    // The engine reports the cancel we asked for as Cancelled (or fails on the way out): the
    // caller wants the Python exception that caused it.
    if (python_error) std::rethrow_exception(python_error);
    throw;
  }
}

}  // namespace cadmedial::bindings
