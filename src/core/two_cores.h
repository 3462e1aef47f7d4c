// Internal: work split over two threads (the pipeline targets a 2-core workstation).
#pragma once

#include <atomic>
#include <cstddef>
#include <future>

namespace cadmedial::internal {

/// Runs `second(stop)` on a new thread while `first()` runs on this one, and returns when both are
/// done. Only `first` may report progress: the callback may call into Python and hold its lock.
/// When `first` throws (a cancel, an error), `stop` is set so that `second`, which should poll it,
/// returns early; then the exception goes on. An exception from `second` is rethrown here.
template <class First, class Second>
void on_two_cores(First&& first, Second&& second) {
  std::atomic<bool> stop{false};
  std::future<void> other = std::async(std::launch::async, [&second, &stop] { second(stop); });
  try {
    first();
  } catch (...) {
    stop = true;
    other.wait();
    throw;
  }
  other.get();
}

/// fn(part, begin, end) for the two halves of [0, n): part 0, [0, n/2), on this thread and part
/// 1, [n/2, n), on a second one (through on_two_cores: no progress from `fn`). Below `min_split`
/// items a thread costs more than it saves: both parts run here, in turn.
template <class Fn>
void on_two_halves(std::size_t n, const Fn& fn, std::size_t min_split = 0) {
  const std::size_t mid = n / 2;
  if (n < min_split) {
    fn(0, std::size_t{0}, mid);
    fn(1, mid, n);
    return;
  }
  on_two_cores([&] { fn(0, std::size_t{0}, mid); }, [&](const std::atomic<bool>&) { fn(1, mid, n); });
}

}  // namespace cadmedial::internal
