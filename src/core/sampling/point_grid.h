// A uniform hash grid over 3D points, for "is any sample within r?" while sampling.
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "../types.h"

namespace cadmedial {

class PointGrid {
 public:
  explicit PointGrid(double cell) : cell_(cell) {}

  void insert(const Point3& p, int id) { cells_[key(cell_of(p[0]), cell_of(p[1]), cell_of(p[2]))].push_back(id); }

  /// Calls visit(id) for every inserted point in the cells within `radius` of p (radius <= cell).
  template <class Visit>
  bool any_near(const Point3& p, double radius, const Visit& visit) const {
    const int64_t cx = cell_of(p[0]), cy = cell_of(p[1]), cz = cell_of(p[2]);
    const int reach = radius <= cell_ ? 1 : static_cast<int>(std::ceil(radius / cell_));
    // The point's own cell first: while sampling, most candidates are turned down there.
    if (visit_cell(key(cx, cy, cz), visit)) return true;
    for (int64_t x = cx - reach; x <= cx + reach; ++x)
      for (int64_t y = cy - reach; y <= cy + reach; ++y)
        for (int64_t z = cz - reach; z <= cz + reach; ++z) {
          if (x == cx && y == cy && z == cz) continue;
          auto it = cells_.find(key(x, y, z));
          if (it == cells_.end()) continue;
          for (int id : it->second)
            if (visit(id)) return true;
        }
    return false;
  }

 private:
  template <class Visit>
  bool visit_cell(int64_t k, const Visit& visit) const {
    auto it = cells_.find(k);
    if (it == cells_.end()) return false;
    for (int id : it->second)
      if (visit(id)) return true;
    return false;
  }
  int64_t cell_of(double v) const { return static_cast<int64_t>(std::floor(v / cell_)); }
  static int64_t key(int64_t x, int64_t y, int64_t z) {
    return (x & 0x1FFFFF) | ((y & 0x1FFFFF) << 21) | ((z & 0x1FFFFF) << 42);
  }
  double cell_;
  std::unordered_map<int64_t, std::vector<int>> cells_;
};

inline double distance2(const Point3& a, const Point3& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

}  // namespace cadmedial
