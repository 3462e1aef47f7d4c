#include "process_memory.h"

#include <cstdlib>  // defines __GLIBC__ on glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cadmedial {

void keep_freed_memory() {
#if defined(__GLIBC__)
  // Each call also turns off glibc's sliding thresholds. 32 MiB is the largest threshold mallopt
  // takes (half of a thread arena's heap); larger blocks are mapped and unmapped as before.
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
#endif
}

}  // namespace cadmedial
