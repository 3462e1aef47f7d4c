// A one-line summary of a set of measured values (for failure messages): count, p50, p95, max and
// where the max occurred.
#pragma once

#include <string>
#include <vector>

#include "support/vec3.h"

namespace cadmedial::test {

struct Summary {
  std::size_t count = 0;
  double p50 = 0, p95 = 0, max = 0;
  Vec3 worst{0, 0, 0};  ///< the point with the max value
  std::size_t above = 0;  ///< how many values exceed the threshold given to summarize()
  std::string str() const;
};

/// values[i] is measured at points[i] (#values == #points).
Summary summarize(const std::vector<double>& values, const std::vector<Vec3>& points, double threshold);

}  // namespace cadmedial::test
