// The cadmedial program. Other tools call it and read its exit status:
//   0 success; 2 bad input, parameters or geometry (InvalidInput, GeometryError); 1 anything else.
// Every failure prints exactly one line `cadmedial: error: ...` on stderr; nothing may crash.
#include <CGAL/version.h>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>
#include <Standard_Version.hxx>

#include <cstdio>
#include <exception>
#include <iostream>
#include <streambuf>
#include <new>
#include <string>
#include <vector>

#include "args.h"
#include "commands.h"
#include "core/errors.h"
#include "core/process_memory.h"

namespace {

// From project(... VERSION) in the top-level CMakeLists.txt.
#ifndef CADMEDIAL_VERSION
#define CADMEDIAL_VERSION "unknown"
#endif
constexpr const char* kVersion = CADMEDIAL_VERSION;

int fail(int status, std::string message) {
  // One line, whatever the message holds (OpenCASCADE messages may carry newlines).
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  while (!message.empty() && message.back() == ' ') message.pop_back();
  std::fprintf(stderr, "cadmedial: error: %s\n", message.c_str());
  return status;
}

// Discards everything written to it.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// OpenCASCADE reports through its default messenger and, in places (BRepTools::Read), straight to
// std::cout. Our contract is one summary paragraph on stdout and one error line on stderr, and our
// messages already carry the reason, so that chatter is dropped: the messenger loses its printers
// and the C++ streams are sunk. The program itself writes with C stdio, which is unaffected.
void quiet_opencascade() {
  static NullBuffer sink;
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  std::cout.rdbuf(&sink);
  std::cerr.rdbuf(&sink);
}

int run(int argc, char** argv) {
  using namespace cadmedial::cli;
  // The batch runner (on Dask) and the wall-thickness analysis are Python and parse their own
  // arguments.
  for (const char* python_command : {"batch", "thickness"})
    if (argc > 1 && std::string(argv[1]) == python_command)
      return run_python_module(std::string("cadmedial.") + python_command,
                               std::vector<std::string>(argv + 2, argv + argc));
  const Args args = parse_args(std::vector<std::string>(argv + 1, argv + argc));
  switch (args.command) {
    case Command::Help:
      std::fputs(usage().c_str(), stdout);
      return 0;
    case Command::Version:
      std::printf("cadmedial %s (OpenCASCADE %s, CGAL %s)\n", kVersion, OCC_VERSION_COMPLETE, CGAL_VERSION_STR);
      return 0;
    case Command::Compute:
      quiet_opencascade();
      return run_compute(args);
    case Command::Info:
      quiet_opencascade();
      return run_info(args);
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  cadmedial::keep_freed_memory();  // the process ends with the command: nothing to give back early
  try {
    return run(argc, argv);
  } catch (const cadmedial::InvalidInput& e) {
    return fail(2, e.what());
  } catch (const cadmedial::GeometryError& e) {
    return fail(2, e.what());
  } catch (const cadmedial::Cancelled& e) {
    return fail(1, e.what());
  } catch (const Standard_Failure& e) {
    const char* m = e.GetMessageString();
    return fail(1, std::string("internal error: ") + e.DynamicType()->Name() + (m && *m ? std::string(": ") + m : ""));
  } catch (const std::bad_alloc&) {
    return fail(1, "out of memory");
  } catch (const std::exception& e) {
    return fail(1, std::string("internal error: ") + e.what());
  } catch (...) {
    return fail(1, "internal error: unknown exception");
  }
}
