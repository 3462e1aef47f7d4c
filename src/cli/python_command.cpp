#include "python_command.h"

#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace cadmedial::cli {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

bool is_dir(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

std::string executable_dir() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (n <= 0) return {};
  std::string path(buf, static_cast<size_t>(n));
  return path.substr(0, path.find_last_of('/'));
}

// The build tree's layout (CMakeLists.txt): <build>/cadmedial, <build>/python/cadmedial/_core*.so,
// and the package sources in <source>/python, found through CMakeCache's CMAKE_HOME_DIRECTORY.
void point_python_at_build_tree() {
  const std::string dir = executable_dir();
  if (dir.empty()) return;
  if (!std::getenv("CADMEDIAL_CORE_DIR") && is_dir(dir + "/python/cadmedial"))
    setenv("CADMEDIAL_CORE_DIR", (dir + "/python/cadmedial").c_str(), 1);
  if (std::getenv("PYTHONPATH")) return;
  FILE* cache = std::fopen((dir + "/CMakeCache.txt").c_str(), "r");
  if (!cache) return;
  char line[4096];
  const char* key = "CMAKE_HOME_DIRECTORY:INTERNAL=";
  while (std::fgets(line, sizeof(line), cache)) {
    if (std::strncmp(line, key, std::strlen(key)) != 0) continue;
    std::string source(line + std::strlen(key));
    while (!source.empty() && (source.back() == '\n' || source.back() == '\r')) source.pop_back();
    if (is_dir(source + "/python/cadmedial")) setenv("PYTHONPATH", (source + "/python").c_str(), 1);
    break;
  }
  std::fclose(cache);
}

}  // namespace

int run_python_module(const char* module, int argc, char** argv) {
  point_python_at_build_tree();
  std::vector<char*> args{const_cast<char*>(kPython), const_cast<char*>("-m"), const_cast<char*>(module)};
  for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  execv(kPython, args.data());
  std::fprintf(stderr, "cadmedial: error: cannot run %s -m %s: %s\n", kPython, module, std::strerror(errno));
  return 1;
}

}  // namespace cadmedial::cli
