// The scenes on the runtime rather than on one pair: many bodies in a world,
// and path T in real time on the runtime's threads.
#pragma once

#include "models.h"
#include "scene_run.h"

namespace prox::bench {

// One tool on path T among crowds of static bunnies out of range.
void run_many_bodies(const Model& model, const Options& opt);
// Path T in real time on the haptic, local and global threads.
void run_threads(const Model& model, const Options& opt);

}  // namespace prox::bench
