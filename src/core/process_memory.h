// Internal: how this process's allocator hands freed memory back, for the programs that own their
// process (the command line, the benchmark); a library inside FreeCAD leaves the host's alone.
#pragma once

namespace cadmedial {

/// Keeps freed heap memory for reuse instead of returning it to the kernel (glibc: no trimming,
/// blocks up to 1 GiB from the heap). A page the kernel hands out again costs a fault on first
/// touch, about 8 us on this project's virtual machines: with glibc's defaults a 66,686-sample
/// computation re-faulted 20,000 to 30,000 pages every time it ran in one process
/// (bench/README.md), where CGAL's bare triangulation re-faulted none. Call once, at start-up.
void keep_freed_memory();

}  // namespace cadmedial
