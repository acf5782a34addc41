#include "contact/local_tracking.h"

#include "contact/global_search.h"
#include "geometry/sampled_distance.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <limits>
#include <tuple>

namespace prox {
namespace {

std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser: spreads pair keys over the table
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A walk gives up after this many moves; real walks take a handful.
constexpr int kMaxSteps = 256;

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

}  // namespace

std::uint32_t LocalTracker::find(std::uint64_t key) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = mix(key) & mask;; i = (i + 1) & mask) {
    if (slots_[i] >> 32 != stamp_) return kMissing;
    const auto index = static_cast<std::uint32_t>(slots_[i]) - 1;
    if (entries_[index].key == key) return index;
  }
}

void LocalTracker::insert(std::uint64_t key, std::uint32_t index) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = mix(key) & mask;
  while (slots_[i] >> 32 == stamp_) i = (i + 1) & mask;
  slots_[i] = std::uint64_t{stamp_} << 32 | (index + 1);
}

void LocalTracker::rehash(std::size_t slots) {
  slots_.assign(slots, 0u);
  for (std::uint32_t i = 0; i < entries_.size(); ++i) insert(entries_[i].key, i);
}

void LocalTracker::update(const PairQuery& q, std::vector<LmdPair>& lmds, LocalTrackingStats& stats,
                          bool known) {
  const auto start = std::chrono::steady_clock::now();
  // The cache lives for one update (the poses change between updates): a
  // new stamp empties it. Stamp 0 is never live, so a table just assigned
  // is empty; after 2^32 - 1 updates the stamps start over on a cleared one.
  entries_.clear();
  if (slots_.empty()) slots_.assign(256, 0u);  // grows with the largest update
  if (++stamp_ == 0) {
    std::fill(slots_.begin(), slots_.end(), 0u);
    stamp_ = 1;
  }
  const Pose b_to_a = q.pose_a.inverse() * q.pose_b;
  const Mesh& ma = *q.mesh_a;
  const Mesh& mb = *q.mesh_b;
  const double size = std::max(glm::length(ma.bounds().max - ma.bounds().min),
                               glm::length(mb.bounds().max - mb.bounds().min));
  const double tolerance = 1e-12 * size;

  // The cache entry of a triangle pair, computed on first use. Returns an
  // index: entries_ may grow while a walk holds it. With a `limit`, a pair
  // farther than it is left partial (its distance only known to be past
  // the limit), found as soon as that is certain; it is measured again if
  // a later look needs more of it.
  auto measure = [&](Entry& e, std::uint32_t ta, std::uint32_t tb, double limit) {
    const Triangle a = ma.triangle(ta);
    const Triangle b = mb.triangle(tb);
    const Triangle moved_b{{b_to_a.apply(b.v[0]), b_to_a.apply(b.v[1]), b_to_a.apply(b.v[2])}};
    ++stats.distance_evaluations;
    if (original_) {
      e.result = geometry::sampled_triangle_distance(a, moved_b);
      return;
    }
    // The reduction's walks start from every candidate of a search, most
    // of them far from a minimum: the single-precision screen settles many
    // of their neighbours. A local update's pairs stand at or next to a
    // minimum, where candidates tie (flush faces, shared vertices) and the
    // screen settles few: there it only added its cost (local update p99
    // 11 -> 20 us on cad-engine; docs/benchmarks-changes.md).
    e.partial = !(known ? geometry::triangle_distance_within(a, moved_b, limit, e.result)
                        : geometry::triangle_distance_within_unscreened(a, moved_b, limit, e.result));
    if (e.partial) e.result.distance = limit;
  };
  auto evaluate = [&](std::uint32_t ta, std::uint32_t tb, std::uint32_t owner,
                      double limit = kNoLimit) -> std::uint32_t {
    const std::uint64_t key = pair_key(ta, tb);
    const std::uint32_t hit = original_ ? kMissing : find(key);
    if (hit != kMissing) {
      Entry& cached = entries_[hit];
      if (cached.partial && limit > cached.result.distance) {
        measure(cached, ta, tb, limit);
      } else {
        ++stats.cache_hits;
      }
      return hit;
    }
    Entry e;
    e.key = key;
    e.owner = owner;
    measure(e, ta, tb, limit);
    const auto index = static_cast<std::uint32_t>(entries_.size());
    entries_.push_back(e);
    if (original_) return index;  // no cache: nothing is looked up again
    if (2 * entries_.size() > slots_.size())
      rehash(2 * slots_.size());
    else
      insert(key, index);
    return index;
  };

  // Whether triangles ta of A and tb of B are farther apart than `limit`
  // by either one's plane.
  auto plane_separated = [&](std::uint32_t ta_, std::uint32_t tb_, double limit) {
    const Triangle a = ma.triangle(ta_);
    const Triangle b = mb.triangle(tb_);
    const Triangle moved_b{{b_to_a.apply(b.v[0]), b_to_a.apply(b.v[1]), b_to_a.apply(b.v[2])}};
    return beyond_plane(a, ma.face_normal(ta_), moved_b, limit) ||
           beyond_plane(moved_b, b_to_a.rotate(mb.face_normal(tb_)), a, limit);
  };

  if (known && !original_) {
    // The candidates' results, back in A's frame, as if computed here.
    const Pose to_a = q.pose_a.inverse();
    for (std::uint32_t k = 0; k < lmds.size(); ++k) {
      const LmdPair& p = lmds[k];
      const std::uint64_t key = pair_key(p.tri_a, p.tri_b);
      if (find(key) != kMissing) continue;
      Entry e;
      e.key = key;
      e.owner = k;
      e.result.distance = p.distance;
      e.result.point_a = to_a.apply(p.point_a);
      e.result.point_b = to_a.apply(p.point_b);
      e.result.feature_a = p.feature_a;
      e.result.feature_b = p.feature_b;
      const auto index = static_cast<std::uint32_t>(entries_.size());
      entries_.push_back(e);
      if (2 * entries_.size() > slots_.size())
        rehash(2 * slots_.size());
      else
        insert(key, index);
    }
  }

  stats.pairs_in += static_cast<std::uint32_t>(lmds.size());
  next_.clear();
  for (std::uint32_t k = 0; k < lmds.size(); ++k) {
    std::uint32_t ta = lmds[k].tri_a, tb = lmds[k].tri_b;
    std::uint32_t here = evaluate(ta, tb, k);
    // Standing where another LMD's walk stood: from there it follows that
    // walk to the same minimum, so this one is a duplicate.
    auto stand_on = [&](std::uint32_t index) {
      Entry& e = entries_[index];
      const bool duplicate = !original_ && e.visited && e.owner != k;
      e.owner = k;
      e.visited = true;
      return duplicate;
    };
    bool duplicate = stand_on(here);
    for (int step = 0; step < kMaxSteps && !duplicate; ++step) {
      const geometry::TriangleDistance current = entries_[here].result;
      if (current.intersects) break;
      feature_neighbourhood(ma, ta, current.feature_a, around_a_);
      feature_neighbourhood(mb, tb, current.feature_b, around_b_);
      std::uint32_t best = here, best_a = ta, best_b = tb;
      double best_distance = current.distance;
      for (std::uint32_t na : around_a_)
        for (std::uint32_t nb : around_b_) {
          if (na == ta && nb == tb) continue;
          // A neighbour the plane bound puts farther than the best so far
          // less half the tolerance cannot be the next step (nor
          // intersect): a step needs a pair closer by the whole tolerance.
          // Skip its exact distance unless the cache already has it. The
          // half tolerance left is far above the plane bound's rounding, so
          // rounding cannot skip a closer pair; and a flat field's ties (a
          // neighbour exactly as far, as across parallel sheets) are skipped
          // rather than computed.
          if (!original_ && best_distance > 0.0 && find(pair_key(na, nb)) == kMissing &&
              plane_separated(na, nb, best_distance - 0.5 * tolerance)) {
            ++stats.plane_skips;
            continue;
          }
          // Only a pair closer than the best by the tolerance is of use
          // here (or one that intersects: a limit of at least 0 keeps it).
          // Not in the reduction (`known`), whose many walks cross: a pair
          // left partial for one would be measured again for another.
          const std::uint32_t e = evaluate(na, nb, k, known ? kNoLimit : std::max(best_distance - tolerance, 0.0));
          if (entries_[e].partial) continue;
          const geometry::TriangleDistance& r = entries_[e].result;
          if (r.intersects || r.distance < best_distance - tolerance) {
            best = e, best_a = na, best_b = nb;
            best_distance = r.intersects ? -1.0 : r.distance;
          }
        }
      if (best == here) break;  // a local minimum: it stays
      ++stats.steps;
      ta = best_a, tb = best_b, here = best;
      duplicate = stand_on(here);
    }
    if (duplicate) {
      ++stats.duplicates_dropped;
      continue;
    }
    const geometry::TriangleDistance& r = entries_[here].result;
    if (r.intersects || r.distance > q.cutoff) {
      ++stats.dropped_out_of_range;
      continue;
    }
    LmdPair out;
    out.tri_a = ta;
    out.tri_b = tb;
    out.point_a = q.pose_a.apply(r.point_a);
    out.point_b = q.pose_a.apply(r.point_b);
    out.distance = r.distance;
    out.feature_a = r.feature_a;
    out.feature_b = r.feature_b;
    out.mesh_feature_a = mesh_feature(ma, ta, r.feature_a);
    out.mesh_feature_b = mesh_feature(mb, tb, r.feature_b);
    // A patch's seed keeps standing for its patch until the next search.
    out.patch_count = lmds[k].patch_count;
    out.patch_extent = lmds[k].patch_extent;
    out.patch_spread = lmds[k].patch_spread;
    out.patch_angle = lmds[k].patch_angle;
    next_.push_back(out);
  }
  // Two pairs on the same mesh features are one LMD.
  std::sort(next_.begin(), next_.end(), [](const LmdPair& a, const LmdPair& b) {
    return std::tie(a.mesh_feature_a.kind, a.mesh_feature_a.id, a.mesh_feature_b.kind, a.mesh_feature_b.id,
                    a.tri_a, a.tri_b) < std::tie(b.mesh_feature_a.kind, b.mesh_feature_a.id,
                                                 b.mesh_feature_b.kind, b.mesh_feature_b.id, b.tri_a,
                                                 b.tri_b);
  });
  lmds.clear();
  for (const LmdPair& p : next_) {
    if (!lmds.empty() && lmds.back().mesh_feature_a == p.mesh_feature_a &&
        lmds.back().mesh_feature_b == p.mesh_feature_b) {
      ++stats.duplicates_dropped;
      continue;
    }
    lmds.push_back(p);
  }
  stats.pairs_out += static_cast<std::uint32_t>(lmds.size());
  stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace prox
