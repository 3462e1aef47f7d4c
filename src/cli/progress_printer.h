// Progress on stderr: a line when the stage changes and one per further quarter of a stage, so a
// long run shows it is alive without flooding a log.
#pragma once

#include <cstdio>
#include <string>

namespace cadmedial::cli {

class ProgressPrinter {
 public:
  explicit ProgressPrinter(bool quiet) : quiet_(quiet) {}

  bool operator()(const std::string& stage, double fraction) {
    // The engine's first stage extracts and checks the solids, where most refusals happen: a
    // refusal stays the one line on stderr that it is when nothing was computed.
    if (quiet_ || stage == "reading") return true;
    const int quarter = fraction >= 1.0 ? 4 : fraction <= 0.0 ? 0 : static_cast<int>(fraction * 4.0);
    if (stage != stage_) {
      stage_ = stage;
      quarter_ = quarter;
      print(stage, fraction);
    } else if (quarter > quarter_) {
      quarter_ = quarter;
      print(stage, fraction);
    }
    return true;
  }

 private:
  static void print(const std::string& stage, double fraction) {
    const int percent = fraction <= 0 ? 0 : fraction >= 1 ? 100 : static_cast<int>(fraction * 100.0);
    std::fprintf(stderr, "[%s] %d%%\n", stage.c_str(), percent);
    std::fflush(stderr);
  }

  bool quiet_;
  std::string stage_;
  int quarter_ = 0;
};

}  // namespace cadmedial::cli
