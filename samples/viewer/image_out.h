// What --out writes per frame: the image as PNG and its JSON sidecar, which
// holds what a test needs to check the picture (docs/viewer.md): the
// matrices, the viewport, the background and what was drawn.
#pragma once

#include "scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace viewer {

// 8-bit RGB rows, top first. Throws std::runtime_error naming the file.
void write_png(const std::string& path, const std::vector<uint8_t>& rgb, uint32_t width, uint32_t height);

struct Sidecar {
  glm::mat4 view{1.0f}, proj{1.0f};
  uint32_t width = 0, height = 0;
  glm::vec4 background{0.0f};
  const FrameData* frame = nullptr;
};

void write_sidecar(const std::string& path, const Sidecar& s);

// DIR/frame-0012 for frame 12.
std::string frame_stem(const std::string& dir, int frame);

}  // namespace viewer
