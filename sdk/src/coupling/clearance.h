// The proxy's safety check: whether any triangle pair of two meshes is
// closer than a distance, by depth-first descent of their sphere trees
// (a node pair culled by its spheres or its boxes, as the searches cull).
// The same decision as contact/global_search.h's any_closer_than (exact at
// the leaves), without its best-first heap: a check that passes must visit
// every node pair whose bounds come that close anyway, so the order buys
// nothing there and a stack costs less per pair.
#pragma once

#include "contact/lmd.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace prox::coupling {

using NodeStack = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// True when some pair is closer than `distance` (or intersects). `stack` is
// scratch, kept between calls so that a warm check allocates nothing.
bool closer_than(const PairQuery& query, double distance, NodeStack& stack);

}  // namespace prox::coupling
