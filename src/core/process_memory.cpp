#include "process_memory.h"

#include <cstdlib>  // defines __GLIBC__ on glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cadmedial {

void keep_freed_memory() {
#if defined(__GLIBC__)
  // Each call also turns off glibc's sliding thresholds. Blocks up to 1 GiB come from the heap
  // (at 250,000 samples the cells' centres alone take 45 MB). Threads' arenas still give back a
  // heap that becomes wholly free: M_ARENA_MAX 1 would keep those too, but all threads then
  // share one lock, and the Y-rod at 66,686 samples ran no faster (bench/README.md).
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
#endif
}

}  // namespace cadmedial
