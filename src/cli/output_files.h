// Checks on output paths made before any computation, and atomic writing of small text files.
#pragma once

#include <string>

namespace cadmedial::cli {

/// Throws InvalidInput unless `path` has one of the mesh extensions (.ply, .obj, .ma).
void check_mesh_extension(const std::string& path);

/// Throws InvalidInput unless a file can be created at `path`: its directory exists and is
/// writable, and `path` is not a directory. Leaves nothing behind.
void check_writable(const std::string& path);

/// Writes `text` to a temporary file beside `path` and renames it over `path`, so the file is
/// complete or absent. Throws InvalidInput naming the path.
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace cadmedial::cli
