// Command-line parsing: every value is checked here, before any file is read, so that a typo
// costs nothing; check_params (the engine's own check) runs again later on the result.
#include "args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/errors.h"

namespace cadmedial::cli {

std::string usage() {
  return
      "usage:\n"
      "  cadmedial compute INPUT -o OUTPUT [--spacing S | --samples N] [--refine] [--min-feature F]\n"
      "                    [--simplify TOL | --simplify P%] [--theta DEG] [--rho R] [--stats FILE.json]\n"
      "                    [--quiet]\n"
      "  cadmedial info INPUT [--spacing S | --samples N]\n"
      "  cadmedial batch INPUTS... -o OUTDIR [--jobs N] [--scheduler ADDRESS] [--timeout S]\n"
      "                  [--memory GB] [--force] [compute options]   (see cadmedial batch --help)\n"
      "  cadmedial thickness INPUT --min T [--max T] [--corners zero|exclude] [-o F.ply|F.csv]\n"
      "                    [--report F.html]   (wall thickness; exit 3 when out of limits; --help)\n"
      "  cadmedial --help | --version\n"
      "\n"
      "Computes the inner medial axis of the solids of a CAD file (CAD_MEDIAL, Dey & Zhao).\n"
      "\n"
      "  INPUT            .step/.stp, .iges/.igs or .brep/.brp; every solid is computed on its own\n"
      "  -o, --output F   .ply (binary, keeps radius, face kind and solid, and the axis's 1-D edges),\n"
      "                   .obj (radius in 'vr' lines, 1-D edges as 'l' lines)\n"
      "                   or .ma (Q-MAT: vertices with radius, edges, triangles)\n"
      "  --spacing S      boundary sample spacing in model units (> 0)\n"
      "  --samples N      or: about N boundary samples over all solids (default 20000, then --refine)\n"
      "  --refine         where a solid's axis comes out with an Euler characteristic other than the\n"
      "                   solid's (holes or extra loops: too few samples for its walls), sample that\n"
      "                   solid again with 2.5 times the samples, at most twice; the default when\n"
      "                   neither --spacing nor --samples is given\n"
      "  --min-feature F  walls thinner than F (model units) are not sampled finer than F needs;\n"
      "                   a warning names the thinnest of them and where it is\n"
      "  --simplify TOL   write the compact mesh: the axis simplified so that every ball of the full\n"
      "                   axis stays within TOL (model units; 0.1% = a share of the bounding-box\n"
      "                   diagonal) of it, with the same topology, borders and seams (triangles)\n"
      "  --theta DEG      Angle condition threshold in degrees, in (0, 90) (default 5)\n"
      "  --rho R          Ratio condition threshold, > 0 (default 8)\n"
      "  --stats F        also write run statistics as JSON\n"
      "  --quiet          no progress lines on stderr\n"
      "  --uniform        one spacing everywhere: do not sample walls thinner than the spacing\n"
      "                   allows more densely (by default they get down to a quarter of it, and\n"
      "                   to a 32nd where few and small walls need it)\n"
      "  --plain-medial   plain MEDIAL (section 3: pole umbrellas, no edge or corner completion),\n"
      "                   for comparison; use with --theta 22.5\n"
      "\n"
      "Exit status: 0 success, 2 bad input or parameters, 1 internal error.\n";
}

double parse_number(const std::string& option, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || std::isspace(static_cast<unsigned char>(text[0])))
    throw InvalidInput(option + ": '" + text + "' is not a number");
  if (!std::isfinite(x) || errno == ERANGE) throw InvalidInput(option + ": '" + text + "' is not a finite number");
  return x;
}

namespace {

double positive(const std::string& option, const std::string& text) {
  const double x = parse_number(option, text);
  if (x <= 0) throw InvalidInput(option + " must be > 0, got " + text);
  return x;
}

std::size_t count(const std::string& option, const std::string& text) {
  const double x = positive(option, text);
  if (x != std::floor(x) || x > 1e12) throw InvalidInput(option + " must be a whole number of samples, got " + text);
  return static_cast<std::size_t>(x);
}

}  // namespace

Args parse_args(const std::vector<std::string>& argv) {
  Args args;
  if (argv.empty()) throw InvalidInput("no command given (try 'cadmedial --help')");

  std::vector<std::string> positional;
  bool spacing_set = false, samples_set = false;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    std::string arg = argv[i];
    std::string value;
    bool has_inline_value = false;
    // --name=value is accepted as well as --name value.
    if (arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos) {
      value = arg.substr(arg.find('=') + 1);
      arg = arg.substr(0, arg.find('='));
      has_inline_value = true;
    }
    auto take_value = [&]() -> std::string {
      if (has_inline_value) return value;
      if (i + 1 >= argv.size()) throw InvalidInput(arg + ": missing value");
      return argv[++i];
    };
    auto no_value = [&]() {
      if (has_inline_value) throw InvalidInput(arg + " takes no value");
    };

    if (arg == "-h" || arg == "--help") {
      no_value();
      args.command = Command::Help;
      return args;
    } else if (arg == "--version") {
      no_value();
      args.command = Command::Version;
      return args;
    } else if (arg == "-o" || arg == "--output") {
      args.output = take_value();
      if (args.output.empty()) throw InvalidInput(arg + ": empty path");
    } else if (arg == "--stats") {
      args.stats = take_value();
      if (args.stats.empty()) throw InvalidInput(arg + ": empty path");
    } else if (arg == "--spacing") {
      args.params.sampling.spacing = positive(arg, take_value());
      spacing_set = true;
    } else if (arg == "--samples") {
      args.params.sampling.target_samples = count(arg, take_value());
      samples_set = true;
    } else if (arg == "--min-feature") {
      args.params.sampling.min_feature = positive(arg, take_value());
    } else if (arg == "--simplify") {
      std::string text = take_value();
      const bool percent = !text.empty() && text.back() == '%';
      if (percent) text.pop_back();
      const double tol = positive(arg, text);
      if (percent && !(tol < 100)) throw InvalidInput(arg + " must be below 100%, got " + text + "%");
      args.params.compact.tolerance = percent ? tol / 100.0 : tol;
      args.params.compact.relative = percent;
    } else if (arg == "--theta") {
      const std::string text = take_value();
      const double theta = parse_number(arg, text);
      if (!(theta > 0 && theta < 90)) throw InvalidInput("--theta must be in (0, 90) degrees, got " + text);
      args.params.medial.theta_deg = theta;
    } else if (arg == "--rho") {
      args.params.medial.rho = positive(arg, take_value());
    } else if (arg == "--refine") {
      no_value();
      args.params.sampling.refine_topology = true;
    } else if (arg == "--uniform") {
      no_value();
      args.params.sampling.adapt_to_walls = false;
    } else if (arg == "--plain-medial") {
      no_value();
      args.params.medial.plain_medial = true;
    } else if (arg == "-q" || arg == "--quiet") {
      no_value();
      args.quiet = true;
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw InvalidInput("unknown option '" + arg + "' (try 'cadmedial --help')");
    } else {
      positional.push_back(arg);
    }
  }
  if (spacing_set && samples_set) throw InvalidInput("give --spacing or --samples, not both");
  // A density the user chose is kept; the default one is only where the sampling starts.
  if (!spacing_set && !samples_set) args.params.sampling.refine_topology = true;

  if (positional.empty()) throw InvalidInput("no command given (try 'cadmedial --help')");
  const std::string command = positional[0];
  if (command == "compute") args.command = Command::Compute;
  else if (command == "info") args.command = Command::Info;
  else throw InvalidInput("unknown command '" + command + "' (expected compute, info or batch)");

  if (positional.size() < 2) throw InvalidInput(command + ": missing INPUT file");
  if (positional.size() > 2) throw InvalidInput(command + ": unexpected argument '" + positional[2] + "'");
  args.input = positional[1];

  if (args.command == Command::Compute && args.output.empty())
    throw InvalidInput("compute: missing -o OUTPUT (.ply, .obj or .ma)");
  if (args.command == Command::Info && (!args.output.empty() || !args.stats.empty()))
    throw InvalidInput("info: takes no -o or --stats");
  return args;
}

}  // namespace cadmedial::cli
