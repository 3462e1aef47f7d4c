#include "support/summary.h"

#include <algorithm>
#include <cstdio>

namespace cadmedial::test {

Summary summarize(const std::vector<double>& values, const std::vector<Vec3>& points, double threshold) {
  Summary s;
  s.count = values.size();
  if (values.empty()) return s;
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  s.p50 = sorted[sorted.size() / 2];
  s.p95 = sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(0.95 * sorted.size()))];
  const auto worst = std::max_element(values.begin(), values.end()) - values.begin();
  s.max = values[worst];
  s.worst = points[worst];
  s.above = std::count_if(values.begin(), values.end(), [&](double v) { return v > threshold; });
  return s;
}

std::string Summary::str() const {
  char buf[256];
  std::snprintf(buf, sizeof buf, "n=%zu p50=%.4g p95=%.4g max=%.4g at (%.4g, %.4g, %.4g), %zu above tolerance",
                count, p50, p95, max, worst[0], worst[1], worst[2], above);
  return buf;
}

}  // namespace cadmedial::test
