// Output paths are checked before computing so that a typo does not cost a long run, and written
// atomically so that a failure or a kill never leaves a partial file for the next tool to read.
#include "output_files.h"

#include "core/io/write_atomically.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/errors.h"

namespace cadmedial::cli {

namespace fs = std::filesystem;

void check_mesh_extension(const std::string& path) {
  std::error_code ec;
  // A directory has no extension either: say what it is rather than "unknown output type ''".
  if (fs::is_directory(path, ec)) throw InvalidInput(path + ": is a directory, not an output file");
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".ply" && ext != ".obj" && ext != ".ma")
    throw InvalidInput(path + ": unknown output type '" + ext + "' (expected .ply, .obj or .ma)");
}

void check_writable(const std::string& path) {
  const fs::path target(path);
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw InvalidInput(path + ": directory " + dir.string() + " does not exist");
  if (!fs::is_directory(dir, ec)) throw InvalidInput(path + ": " + dir.string() + " is not a directory");
  if (fs::is_directory(target, ec)) throw InvalidInput(path + ": is a directory");
  // access() tells whether we may create the temporary file and rename it there.
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw InvalidInput(path + ": directory " + dir.string() + " is not writable (" + std::strerror(errno) + ")");
}

void write_text_atomically(const std::string& path, const std::string& text) {
  write_atomically(path, [&](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

}  // namespace cadmedial::cli
