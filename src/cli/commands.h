// The sub-commands of the cadmedial program. Each returns the exit status on success and throws
// (InvalidInput, GeometryError, ...) on failure; main() turns exceptions into messages and statuses.
#pragma once

#include <string>
#include <vector>

#include "args.h"

namespace cadmedial::cli {

/// `cadmedial compute`: reads, computes, writes the mesh (and --stats), prints a summary on stdout.
int run_compute(const Args& args);

/// `cadmedial info`: solids, their topology, volume, bounding box, and the sampling plan.
int run_info(const Args& args);

/// `cadmedial batch|thickness ARGS...`: replaces this process with `python3 -m MODULE ARGS...`
/// (python_command.cpp says where the package is found). Returns only by throwing.
int run_python_module(const std::string& module, const std::vector<std::string>& args);

}  // namespace cadmedial::cli
