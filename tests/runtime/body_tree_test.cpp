// The broadphase tree against brute force: every query must return exactly
// the boxes that overlap, whatever the layout.
#include "runtime/body_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace prox::runtime {
namespace {

std::vector<std::uint32_t> brute_force(const std::vector<BodyTree::Item>& items, const Aabb& box) {
  std::vector<std::uint32_t> out;
  for (const BodyTree::Item& item : items)
    if (boxes_overlap(item.box, box)) out.push_back(item.id);
  std::sort(out.begin(), out.end());
  return out;
}

TEST(BodyTree, FindsExactlyTheOverlappingBoxes) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> where(-10.0, 10.0), size(0.0, 1.5);
  for (int n : {0, 1, 3, 4, 5, 17, 100, 1000}) {
    std::vector<BodyTree::Item> items;
    for (int i = 0; i < n; ++i) {
      const Vec3 lo(where(rng), where(rng), where(rng));
      // Some boxes flat or a point: degenerate bodies still have boxes.
      const Vec3 extent(size(rng), i % 7 == 0 ? 0.0 : size(rng), i % 11 == 0 ? 0.0 : size(rng));
      items.push_back({{lo, lo + extent}, static_cast<std::uint32_t>(1000 + i)});
    }
    // Duplicated boxes: the median split must cope with ties.
    if (n > 10)
      for (int i = 0; i < 20; ++i) items.push_back({items[0].box, static_cast<std::uint32_t>(5000 + i)});
    BodyTree tree;
    tree.build(items);
    EXPECT_EQ(tree.size(), items.size());
    for (int q = 0; q < 200; ++q) {
      const Vec3 lo(where(rng), where(rng), where(rng));
      const Aabb box{lo, lo + Vec3(3.0 * size(rng), 3.0 * size(rng), 3.0 * size(rng))};
      std::vector<std::uint32_t> found;
      tree.query(box, [&found](std::uint32_t id) { found.push_back(id); });
      std::sort(found.begin(), found.end());
      ASSERT_EQ(found, brute_force(items, box)) << n << " boxes, query " << q;
    }
    // A query covering everything finds everything once.
    std::vector<std::uint32_t> all;
    tree.query({Vec3(-100.0), Vec3(100.0)}, [&all](std::uint32_t id) { all.push_back(id); });
    EXPECT_EQ(all.size(), items.size());
  }
}

TEST(BodyTree, AllBoxesInOneSpotStillWork) {
  // Every box the same: the median split cannot separate them; the depth
  // cap keeps the query's stack bounded.
  std::vector<BodyTree::Item> items;
  for (std::uint32_t i = 0; i < 5000; ++i) items.push_back({{Vec3(0.0), Vec3(1.0)}, i});
  BodyTree tree;
  tree.build(items);
  int hits = 0;
  tree.query({Vec3(0.5), Vec3(0.6)}, [&hits](std::uint32_t) { ++hits; });
  EXPECT_EQ(hits, 5000);
}

}  // namespace
}  // namespace prox::runtime
