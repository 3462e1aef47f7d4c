// libFuzzer target: arbitrary bytes as BREP text through read_brep_string and extract_solids, the
// path that Python's cadmedial.compute(text) and FreeCAD shapes take. Any outcome but a shape, a
// list of solids or a cadmedial::Error (a crash, an abort, another exception escaping, a leak of
// control to a signal) is a finding. Built by fuzz/build.sh, run by fuzz/run.sh.
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <streambuf>
#include <string>

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>

#include "core/errors.h"
#include "core/io/read_shape.h"

namespace {
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // BRepTools::Read and the messenger chatter on std::cout: keep libFuzzer's own log readable.
  static NullBuffer sink;
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  std::cout.rdbuf(&sink);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const TopoDS_Shape shape = cadmedial::read_brep_string(text);
    (void)cadmedial::extract_solids(shape);
  } catch (const cadmedial::Error&) {
    // The documented refusal.
  }
  return 0;
}
