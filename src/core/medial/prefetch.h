// Internal to medial/: loading ahead what a pass over the cells will read.
#pragma once

#include <cstddef>

namespace cadmedial::internal {

/// How many cells ahead a pass asks for its next cells' data. The passes over the cells in id
/// order read rows of other arrays by neighbour or sample id, which lie anywhere in memory, and
/// waited on those loads (the walks around the Delaunay edges in select_facets: 61 % of their
/// samples on two loads; perf annotate at 250k samples on the Y-rod mount). 8 to 128 cells ahead
/// gave about the same (bench/README.md).
constexpr std::size_t kPrefetchAhead = 24;

/// A hint to the cache to load x; it never faults and changes no result.
template <class T>
inline void prefetch(const T& x) {
  __builtin_prefetch(&x);
}

}  // namespace cadmedial::internal
