// Internal: work split over two threads (the pipeline targets a 2-core workstation).
#pragma once

#include <atomic>
#include <cstddef>
#include <exception>
#include <future>

namespace cadmedial::internal {

/// Sets a flag however the scope is left (a return, an exception), for a thread that polls it.
struct SetOnExit {
  std::atomic<bool>& flag;
  ~SetOnExit() { flag = true; }
};

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

/// fn(k) for every k in [0, n), two threads each taking the next k in turn: for items of uneven
/// cost (a B-spline face against a plane), where halves would leave one thread waiting. Which
/// thread takes which k varies from run to run: fn should write to k's own slot. After a throw
/// on either thread neither takes a new k; when both are done, the exception of the lowest k that
/// threw goes on (the one a loop over k would have thrown, whichever thread ran first).
template <class Fn>
void on_two_cores_each(std::size_t n, const Fn& fn) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::size_t failed_at[2] = {n, n};
  std::exception_ptr error[2];
  auto work = [&](int part) {
    for (std::size_t k; !failed && (k = next++) < n;) {
      try {
        fn(k);
      } catch (...) {
        failed_at[part] = k;
        error[part] = std::current_exception();
        failed = true;
        return;
      }
    }
  };
  if (n < 2)
    work(0);
  else
    on_two_cores([&] { work(0); }, [&](const std::atomic<bool>&) { work(1); });
  const int first = failed_at[1] < failed_at[0] ? 1 : 0;
  if (error[first]) std::rethrow_exception(error[first]);
}

}  // namespace cadmedial::internal
