// The engine's exception hierarchy. Every OpenCASCADE or CGAL failure is rethrown as one of these
// with context, so callers (CLI, Python) only ever see a message, never a crash.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace cadmedial {

/// A number for a message: six significant digits, so that 1e-6 does not print as 0.000000.
inline std::string message_number(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

/// Base of all engine errors.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A bad file, shape or parameter: the caller can fix the input.
class InvalidInput : public Error {
 public:
  using Error::Error;
};

/// A stage cannot proceed on valid-looking input.
class GeometryError : public Error {
 public:
  using Error::Error;
};

/// The progress callback asked to stop.
class Cancelled : public Error {
 public:
  Cancelled() : Error("cancelled") {}
};

}  // namespace cadmedial
