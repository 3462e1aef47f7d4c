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
};

/// read_shape_file + extract_solids; InvalidInput messages start with `path: `.
LoadedSolids load_solids(const std::string& path);

}  // namespace cadmedial::cli
