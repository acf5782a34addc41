// What a scene run reports: the per-step CSV, the summary JSON and the
// readable summary on standard output.
#pragma once

#include "scene_run.h"

#include <string>

namespace prox::bench {

// What the peers answer, beside Proxima's answer (printed and in the JSON).
extern const char* const kPeerNote;

std::string summary_json(const SceneRun& run, const Options& opt);
std::string csv(const SceneRun& run);
void print_summary(const SceneRun& run);

}  // namespace prox::bench
