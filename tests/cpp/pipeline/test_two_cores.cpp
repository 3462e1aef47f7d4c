// on_two_cores_each: the work split for items of uneven cost (measure_solid, the solid's volume).
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/two_cores.h"

namespace cadmedial::internal {
namespace {

TEST(OnTwoCoresEach, VisitsEveryItemOnce) {
  for (std::size_t n : {0u, 1u, 2u, 3u, 1000u}) {
    std::vector<std::atomic<int>> seen(n);
    on_two_cores_each(n, [&](std::size_t k) { ++seen[k]; });
    for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(seen[k].load(), 1) << "item " << k << " of " << n;
  }
}

TEST(OnTwoCoresEach, UsesBothThreadsOnSlowItems) {
  // Items that wait for each other can only finish when two threads take them: the first
  // waits until another item has started.
  std::atomic<int> started{0};
  on_two_cores_each(2, [&](std::size_t) {
    ++started;
    for (int i = 0; i < 2000 && started < 2; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  EXPECT_EQ(started.load(), 2);
  std::vector<std::thread::id> who(64);
  on_two_cores_each(who.size(), [&](std::size_t k) {
    who[k] = std::this_thread::get_id();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  });
  std::size_t here = 0;
  for (const auto& id : who) here += id == std::this_thread::get_id();
  EXPECT_GT(here, 0u);
  EXPECT_LT(here, who.size());
}

TEST(OnTwoCoresEach, AThrowStopsTheOtherThreadAndGoesOn) {
  std::atomic<int> done{0};
  EXPECT_THROW(on_two_cores_each(100000, [&](std::size_t k) {
                 if (k == 10) throw std::runtime_error("item 10");
                 ++done;
                 std::this_thread::sleep_for(std::chrono::microseconds(50));
               }),
               std::runtime_error);
  EXPECT_LT(done.load(), 1000);
}

}  // namespace
}  // namespace cadmedial::internal
