// Progress reporting: a callback bool(stage, fraction in [0,1]); returning false cancels.
#pragma once

#include <functional>
#include <string>

#include "errors.h"

namespace cadmedial {

using Progress = std::function<bool(const std::string& stage, double fraction)>;

/// Reports progress; throws Cancelled when the callback returns false.
inline void report(const Progress& progress, const std::string& stage, double fraction) {
  if (progress && !progress(stage, fraction)) throw Cancelled();
}

}  // namespace cadmedial
