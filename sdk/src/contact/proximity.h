// One deterministic proximity query between two meshes: the whole method of
// the paper for one pose, as the global thread runs it.
#pragma once

#include "contact/global_search.h"
#include "contact/local_tracking.h"
#include "contact/patches.h"

#include <vector>

namespace prox {

enum class Method {
  Precise,    // the improved method: exact distances, visibility pre-test, reduction
  Original,   // the Johnson-Cohen baseline: 7 x 7 feature points, G5
  Reference,  // the brute-force truth
};

const char* method_name(Method m);

struct ProximityResult {
  std::vector<LmdPair> lmds;
  GlobalSearchStats global;
  // The two local tracking passes that follow the precise global search
  // (paper section 4.3): the first reduces the candidates, the second brings
  // them to the latest pose.
  LocalTrackingStats reduction[2];
  // The precise and reference LMDs merged into patches (query.patches):
  // lmds holds the seeds; patches.lmds_in is how many LMDs there were.
  PatchStats patches;
  std::uint32_t candidates = 0;  // before reduction
  double min_distance = -1.0;    // over lmds; -1 when there are none
};

// What a pair of bodies keeps between queries: the trackers' memory, so that
// repeated queries allocate nothing once warm.
struct PairState {
  LocalTracker precise;
  LocalTracker original = LocalTracker::original();
  PatchMerger patches;
};

// Runs `method` for the query's poses. `later_pose` lets the last tracking
// pass see where B has moved meanwhile (nullptr: stay at the query's pose).
// The precise LMDs after their reduction, and the reference's, are merged
// into patches by query.patches (the baseline's are left as they are).
void find_lmds(const PairQuery& query, Method method, PairState& state, ProximityResult& result,
               const PairQuery* later_pose = nullptr);

}  // namespace prox
