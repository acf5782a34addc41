// Local tracking of LMD pairs with a results cache (paper sections 3.2.2, 4.2).
#pragma once

#include "contact/lmd.h"
#include "geometry/triangle_distance.h"

#include <cstdint>
#include <vector>

namespace prox {

struct LocalTrackingStats {
  std::uint32_t pairs_in = 0;
  std::uint32_t pairs_out = 0;
  std::uint64_t distance_evaluations = 0;  // exact triangle distances computed
  std::uint64_t cache_hits = 0;            // ... and answered from the cache instead
  std::uint64_t plane_skips = 0;           // ... and proved no closer by a plane bound instead
  std::uint32_t duplicates_dropped = 0;    // walked into another LMD's path or result
  std::uint32_t dropped_out_of_range = 0;  // walked beyond the cutoff or into an intersection
  std::uint32_t steps = 0;                 // moves to a closer neighbouring pair
  double seconds = 0.0;

  LocalTrackingStats& operator+=(const LocalTrackingStats& s) {
    pairs_in += s.pairs_in, pairs_out += s.pairs_out, distance_evaluations += s.distance_evaluations;
    cache_hits += s.cache_hits, plane_skips += s.plane_skips, duplicates_dropped += s.duplicates_dropped;
    dropped_out_of_range += s.dropped_out_of_range, steps += s.steps, seconds += s.seconds;
    return *this;
  }
};

// Updates a set of LMD pairs to the query's poses. Each pair walks to the
// closest pair among the triangles around its closest features (face: the
// triangle; edge: the triangles sharing it; vertex: its one-ring) until it
// stays. A cache of triangle-pair results, cleared at every update, avoids
// computing a pair twice and tells when a pair walks onto another pair's path:
// that pair is then a duplicate and is dropped. Pairs that end beyond the
// cutoff or on intersecting triangles are dropped too.
//
// Keeps its cache and scratch memory between updates: after the first few
// updates it allocates nothing. One tracker per thread.
class LocalTracker {
 public:
  // The improved tracker: exact distances, a results cache, duplicates
  // dropped when walks meet (paper 4.2).
  LocalTracker() = default;
  // The Johnson-Cohen baseline (paper 3.2.2): 7 x 7 sampled distances, no
  // cache; pairs that end on the same triangle pair merge.
  static LocalTracker original() {
    LocalTracker t;
    t.original_ = true;
    return t;
  }

  // `known`: the input pairs' distances were just computed at the query's
  // poses (the global search's candidates), so they seed the cache instead
  // of being computed again.
  void update(const PairQuery& query, std::vector<LmdPair>& lmds, LocalTrackingStats& stats,
              bool known = false);

  // Tests only: the stamp of the last update, to cross its wrap-around
  // without 2^32 updates.
  void set_stamp_for_testing(std::uint32_t stamp) { stamp_ = stamp; }

 private:
  // The cache: entries in the order computed (indices stay valid while the
  // vector grows), found through an open-addressing table of indices.
  struct Entry {
    std::uint64_t key = 0;
    std::uint32_t owner = 0;  // the LMD whose walk computed it
    bool visited = false;     // the owner's walk stood on this pair
    // Only known to be farther than result.distance (a neighbour measured
    // against a walk's limit); the rest of `result` is not there yet.
    bool partial = false;
    geometry::TriangleDistance result;
  };
  // Index of the entry for `key`, or kMissing.
  std::uint32_t find(std::uint64_t key) const;
  void insert(std::uint64_t key, std::uint32_t index);
  void rehash(std::size_t slots);

  static constexpr std::uint32_t kMissing = 0xFFFFFFFFu;
  bool original_ = false;
  std::vector<Entry> entries_;
  // Entry index + 1 in the low 32 bits, the update's stamp in the high 32: a
  // slot of an earlier update's stamp is empty, so a new update needs no
  // clearing (the table keeps the size its largest update needed).
  std::vector<std::uint64_t> slots_;
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> around_a_, around_b_;
  std::vector<LmdPair> next_;
};

}  // namespace prox
