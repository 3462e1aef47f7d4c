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
};

/// read_shape_file + extract_solids; InvalidInput messages start with `path: `. What was skipped
/// is printed on stderr as a warning. Without `brep_check`, BRepCheck_Analyzer is left to the
/// engine, which runs it beside the triangulation (NIST CTC 02: 0.3 s that compute ran twice).
LoadedSolids load_solids(const std::string& path, bool brep_check = true);

}  // namespace cadmedial::cli
