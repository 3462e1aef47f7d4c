// Command-line parsing of the cadmedial program: no I/O, so that it can be tested on its own.
#pragma once

#include <string>
#include <vector>

#include "core/types.h"

namespace cadmedial::cli {

enum class Command { Help, Version, Compute, Info };

struct Args {
  Command command = Command::Help;
  std::string input;   ///< compute, info
  std::string output;  ///< compute: -o
  std::string stats;   ///< compute: --stats, empty = none
  bool quiet = false;  ///< no progress lines on stderr
  ComputeParams params;
};

/// Parses argv[1..argc). Throws InvalidInput with a one-line message on any bad option or value:
/// unknown option, missing value, a number that is not finite and positive, both --spacing and
/// --samples, theta outside (0, 90), rho <= 0.
Args parse_args(const std::vector<std::string>& argv);

/// A finite number, all of `text` consumed (strtod); throws InvalidInput naming `option`.
double parse_number(const std::string& option, const std::string& text);

/// The usage text printed by --help.
std::string usage();

}  // namespace cadmedial::cli
