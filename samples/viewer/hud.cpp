#include "hud.h"

#include <algorithm>
#include <cmath>

namespace viewer {

namespace {

constexpr double kLeft = 16.0, kTop = 16.0, kLength = 200.0, kRow = 14.0;
constexpr float kThickness = 8.0f;
const glm::vec4 kTrack(0.22f, 0.23f, 0.26f, 1.0f);

void bar(DrawList& list, int row, double fill, const glm::vec4& color) {
  const double y = kTop + row * kRow;
  add_segment(list.screen, {kLeft, y, 0.0}, {kLeft + kLength, y, 0.0}, kThickness, kTrack);
  const double f = std::clamp(std::isfinite(fill) ? fill : 0.0, 0.0, 1.0);
  if (f > 0.0) add_segment(list.screen, {kLeft, y, 0.0}, {kLeft + f * kLength, y, 0.0}, kThickness, color);
}

void square(DrawList& list, int row, int column, const glm::vec4& color) {
  const double y = kTop + row * kRow, x = kLeft + column * 2.0 * kRow;
  add_segment(list.screen, {x, y, 0.0}, {x + 0.5 * kRow, y, 0.0}, kThickness, color);
}

}  // namespace

void add_hud(DrawList& list, const HudState& hud) {
  const double ms = hud.frame_seconds * 1e3;
  bar(list, 0, ms / 50.0,
      ms < 16.7   ? glm::vec4(0.3f, 0.8f, 0.3f, 1.0f)
      : ms < 33.3 ? glm::vec4(0.9f, 0.8f, 0.2f, 1.0f)
                  : glm::vec4(0.9f, 0.3f, 0.2f, 1.0f));
  const glm::vec4 rate(0.35f, 0.55f, 0.95f, 1.0f);
  for (int t = 0; t < 3; ++t) {
    double fill = 0.0;
    if (hud.threads && hud.threads[t].running) {
      const double target = hud.threads[t].targetRate > 0.0 ? hud.threads[t].targetRate : 100.0;
      fill = hud.threads[t].achievedRate / target;
    }
    bar(list, 1 + t, fill, rate);
  }
  bar(list, 4, std::log10(1.0 + static_cast<double>(hud.contacts)) / 3.0, glm::vec4(0.9f, 0.6f, 0.2f, 1.0f));
  bar(list, 5, hud.force / hud.max_force, glm::vec4(1.0f));
  square(list, 6, 0,
         hud.method == PROX_METHOD_ORIGINAL ? glm::vec4(1.0f, 0.55f, 0.1f, 1.0f)
                                            : glm::vec4(0.3f, 0.5f, 1.0f, 1.0f));
  const glm::vec4 device = hud.device == DeviceKind::scripted  ? glm::vec4(0.6f, 0.4f, 0.9f, 1.0f)
                           : hud.device == DeviceKind::mouse   ? glm::vec4(0.2f, 0.8f, 0.7f, 1.0f)
                           : hud.device == DeviceKind::gamepad ? glm::vec4(0.9f, 0.9f, 0.3f, 1.0f)
                                                               : glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  square(list, 6, 1, device);
}

}  // namespace viewer
