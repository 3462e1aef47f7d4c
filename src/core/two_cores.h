// Internal: work split over two threads (the pipeline targets a 2-core workstation).
#pragma once

#include <atomic>
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

}  // namespace cadmedial::internal
