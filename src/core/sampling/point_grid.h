// A uniform hash grid over 3D points, for "is any sample within r?" while sampling.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../types.h"

namespace cadmedial {

/// Cells are keyed by their integer coordinates packed 21 bits each (cells 2^21 apart share a
/// key, and then a bucket). Cells come in blocks of 4 x 4 x 4: an open-addressing table (linear
/// probing) maps a block's key to its 64 cells' list heads, side by side in one array, and a
/// cell's list of ids is kept in insertion order in one flat array. A query's 8 to 27 cells
/// mostly fall in one or two blocks, a few cache lines, where with a slot per cell each was a
/// line of its own: a third of the candidate tests' time went to those loads when sampling the
/// Y-rod mount at 250k samples (bench/README.md). The slot of a block is a hash of its x and y
/// plus its z, and the table is kept at most a quarter full.
class PointGrid {
 public:
  explicit PointGrid(double cell) : cell_(cell) { slots_.assign(kInitialSlots, Slot{}); }

  /// Adds point p with id; returns the index of p's cell, below cells(), for data a caller keeps
  /// per cell (an index stays its cell's as more points come).
  size_t insert(const Point3& p, int id) {
    const int64_t x = cell_of(p[0]), y = cell_of(p[1]), z = cell_of(p[2]);
    const int64_t k = block_key(x, y, z);
    Slot* s = find_slot(k);
    if (s->key == kEmpty) {
      if (4 * (used_ + 1) > slots_.size()) {
        grow();
        s = find_slot(k);
      }
      s->key = k;
      s->block = static_cast<int>(heads_.size() / kBlockCells);
      heads_.resize(heads_.size() + kBlockCells, -1);
      tails_.resize(tails_.size() + kBlockCells, -1);
      ++used_;
    }
    const size_t c = static_cast<size_t>(s->block) * kBlockCells + in_block(x, y, z);
    const int entry = static_cast<int>(entries_.size());
    entries_.push_back({id, -1});
    if (heads_[c] < 0)
      heads_[c] = entry;
    else
      entries_[static_cast<size_t>(tails_[c])].next = entry;
    tails_[c] = entry;
    return c;
  }

  /// How many cell indices insert() has handed out so far (and the ones it may yet use in the
  /// blocks it has made): a bound for arrays over them.
  size_t cells() const { return heads_.size(); }

  /// Calls visit(id) for every inserted point in the cells that meet the cube of half-side
  /// `radius` around p (so every point within `radius` of p, and others), p's own cell first, then
  /// the others in x, y, z order; a cell's ids in insertion order. Stops and returns true as soon
  /// as visit returns true. These cells are among the cube of reach ceil(radius / cell) (at least
  /// 1) around p's cell, the cube visited before: with radius at most half a cell, 8 cells of its
  /// 27 (most of sampling's lookups were in that cube).
  template <class Visit>
  bool any_near(const Point3& p, double radius, const Visit& visit) const {
    const int64_t cx = cell_of(p[0]), cy = cell_of(p[1]), cz = cell_of(p[2]);
    const int64_t reach_cells = radius <= cell_ ? 1 : static_cast<int64_t>(std::ceil(radius / cell_));
    // A margin far above the rounding of p -/+ radius: a point within radius is never left out.
    const double reach = radius + 1e-12 * (radius + std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]));
    const auto first = [&](double v, int64_t c) { return std::max(cell_of(v - reach), c - reach_cells); };
    const auto last = [&](double v, int64_t c) { return std::min(cell_of(v + reach), c + reach_cells); };
    const int64_t x0 = first(p[0], cx), y0 = first(p[1], cy), z0 = first(p[2], cz);
    const int64_t x1 = last(p[0], cx), y1 = last(p[1], cy), z1 = last(p[2], cz);
    // The point's own cell first: while sampling, most candidates are turned down there.
    if (visit_cell(cx, cy, cz, visit)) return true;
    for (int64_t x = x0; x <= x1; ++x)
      for (int64_t y = y0; y <= y1; ++y)
        for (int64_t z = z0; z <= z1; ++z) {
          if (x == cx && y == cy && z == cz) continue;
          if (visit_cell(x, y, z, visit)) return true;
        }
    return false;
  }

  /// Calls visit(id) for every inserted point in the cells that meet the box [lo, hi], cells in
  /// x, y, z order, a cell's ids in insertion order. Stops and returns true as soon as visit
  /// returns true.
  template <class Visit>
  bool any_in_box(const Point3& lo, const Point3& hi, const Visit& visit) const {
    return any_in_box(lo, hi, visit, [](size_t) { return false; });
  }

  /// As any_in_box(lo, hi, visit), but the ids of a cell for which skip(its index, as insert()
  /// returned it) is true are not visited.
  template <class Visit, class Skip>
  bool any_in_box(const Point3& lo, const Point3& hi, const Visit& visit, const Skip& skip) const {
    const int64_t x0 = cell_of(lo[0]), y0 = cell_of(lo[1]), z0 = cell_of(lo[2]);
    const int64_t x1 = cell_of(hi[0]), y1 = cell_of(hi[1]), z1 = cell_of(hi[2]);
    for (int64_t x = x0; x <= x1; ++x)
      for (int64_t y = y0; y <= y1; ++y)
        for (int64_t z = z0; z <= z1; ++z)
          if (visit_cell(x, y, z, visit, skip)) return true;
    return false;
  }

 private:
  static constexpr int64_t kEmpty = -1;  // keys are non-negative (63 bits)
  static constexpr size_t kInitialSlots = 256;
  static constexpr size_t kBlockCells = 64;  // 4 x 4 x 4
  struct Slot {
    int64_t key = kEmpty;  // the block's
    int block = -1;        // its cells are heads_[64 block, 64 block + 64)
  };
  struct Entry {
    int id, next;
  };

  template <class Visit>
  bool visit_cell(int64_t x, int64_t y, int64_t z, const Visit& visit) const {
    return visit_cell(x, y, z, visit, [](size_t) { return false; });
  }
  template <class Visit, class Skip>
  bool visit_cell(int64_t x, int64_t y, int64_t z, const Visit& visit, const Skip& skip) const {
    const Slot* s = find_slot(block_key(x, y, z));
    if (s->key == kEmpty) return false;
    const size_t c = static_cast<size_t>(s->block) * kBlockCells + in_block(x, y, z);
    const int head = heads_[c];
    if (head < 0 || skip(c)) return false;
    for (int e = head; e >= 0; e = entries_[static_cast<size_t>(e)].next)
      if (visit(entries_[static_cast<size_t>(e)].id)) return true;
    return false;
  }

  // The slot holding block key k, or the empty slot where it would go.
  Slot* find_slot(int64_t k) { return const_cast<Slot*>(static_cast<const PointGrid*>(this)->find_slot(k)); }
  const Slot* find_slot(int64_t k) const {
    const size_t mask = slots_.size() - 1;
    size_t i = home(k) & mask;
    while (slots_[i].key != k && slots_[i].key != kEmpty) i = (i + 1) & mask;
    return &slots_[i];
  }
  static size_t home(int64_t k) {
    // splitmix64's finaliser on the x, y bits, plus z.
    uint64_t h = static_cast<uint64_t>(k) & ((uint64_t{1} << 42) - 1);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    h ^= h >> 31;
    return static_cast<size_t>(h + (static_cast<uint64_t>(k) >> 42));
  }
  void grow() {
    std::vector<Slot> old(slots_.size() * 2, Slot{});
    old.swap(slots_);
    for (const Slot& s : old)
      if (s.key != kEmpty) *find_slot(s.key) = s;
  }

  int64_t cell_of(double v) const { return static_cast<int64_t>(std::floor(v / cell_)); }
  // A cell's block: its packed coordinates without their two low bits (cells 2^21 apart still
  // share a key, and then a list).
  static int64_t block_key(int64_t x, int64_t y, int64_t z) {
    return ((x & 0x1FFFFF) >> 2) | (((y & 0x1FFFFF) >> 2) << 21) | (((z & 0x1FFFFF) >> 2) << 42);
  }
  static size_t in_block(int64_t x, int64_t y, int64_t z) {
    return static_cast<size_t>((x & 3) << 4 | (y & 3) << 2 | (z & 3));
  }
  double cell_;
  std::vector<Slot> slots_;  // a power of two, at most a quarter full
  size_t used_ = 0;
  std::vector<int> heads_, tails_;  // per cell of each block: its first and last entry, or -1
  std::vector<Entry> entries_;
};

inline double distance2(const Point3& a, const Point3& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

}  // namespace cadmedial
