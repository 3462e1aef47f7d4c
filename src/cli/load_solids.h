// Reading the input file into checked solids, with the file name in every message.
#pragma once

#include <string>
#include <vector>

#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>

namespace cadmedial::cli {

struct LoadedSolids {
  std::vector<TopoDS_Solid> solids;
  TopoDS_Compound compound;  ///< the checked solids, in order: what the engine is given
  std::vector<std::string> skipped;  ///< open construction surfaces left out beside the solids
  std::vector<std::string> warnings;  ///< solids healed, or skipped for what healing cannot mend
};

/// read_shape_file + extract_solids; InvalidInput messages start with `path: `. What was skipped
/// or healed is printed on stderr as a warning. (`compute` leaves all this to the engine, which extracts
/// the solids and runs BRepCheck_Analyzer beside the triangulation.)
LoadedSolids load_solids(const std::string& path);

}  // namespace cadmedial::cli
