#include "contact/proximity.h"

#include <algorithm>

namespace prox {

const char* method_name(Method m) {
  switch (m) {
    case Method::Precise:
      return "precise";
    case Method::Original:
      return "original";
    case Method::Reference:
      return "reference";
  }
  return "unknown";
}

void find_lmds(const PairQuery& query, Method method, PairState& state, ProximityResult& result,
               const PairQuery* later_pose) {
  result = ProximityResult{};
  switch (method) {
    case Method::Precise:
      global_search_precise(query, result.lmds, result.global);
      result.candidates = static_cast<std::uint32_t>(result.lmds.size());
      state.precise.update(query, result.lmds, result.reduction[0], /*known=*/true);
      state.precise.update(later_pose ? *later_pose : query, result.lmds, result.reduction[1]);
      state.patches.merge(later_pose ? *later_pose : query, query.patches, result.lmds, result.patches);
      break;
    case Method::Original:
      // The baseline has no tracking in the global thread; its local thread's
      // first update (at the same pose here) is what reduces the candidates.
      global_search_original(query, result.lmds, result.global);
      result.candidates = static_cast<std::uint32_t>(result.lmds.size());
      state.original.update(later_pose ? *later_pose : query, result.lmds, result.reduction[0]);
      break;
    case Method::Reference:
      reference_lmds(query, result.lmds);
      result.candidates = static_cast<std::uint32_t>(result.lmds.size());
      state.patches.merge(query, query.patches, result.lmds, result.patches);
      break;
  }
  for (const LmdPair& p : result.lmds)
    result.min_distance = result.min_distance < 0.0 ? p.distance : std::min(result.min_distance, p.distance);
}

}  // namespace prox
