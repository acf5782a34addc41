#include "contact/patches.h"

#include "snch/cone.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace prox {

Vec3 lmd_direction(const PairQuery& q, const LmdPair& p) {
  const Vec3 d = p.point_b - p.point_a;
  const double len = glm::length(d);
  if (len > 0.0) return d / len;
  // Touching: the tool's face normal, turned to point away from A's.
  Vec3 n = q.pose_b.rotate(q.mesh_b->face_normal(p.tri_b));
  const Vec3 na = q.pose_a.rotate(q.mesh_a->face_normal(p.tri_a));
  if (glm::dot(n, na) < 0.0) n = -n;
  const double nl = glm::length(n);
  return nl > 0.0 ? n / nl : Vec3(0.0);
}

namespace {

std::int64_t cell_of(double x, double cell) {
  const double c = std::floor(x / cell);
  // Far-away points share the extreme cells: still correct, only slower.
  return static_cast<std::int64_t>(std::clamp(c, -1e15, 1e15));
}

std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  // Mixes the three cell indices into one key (collisions only share a
  // bucket: every candidate is still tested exactly).
  const auto h = [](std::int64_t v) { return static_cast<std::uint64_t>(v) * 0x9E3779B97F4A7C15ull; };
  return h(x) ^ (h(y) >> 21 | h(y) << 43) ^ (h(z) >> 42 | h(z) << 22);
}

}  // namespace

void PatchMerger::merge(const PairQuery& q, const PatchSettings& settings, std::vector<LmdPair>& lmds,
                        PatchStats& stats) {
  const auto n = static_cast<std::uint32_t>(lmds.size());
  stats.lmds_in += n;
  const double radius = settings.radius_over_cutoff * q.cutoff;
  if (!settings.enabled() || !(radius > 0.0) || n < 2) {
    stats.patches += n;
    if (n > 0) stats.largest = std::max<std::uint32_t>(stats.largest, 1);
    return;
  }
  const double max_spread = settings.max_spread_over_cutoff * q.cutoff;
  const double cos_max = std::cos(std::clamp(settings.max_angle_degrees, 0.0, 180.0) * (kPi / 180.0));
  order_.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) order_[i] = i;
  std::sort(order_.begin(), order_.end(), [&](std::uint32_t i, std::uint32_t j) {
    const LmdPair &a = lmds[i], &b = lmds[j];
    return std::tie(a.distance, a.tri_a, a.tri_b, a.feature_a.kind, a.feature_a.index, a.feature_b.kind,
                    a.feature_b.index) < std::tie(b.distance, b.tri_a, b.tri_b, b.feature_a.kind,
                                                  b.feature_a.index, b.feature_b.kind, b.feature_b.index);
  });
  directions_.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) directions_[i] = lmd_direction(q, lmds[i]);
  seeds_.clear();
  seed_index_.clear();
  next_in_cell_.clear();
  cells_.clear();
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t i = order_[k];
    const LmdPair& p = lmds[i];
    const Vec3& u = directions_[i];
    const std::int64_t cx = cell_of(p.point_b.x, radius), cy = cell_of(p.point_b.y, radius),
                       cz = cell_of(p.point_b.z, radius);
    // The first seed (in seed order) it agrees with, among the 27 cells
    // around it: a point within the radius is in one of them.
    std::uint32_t join = ~0u;
    double join_cos = 1.0;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(cell_key(cx + dx, cy + dy, cz + dz));
          if (it == cells_.end()) continue;
          for (std::uint32_t s = it->second; s != 0; s = next_in_cell_[s - 1]) {
            const std::uint32_t seed = s - 1;
            if (seed >= join) continue;
            const LmdPair& sp = seeds_[seed];
            const Vec3 off = p.point_b - sp.point_b;
            if (glm::dot(off, off) > radius * radius || p.distance - sp.distance > max_spread) continue;
            const double c = glm::dot(u, directions_[seed_index_[seed]]);
            // A zero direction agrees with nothing.
            if (!(c >= cos_max) || glm::dot(u, u) == 0.0 ||
                glm::dot(directions_[seed_index_[seed]], directions_[seed_index_[seed]]) == 0.0)
              continue;
            join = seed, join_cos = c;
          }
        }
    if (join != ~0u) {
      LmdPair& sp = seeds_[join];
      sp.patch_count += p.patch_count;
      sp.patch_extent = std::max(sp.patch_extent, glm::length(p.point_b - sp.point_b) + p.patch_extent);
      sp.patch_spread = std::max(sp.patch_spread, p.distance - sp.distance + p.patch_spread);
      sp.patch_angle = std::max(sp.patch_angle, std::acos(std::clamp(join_cos, -1.0, 1.0)) + p.patch_angle);
      continue;
    }
    const auto seed = static_cast<std::uint32_t>(seeds_.size());
    seeds_.push_back(p);
    seed_index_.push_back(i);
    std::uint32_t& head = cells_[cell_key(cx, cy, cz)];
    next_in_cell_.push_back(head);
    head = seed + 1;
  }
  stats.patches += static_cast<std::uint32_t>(seeds_.size());
  stats.merged += n - static_cast<std::uint32_t>(seeds_.size());
  for (const LmdPair& s : seeds_) stats.largest = std::max(stats.largest, s.patch_count);
  lmds.swap(seeds_);
}

double patch_force_error_bound(const ForceSettings& settings, const std::vector<LmdPair>& seeds) {
  double bound = 0.0;
  for (const LmdPair& s : seeds) {
    if (s.patch_count < 2) continue;
    const double f = force_magnitude(settings, s.distance);
    const double per_member = (f - force_magnitude(settings, s.distance + s.patch_spread)) +
                              f * 2.0 * std::sin(std::min(s.patch_angle, kPi) / 2.0);
    bound += (s.patch_count - 1) * per_member;
  }
  return bound;
}

}  // namespace prox
