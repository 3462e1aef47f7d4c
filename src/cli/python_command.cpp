// The sub-commands written in Python (`cadmedial batch`: cadmedial.batch on Dask; `cadmedial
// thickness`: cadmedial.thickness) are handed over by exec, so that their exit status, signals
// and terminal are the user's own. The package is looked for where an
// install puts it, then in the source tree this program was built from.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.h"
#include "core/errors.h"

#ifndef CADMEDIAL_PYTHON
#define CADMEDIAL_PYTHON "/usr/bin/python3"
#endif
#ifndef CADMEDIAL_SOURCE_PYTHON_DIR
#define CADMEDIAL_SOURCE_PYTHON_DIR ""
#endif

namespace cadmedial::cli {

namespace fs = std::filesystem;

namespace {

// Whether `dir` holds the package `module` ("cadmedial.batch") with its __main__.
bool holds_package(const fs::path& dir, const std::string& module) {
  fs::path package = dir;
  for (std::size_t begin = 0; begin <= module.size();) {
    const std::size_t dot = std::min(module.find('.', begin), module.size());
    package /= module.substr(begin, dot - begin);
    begin = dot + 1;
  }
  std::error_code ec;
  return fs::is_regular_file(package / "__main__.py", ec);
}

// The folder of a compiled cadmedial._core in `dir`, if any (a build tree keeps it apart from
// the Python sources, which cadmedial/__init__.py finds through CADMEDIAL_CORE_DIR).
bool holds_core(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return false;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().filename().string().rfind("_core", 0) == 0 && entry.path().extension() == ".so") return true;
  return false;
}

}  // namespace

int run_python_module(const std::string& module, const std::vector<std::string>& args) {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw InvalidInput((module + ": cannot tell where this program is: ") + ec.message());
  const fs::path bin = exe.parent_path();

  // `cmake --install` puts the package in <prefix>/lib/cadmedial/python (CMakeLists.txt); a build
  // tree uses the sources it was configured from.
  std::vector<fs::path> candidates = {bin.parent_path() / "lib" / "cadmedial" / "python"};
  if (*CADMEDIAL_SOURCE_PYTHON_DIR) candidates.emplace_back(CADMEDIAL_SOURCE_PYTHON_DIR);
  fs::path package;
  for (const fs::path& dir : candidates)
    if (holds_package(dir, module)) {
      package = dir;
      break;
    }
  if (package.empty()) {
    std::string looked;
    for (const fs::path& dir : candidates) looked += (looked.empty() ? "" : ", ") + dir.string();
    throw InvalidInput("cannot find the Python package " + module + " (looked in " + looked + ")");
  }

  const char* old_path = std::getenv("PYTHONPATH");
  const std::string python_path = package.string() + (old_path && *old_path ? ":" + std::string(old_path) : "");
  setenv("PYTHONPATH", python_path.c_str(), 1);
  if (!std::getenv("CADMEDIAL_CORE_DIR") && holds_core(bin / "python" / "cadmedial"))
    setenv("CADMEDIAL_CORE_DIR", (bin / "python" / "cadmedial").c_str(), 1);
  // Each part is computed by this same program.
  setenv("CADMEDIAL_CLI", exe.c_str(), 1);

  std::vector<std::string> words = {CADMEDIAL_PYTHON, "-m", module};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  execv(CADMEDIAL_PYTHON, argv.data());
  throw InvalidInput(module + ": cannot run " + CADMEDIAL_PYTHON + ": " + std::strerror(errno));
}

}  // namespace cadmedial::cli
