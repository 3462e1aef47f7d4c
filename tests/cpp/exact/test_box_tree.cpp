// BoxTree.near against a scan of every box: the same indices, ascending, on random boxes of very
// different sizes (a solid's long edges beside its small faces), empty boxes never returned.
#include <vector>

#include <gtest/gtest.h>

#include "core/exact/box_tree.h"
#include "support/random.h"

namespace cadmedial {
namespace {

std::vector<Box> random_boxes(test::Random& rng, int n) {
  std::vector<Box> boxes;
  for (int i = 0; i < n; ++i) {
    if (i % 37 == 0) {
      boxes.push_back({1, 1, 1, -1, -1, -1});  // empty
      continue;
    }
    const double size = rng.uniform() < 0.1 ? rng.uniform(5.0, 50.0) : rng.uniform(0.0, 2.0);
    Box b;
    for (int a = 0; a < 3; ++a) {
      b[a] = rng.uniform(-50.0, 50.0);
      b[a + 3] = b[a] + size * rng.uniform();
    }
    boxes.push_back(b);
  }
  return boxes;
}

TEST(BoxTree, NearGivesWhatAScanGives) {
  test::Random rng(7);
  for (int n : {0, 1, 3, 4, 5, 17, 1000}) {
    const std::vector<Box> boxes = random_boxes(rng, n);
    const BoxTree tree(boxes);
    std::vector<int> got;
    for (int q = 0; q < 300; ++q) {
      const Point3 p{rng.uniform(-60.0, 60.0), rng.uniform(-60.0, 60.0), rng.uniform(-60.0, 60.0)};
      const double d = q % 3 == 0 ? 0.0 : rng.uniform(0.0, 30.0);
      tree.near(p, d * d, got);
      std::vector<int> want;
      for (int i = 0; i < n; ++i)
        if (sq_distance(boxes[i], p) < d * d) want.push_back(i);
      ASSERT_EQ(got, want) << "n " << n << " query " << q;
    }
  }
}

TEST(BoxTree, APointInsideABoxIsNearItAtAnyPositiveDistance) {
  const std::vector<Box> boxes{{0, 0, 0, 1, 1, 1}, {5, 5, 5, 6, 6, 6}, {1, 1, 1, -1, -1, -1}};
  const BoxTree tree(boxes);
  std::vector<int> got;
  tree.near({0.5, 0.5, 0.5}, 1e-300, got);
  EXPECT_EQ(got, std::vector<int>{0});
  tree.near({3, 3, 3}, 3 * 4.0 + 1e-9, got);  // sqrt(12) from both corners
  EXPECT_EQ(got, (std::vector<int>{0, 1}));
  tree.near({3, 3, 3}, 3 * 4.0 - 1e-9, got);
  EXPECT_TRUE(got.empty());
}

}  // namespace
}  // namespace cadmedial
