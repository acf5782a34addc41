#include "runtime/body_tree.h"

#include <glm/common.hpp>

#include <algorithm>

namespace prox::runtime {
namespace {

constexpr std::uint32_t kLeafSize = 4;
// Median splits halve the items, so depth stays near log2(n / kLeafSize);
// the cap keeps the query's fixed stack safe whatever the input.
constexpr int kMaxDepth = 48;

Aabb merged(const Aabb& a, const Aabb& b) { return {glm::min(a.min, b.min), glm::max(a.max, b.max)}; }

}  // namespace

void BodyTree::build(std::vector<Item> items) {
  items_ = std::move(items);
  nodes_.clear();
  if (items_.empty()) return;
  nodes_.reserve(2 * (items_.size() / kLeafSize + 1));
  nodes_.emplace_back();
  split(0, 0, static_cast<std::uint32_t>(items_.size()), 0);
}

void BodyTree::split(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth) {
  Aabb box = items_[begin].box;
  for (std::uint32_t i = begin + 1; i < end; ++i) box = merged(box, items_[i].box);
  nodes_[node].box = box;
  if (end - begin <= kLeafSize || depth >= kMaxDepth) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
    return;
  }
  const Vec3 extent = box.max - box.min;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                   [axis](const Item& a, const Item& b) {
                     return a.box.min[axis] + a.box.max[axis] < b.box.min[axis] + b.box.max[axis];
                   });
  const auto left = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  nodes_.emplace_back();
  nodes_[node].first = left;
  nodes_[node].count = 0;
  split(left, begin, mid, depth + 1);
  split(left + 1, mid, end, depth + 1);
}

}  // namespace prox::runtime
