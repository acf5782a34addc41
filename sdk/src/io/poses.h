// Pose files: one rigid pose per line, "tx ty tz qw qx qy qz" (translation,
// then a quaternion with w first), '#' starting a comment line. Used for
// scripted paths (the scripted device, the CLI's --poses).
#pragma once

#include "common/status.h"

#include <cstddef>
#include <string>
#include <vector>

namespace prox::io {

// The most poses a file may hold: a 1 kHz path of almost 17 minutes. Longer
// files are refused before they are parsed, bounding time and memory.
constexpr std::size_t kMaxPoses = 1000000;

struct PoseRecord {
  double position[3];
  double rotation[4];  // w, x, y, z; normalised on reading
};

// Reads `path`. Errors name the file and line: a missing file, a line
// without exactly seven numbers, a non-finite number, a zero quaternion, a
// file with no pose or more than kMaxPoses.
Status read_poses(const std::string& path, std::vector<PoseRecord>& out);
// The same, from text already in memory (`name` is used in messages).
Status parse_poses(const std::string& text, const std::string& name, std::vector<PoseRecord>& out);

}  // namespace prox::io
