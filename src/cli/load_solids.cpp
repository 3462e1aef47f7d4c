#include "load_solids.h"

#include <cstdio>

#include <BRep_Builder.hxx>

#include "core/errors.h"
#include "core/io/read_shape.h"

namespace cadmedial::cli {

LoadedSolids load_solids(const std::string& path) {
  LoadedSolids loaded;
  const TopoDS_Shape shape = read_shape_file(path);  // its messages already name the file
  try {
    loaded.solids = extract_solids(shape, &loaded.skipped, &loaded.warnings);
  } catch (const InvalidInput& e) {
    throw InvalidInput(path + ": " + e.what());
  }
  for (const std::string& what : loaded.skipped)
    std::fprintf(stderr, "cadmedial: warning: %s: skipped %s\n", path.c_str(), what.c_str());
  for (const std::string& what : loaded.warnings)
    std::fprintf(stderr, "cadmedial: warning: %s: %s\n", path.c_str(), what.c_str());
  // The engine gets the solids as checked here (closed shells made solids, inside-out ones
  // reversed), so that its own extraction sees the same solids in the same order.
  BRep_Builder builder;
  builder.MakeCompound(loaded.compound);
  for (const TopoDS_Solid& s : loaded.solids) builder.Add(loaded.compound, s);
  return loaded;
}

}  // namespace cadmedial::cli
