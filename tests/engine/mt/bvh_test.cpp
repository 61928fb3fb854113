#include "engine/mt/bvh.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "tests/engine/mt/random_box.h"

namespace mtcut::engine {
namespace {

using mtcut::test::random_box;

TEST(Bvh, DistancesBoundEveryPointOfTheBox) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-2.0, 2.0), t(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Aabb box = random_box(rng, 0.5);
    const Vec3 p(u(rng), u(rng), u(rng));
    const double near = box.min_distance(p), far = box.max_distance(p);
    EXPECT_EQ(near == 0.0, box.contains(p));
    for (int k = 0; k < 20; ++k) {
      const Vec3 q = box.lo + (box.hi - box.lo).cwiseProduct(Vec3(t(rng), t(rng), t(rng)));
      EXPECT_LE(near, (q - p).norm() + 1e-15);
      EXPECT_GE(far, (q - p).norm() - 1e-15);
    }
    // Monotone under inclusion, exactly (selective refinement relies on it).
    Aabb inner;
    inner.extend(box.lo + 0.3 * (box.hi - box.lo));
    inner.extend(box.lo + 0.6 * (box.hi - box.lo));
    EXPECT_LE(box.min_distance(p), inner.min_distance(p));
    EXPECT_GE(box.max_distance(p), inner.max_distance(p));
  }
}

// Every item whose box holds p, by walking the tree.
std::set<std::int32_t> holding(const Bvh& bvh, const std::vector<Aabb>& boxes, const Vec3& p) {
  std::set<std::int32_t> out;
  const auto nodes = bvh.nodes();
  bvh.walk([&](std::int32_t n) { return nodes[static_cast<std::size_t>(n)].box.contains(p); },
           [&](std::int32_t n) {
             const BvhNode& node = nodes[static_cast<std::size_t>(n)];
             for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
               const std::int32_t item = bvh.items()[static_cast<std::size_t>(i)];
               if (boxes[static_cast<std::size_t>(item)].contains(p)) out.insert(item);
             }
             return true;
           });
  return out;
}

TEST(Bvh, WalksFindEveryItemWithAndWithoutLevels) {
  std::mt19937 rng(2);
  std::vector<Aabb> boxes;
  std::vector<std::int32_t> levels;
  for (int i = 0; i < 2000; ++i) {
    const int level = static_cast<int>(rng() % 5);
    boxes.push_back(random_box(rng, 0.02 * (1 << level)));
    levels.push_back(level);
  }
  for (bool with_levels : {false, true}) {
    Bvh bvh;
    bvh.build(boxes, with_levels ? std::span<const std::int32_t>(levels) : std::span<const std::int32_t>());
    // Every item once, every node's box holds its children.
    std::multiset<std::int32_t> items(bvh.items().begin(), bvh.items().end());
    EXPECT_EQ(items.size(), boxes.size());
    EXPECT_EQ(std::set<std::int32_t>(items.begin(), items.end()).size(), boxes.size());
    for (const BvhNode& node : bvh.nodes()) {
      if (node.leaf()) {
        EXPECT_LE(node.count, 4);
        for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
          const Aabb& b = boxes[static_cast<std::size_t>(bvh.items()[static_cast<std::size_t>(i)])];
          EXPECT_TRUE(node.box.contains(b.lo) && node.box.contains(b.hi));
        }
      } else {
        for (int c = 0; c < 2; ++c) {
          const Aabb& b = bvh.nodes()[static_cast<std::size_t>(node.first + c)].box;
          EXPECT_TRUE(node.box.contains(b.lo) && node.box.contains(b.hi));
        }
      }
    }
    std::uniform_real_distribution<double> u(-1.0, 1.5);
    for (int q = 0; q < 200; ++q) {
      const Vec3 p(u(rng), u(rng), u(rng));
      std::set<std::int32_t> expected;
      for (std::size_t i = 0; i < boxes.size(); ++i)
        if (boxes[i].contains(p)) expected.insert(static_cast<std::int32_t>(i));
      ASSERT_EQ(holding(bvh, boxes, p), expected);
    }
  }
}

TEST(Bvh, EmptyBuildHasNoNodes) {
  Bvh bvh;
  bvh.build({});
  EXPECT_TRUE(bvh.empty());
  int visited = 0;
  bvh.walk([&](std::int32_t) { return ++visited, true; }, [](std::int32_t) { return true; });
  EXPECT_EQ(visited, 0);
}

}  // namespace
}  // namespace mtcut::engine
