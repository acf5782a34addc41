// The broadphase over bodies: a bounding-volume tree of their world boxes,
// built top-down (median split on the longest axis) and queried with a
// tool's box grown by the cutoff. Static and movable bodies only change
// when the game moves them, so the tree is rebuilt then and not per step: a
// step costs O(log n + k) for n bodies of which k are in range
// (docs/benchmarks-runtime.md, the many-bodies scene).
#pragma once

#include "mesh/mesh.h"

#include <cstdint>
#include <vector>

namespace prox::runtime {

inline bool boxes_overlap(const Aabb& a, const Aabb& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
         a.min.z <= b.max.z && b.min.z <= a.max.z;
}

class BodyTree {
 public:
  struct Item {
    Aabb box;
    std::uint32_t id = 0;
  };

  // Replaces the tree's contents.
  void build(std::vector<Item> items);

  // Calls visit(id) for every item whose box overlaps `box`.
  template <typename Visit>
  void query(const Aabb& box, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!boxes_overlap(n.box, box)) continue;
      if (n.count > 0) {
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
          if (boxes_overlap(items_[i].box, box)) visit(items_[i].id);
      } else {
        stack[top++] = n.first;  // left child; the right one follows it
        stack[top++] = n.first + 1;
      }
    }
  }

  std::size_t size() const { return items_.size(); }

 private:
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  // leaf: first item; inner: left child (right = first + 1)
    std::uint32_t count = 0;  // items in a leaf; 0 for an inner node
  };
  void split(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth);

  std::vector<Node> nodes_;
  std::vector<Item> items_;
};

}  // namespace prox::runtime
