// Reading STEP / IGES / BREP into a shape.
// OpenCASCADE's Linux build defines this; without it OCC_CATCH_SIGNALS (below) is empty and a fault
// caught by OSD's handler aborts the process instead of becoming a Standard_Failure. It must come
// before any OpenCASCADE header.
#define OCC_CONVERT_SIGNALS
#include "read_shape.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <ios>
#include <mutex>
#include <new>
#include <sstream>

#include <signal.h>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Reader.hxx>
#include <OSD.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>

#include "../errors.h"
#include "shape_text.h"

namespace cadmedial {

using internal::failure_text;

namespace internal {

// OpenCASCADE's readers guard their geometry parsing with OCC_CATCH_SIGNALS (GeomTools_*Set::Read*:
// an offset curve whose basis is unknown dereferences null, and the reader catches that and goes
// on without the curve), but that only works once OSD::SetSignal has installed OpenCASCADE's
// SIGSEGV/SIGBUS/SIGFPE/SIGILL handlers; without them the process dies (fuzz/fuzz_read_brep.cpp,
// tests/data/bad/fuzz/). FreeCAD installs them at start-up; the CLI and a plain Python process
// get them here, on the first read. Only the fault signals: SIGINT and the other job-control
// signals keep their handlers (Python's KeyboardInterrupt, the shell's Ctrl-C), and floating-point
// traps stay off.
void enable_reader_fault_recovery() {
  static std::once_flag once;
  std::call_once(once, [] {
    const int keep[] = {SIGINT, SIGHUP, SIGQUIT, SIGTERM, SIGABRT, SIGTRAP, SIGSYS, SIGCHLD, SIGPIPE};
    struct sigaction saved[sizeof keep / sizeof keep[0]];
    for (std::size_t i = 0; i < sizeof keep / sizeof keep[0]; ++i) ::sigaction(keep[i], nullptr, &saved[i]);
    OSD::SetSignal(false);
    for (std::size_t i = 0; i < sizeof keep / sizeof keep[0]; ++i) ::sigaction(keep[i], &saved[i], nullptr);
  });
}

}  // namespace internal

namespace {

using internal::enable_reader_fault_recovery;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

TopoDS_Shape read_step(const std::string& path) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw InvalidInput(path + ": not a readable STEP file (the STEP parser failed)");
  if (reader.TransferRoots() == 0 || reader.NbShapes() == 0)
    throw InvalidInput(path + ": the STEP file holds no shape");
  return reader.OneShape();
}

TopoDS_Shape read_iges(const std::string& path) {
  IGESControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw InvalidInput(path + ": not a readable IGES file (the IGES parser failed)");
  if (reader.TransferRoots() == 0 || reader.NbShapes() == 0)
    throw InvalidInput(path + ": the IGES file holds no shape");
  return reader.OneShape();
}

// BRepTools::Read prints to std::cout and returns nothing useful on text that is not BREP, so
// look for the header it writes ("CASCADE Topology V1/V2/V3...") first.
bool has_brep_header(std::istream& in) {
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  in.clear();
  in.seekg(0);
  return head.find("CASCADE Topology V") != std::string::npos;
}

// BRepTools::Read loops over a shape's sub-shape list until it reads the '*' that ends it. When
// the stream fails first (the text is truncated, or a number is not a number), every later read
// is a no-op and that loop never ends, appending the same sub-shape until memory runs out (found
// by fuzz/fuzz_read_brep.cpp; tests/data/bad/fuzz/). So the stream throws on the first failed
// read instead: a failed read is always a broken file, since a valid one is read to its last
// token and no further (eofbit alone, at the very end, does not throw).
TopoDS_Shape parse_brep(std::istream& in, const std::string& context) {
  enable_reader_fault_recovery();
  in.exceptions(std::ios::failbit | std::ios::badbit);
  TopoDS_Shape shape;
  try {
    BRep_Builder builder;
    BRepTools::Read(shape, in, builder);
  } catch (const std::ios_base::failure&) {
    throw InvalidInput(context + "not valid BREP (truncated, or a malformed number near byte " +
                       std::to_string(std::max<long long>(0, static_cast<long long>(in.rdbuf()->pubseekoff(0, std::ios::cur, std::ios::in)))) + ")");
  } catch (const std::bad_alloc&) {
    throw InvalidInput(context + "not valid BREP (a count in it asks for more memory than there is)");
  }
  in.exceptions(std::ios::goodbit);
  return shape;
}

TopoDS_Shape read_brep_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput(path + ": cannot open for reading");
  if (!has_brep_header(in)) throw InvalidInput(path + ": not a BREP file (no 'CASCADE Topology' header)");
  const TopoDS_Shape shape = parse_brep(in, path + ": ");
  if (shape.IsNull()) throw InvalidInput(path + ": not a BREP file, or it holds no shape");
  return shape;
}

}  // namespace

TopoDS_Shape read_shape_file(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string ext = lower(fs::path(path).extension().string());
  enum class Format { Step, Iges, Brep } format;
  if (ext == ".step" || ext == ".stp") format = Format::Step;
  else if (ext == ".iges" || ext == ".igs") format = Format::Iges;
  else if (ext == ".brep" || ext == ".brp") format = Format::Brep;
  else
    throw InvalidInput(path + ": unknown file type '" + ext +
                       "' (expected .step, .stp, .iges, .igs, .brep or .brp)");

  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InvalidInput(path + ": no such file");
  if (fs::is_directory(st)) throw InvalidInput(path + ": is a directory, not a file");
  if (fs::is_regular_file(st) && fs::file_size(path, ec) == 0 && !ec) throw InvalidInput(path + ": the file is empty");
  if (!std::ifstream(path)) throw InvalidInput(path + ": cannot open for reading (permissions?)");

  enable_reader_fault_recovery();
  try {
    OCC_CATCH_SIGNALS
    TopoDS_Shape shape;
    switch (format) {
      case Format::Step: shape = read_step(path); break;
      case Format::Iges: shape = read_iges(path); break;
      case Format::Brep: shape = read_brep_file(path); break;
    }
    if (shape.IsNull()) throw InvalidInput(path + ": the file holds no shape");
    return shape;
  } catch (const Standard_Failure& e) {
    throw InvalidInput(path + ": cannot read (broken or truncated file?): " + failure_text(e));
  } catch (const InvalidInput&) {
    throw;
  } catch (const std::exception& e) {
    throw InvalidInput(path + ": cannot read: " + e.what());
  }
}

TopoDS_Shape read_brep_string(const std::string& text) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InvalidInput("BREP text: it is empty");
  try {
    OCC_CATCH_SIGNALS
    std::istringstream in(text);
    if (!has_brep_header(in)) throw InvalidInput("BREP text: not BREP (no 'CASCADE Topology' header)");
    const TopoDS_Shape shape = parse_brep(in, "BREP text: ");
    if (shape.IsNull()) throw InvalidInput("BREP text: does not parse, or holds no shape");
    return shape;
  } catch (const Standard_Failure& e) {
    throw InvalidInput("BREP text: does not parse: " + failure_text(e));
  }
}

}  // namespace cadmedial
