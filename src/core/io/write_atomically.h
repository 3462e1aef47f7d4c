// Writing a file so that it appears complete or not at all.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace cadmedial {

/// Calls `write` on a temporary file beside `path`, then renames it to `path`: readers see the
/// old file or the complete new one. On any failure (including an exception from `write`) the
/// temporary is removed and InvalidInput names the path and the reason.
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace cadmedial
