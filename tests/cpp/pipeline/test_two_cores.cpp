// on_two_cores_each: the work split for items of uneven cost (measure_solid, the solid's volume).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
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

TEST(OnTwoCoresEach, TwoThreadsTakeItems) {
  // Item 0 waits (up to 10 s) for item 1 to start: only a second thread can start it meanwhile.
  std::atomic<bool> second_started{false}, seen_by_first{false};
  on_two_cores_each(2, [&](std::size_t k) {
    if (k == 1) {
      second_started = true;
      return;
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!second_started && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    seen_by_first = second_started.load();
  });
  EXPECT_TRUE(seen_by_first);
}

TEST(OnTwoCoresEach, TheLowestItemsErrorGoesOn) {
  // Item 5 throws at once, item 4 after a while: a loop over the items would have thrown item 4's.
  for (int run = 0; run < 5; ++run) {
    std::string what;
    try {
      on_two_cores_each(100, [&](std::size_t k) {
        if (k == 4) {
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
          throw std::runtime_error("item 4");
        }
        if (k == 5) throw std::runtime_error("item 5");
      });
    } catch (const std::runtime_error& e) {
      what = e.what();
    }
    EXPECT_EQ(what, "item 4") << "run " << run;
  }
}

TEST(OnTwoCoresEach, NoNewItemAfterAThrow) {
  const std::size_t n = 100000;
  std::atomic<std::size_t> done{0};
  EXPECT_THROW(on_two_cores_each(n, [&](std::size_t k) {
                 if (k == 10) throw std::runtime_error("item 10");
                 ++done;
                 std::this_thread::sleep_for(std::chrono::microseconds(50));
               }),
               std::runtime_error);
  EXPECT_LT(done.load(), n / 2);
}

}  // namespace
}  // namespace cadmedial::internal
