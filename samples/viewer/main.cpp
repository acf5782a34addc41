// proxima-viewer: the Vulkan viewer. Draws the meshes, the LMD strings, the
// intersection polylines and the force while the world's threads run the
// haptic loop beside it, in a window (GLFW) or headless (offscreen, e.g. on
// lavapipe). A customer of the SDK like any other: it sees only the C API.
// docs/viewer.md says what it shows and how it is tested.
#include "draw_list.h"
#include "hud.h"
#if PROX_VIEWER_TEXT_HUD
#include "hud_text.h"
#endif
#include "image_out.h"
#include "input.h"
#include "options.h"
#include "render_mesh.h"
#include "renderer.h"
#include "scene.h"
#include "targets.h"
#include "vulkan_context.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace viewer {
namespace {

volatile std::sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

std::string default_asset(const char* name) {
  if (const char* dir = std::getenv("PROXIMA_ASSETS")) return std::string(dir) + "/" + name;
  return std::string(PROX_SHARED_ASSETS_DIR) + "/" + name;
}

using Clock = std::chrono::steady_clock;

// Frame times and the summary printed at the end (docs/viewer.md quotes it).
struct Timing {
  std::vector<double> seconds;
  void add(Clock::time_point start) {
    seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  double last() const { return seconds.empty() ? 0.0 : seconds.back(); }
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5))];
}

void print_summary(const Timing& t, const Options& o, const std::string& device, const FrameData& last) {
  if (t.seconds.empty()) return;
  const std::vector<double> steady(t.seconds.begin() + 1, t.seconds.end());
  std::printf("proxima-viewer: %zu frames at %dx%d, %dx MSAA on %s: first %.2f ms", t.seconds.size(), o.width,
              o.height, o.msaa, device.c_str(), t.seconds.front() * 1e3);
  if (!steady.empty())
    std::printf(", then p50 %.2f ms, p99 %.2f ms", percentile(steady, 0.5) * 1e3,
                percentile(steady, 0.99) * 1e3);
  std::printf("\n");
  if (last.threads) {
    const char* names[3] = {"haptic", "local", "global"};
    for (int i = 0; i < 3; ++i) {
      const proxThreadStats& s = last.thread_stats[i];
      std::printf(
          "proxima-viewer: %-6s thread %8.1f Hz, period p50 %.3f ms, p99 %.3f ms, max %.3f ms, %llu "
          "overruns\n",
          names[i], s.achievedRate, s.periodP50 * 1e3, s.periodP99 * 1e3, s.periodMax * 1e3,
          static_cast<unsigned long long>(s.overruns));
    }
  }
}

class Viewer {
 public:
  explicit Viewer(const Options& o) : options_(o), show_(o.show), tool_target_(o.pose_b) {
    path_a_ = o.mesh_a.empty() ? default_asset("bunny.obj") : o.mesh_a;
    path_b_ = o.mesh_b.empty() ? path_a_ : o.mesh_b;
  }
  const RenderMesh& mesh_tool() const { return scene_->shares_mesh() ? mesh_a_ : mesh_b_; }

  int run_headless();
  int run_window();

 private:
  // The world and the meshes to draw; in a window once GLFW can say whether
  // a gamepad is there.
  void build_scene() {
    scene_ = std::make_unique<Scene>(options_, path_a_, path_b_);
    mesh_a_ = scene_->render_mesh(false);
    if (!scene_->shares_mesh()) mesh_b_ = scene_->render_mesh(true);
    if (!options_.out_dir.empty()) {
      std::error_code ec;
      std::filesystem::create_directories(options_.out_dir, ec);
      if (ec)
        throw std::runtime_error(options_.out_dir + ": cannot create the directory (" + ec.message() + ")");
    }
  }
  // --animate: poses the meshes at `seconds` of their animations and hands
  // the renderer the posed vertices, into the buffers it has (the vertex
  // count never changes).
  void animate(Renderer& renderer, double seconds) {
    if (!scene_->animate(seconds)) return;
    frame_.polylines_valid = false;  // the shapes changed, if the tool did not move
    scene_->read_vertices(false, mesh_a_.positions);
    renderer.update_vertices(false, mesh_a_.positions);
    if (!scene_->shares_mesh()) {
      scene_->read_vertices(true, mesh_b_.positions);
      renderer.update_vertices(true, mesh_b_.positions);
    }
  }
  // Reads the scene and builds what the frame draws.
  FrameInput prepare(VkExtent2D extent) {
    scene_->update(frame_, show_.polylines || !options_.out_dir.empty());
    lines_.world.clear();
    lines_.screen.clear();
    add_scene_lines(lines_, frame_, *scene_, show_, camera_);
    std::function<void(VkCommandBuffer)> overlay;
    if (show_.hud) {
      HudState hud;
      hud.frame_seconds = timing_.last();
      hud.threads = frame_.threads ? frame_.thread_stats : nullptr;
      hud.stepped_each_frame = scene_->animated();
      hud.contacts = frame_.contacts.size();
      const proxVec3& f = frame_.wrench.force;
      const proxVec3& t = frame_.wrench.torque;
      hud.force = std::sqrt(f.x * f.x + f.y * f.y + f.z * f.z);
      hud.torque = std::sqrt(t.x * t.x + t.y * t.y + t.z * t.z);
      hud.max_force = scene_->force().maxForce;
      hud.method = options_.method;
      hud.preset = options_.force;
      hud.device = options_.device_kind;
#if PROX_VIEWER_TEXT_HUD
      text_hud_->build(hud, extent);
      overlay = [this](VkCommandBuffer cmd) { text_hud_->record(cmd); };
#else
      add_hud(lines_, hud);
#endif
    }
    const double aspect = static_cast<double>(extent.width) / static_cast<double>(extent.height);
    FrameInput in;
    in.view = camera_.view();
    in.proj = camera_.proj(aspect);
    in.model_a = glm::mat4(frame_.model_a);
    in.model_tool = glm::mat4(frame_.model_tool);
    in.meshes = show_.meshes;
    in.ghost = show_.ghost && frame_.ghost;
    in.model_ghost = glm::mat4(frame_.model_ghost);
    in.lines = &lines_;
    in.overlay = std::move(overlay);
    return in;
  }
  void write_sidecar_for(const FrameInput& in, VkExtent2D extent, int index) {
    Sidecar s;
    s.view = in.view;
    s.proj = in.proj;
    s.width = extent.width;
    s.height = extent.height;
    s.background = kBackground;
    s.frame = &frame_;
    write_sidecar(frame_stem(options_.out_dir, index) + ".json", s);
  }
  void frame_camera(VkExtent2D extent) {
    camera_.frame(scene_->bounds_min(), scene_->bounds_max(),
                  static_cast<double>(extent.width) / static_cast<double>(extent.height));
  }
  int finish(const std::string& device) {
    print_summary(timing_, options_, device, frame_);
    proxStreamDeviceStats stream;
    if (scene_->stream_stats(&stream)) {
      const proxPose p = scene_->tool_pose();
      std::printf(
          "proxima-viewer: %s device: %llu poses pushed, tool at %.6f %.6f %.6f, turned %.6f %.6f %.6f "
          "%.6f\n",
          device_name(options_.device_kind), static_cast<unsigned long long>(stream.samplesPushed),
          p.position.x, p.position.y, p.position.z, p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
    }
    const std::string hid = scene_->hid_summary();
    if (!hid.empty()) std::printf("proxima-viewer: %s\n", hid.c_str());
    const int messages = VulkanContext::validation_messages();
    if (messages > 0) {
      std::fprintf(stderr, "proxima-viewer: %d validation message%s (printed above)\n", messages,
                   messages == 1 ? "" : "s");
      return 1;
    }
    return 0;
  }

  Options options_;
  Show show_;
  proxPose tool_target_;  // where the mouse or the gamepad has taken the tool
  Clock::time_point last_input_ = Clock::now();
  std::string path_a_, path_b_;
  std::unique_ptr<Scene> scene_;
  RenderMesh mesh_a_, mesh_b_;
  Camera camera_;
  FrameData frame_;
  DrawList lines_;
  Timing timing_;
#if PROX_VIEWER_TEXT_HUD
  std::unique_ptr<TextHud> text_hud_;
#endif
  void attach_hud(VulkanContext& vk, const Renderer& renderer) {
#if PROX_VIEWER_TEXT_HUD
    text_hud_ = std::make_unique<TextHud>(vk, renderer.render_pass(), renderer.samples());
#else
    (void)vk;
    (void)renderer;
#endif
  }
  void detach_hud() {
#if PROX_VIEWER_TEXT_HUD
    text_hud_.reset();
#endif
  }
};

VkSampleCountFlagBits samples_of(int msaa) {
  return msaa == 4 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
}

int Viewer::run_headless() {
  build_scene();
  const VkExtent2D extent{static_cast<uint32_t>(options_.width), static_cast<uint32_t>(options_.height)};
  VulkanContext vk({}, options_.validation);
  vk.pick_device(VK_NULL_HANDLE, samples_of(options_.msaa));
  {
    Renderer renderer(vk, kOffscreenFormat, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, samples_of(options_.msaa));
    renderer.set_meshes(mesh_a_, mesh_tool());
    attach_hud(vk, renderer);
    OffscreenTarget target(vk, renderer, extent);
    frame_camera(extent);
    for (int i = 0; i < options_.frames && !g_stop; ++i) {
      const Clock::time_point start = Clock::now();
      animate(renderer, i / 60.0);  // headless: frame i at i / 60 s, the same every run
      const FrameInput in = prepare(extent);
      VkCommandBuffer cmd = vk.begin_frame();
      renderer.record(cmd, target.framebuffer(), extent, in);
      if (!options_.out_dir.empty()) target.record_readback(cmd);
      vk.submit(VK_NULL_HANDLE, 0, VK_NULL_HANDLE);
      vk.wait_frame();
      timing_.add(start);
      if (!options_.out_dir.empty()) {
        write_png(frame_stem(options_.out_dir, i) + ".png", target.rgb(), extent.width, extent.height);
        write_sidecar_for(in, extent, i);
      }
    }
    detach_hud();
  }
  if (!options_.out_dir.empty())
    std::printf("proxima-viewer: wrote %d frame%s to %s\n", static_cast<int>(timing_.seconds.size()),
                timing_.seconds.size() == 1 ? "" : "s", options_.out_dir.c_str());
  return finish(vk.device_name());
}

std::string glfw_error() {
  const char* text = nullptr;
  glfwGetError(&text);
  return text ? text : "no reason given";
}

int Viewer::run_window() {
  if (!glfwInit())
    throw std::runtime_error("cannot open a window: no display (" + glfw_error() +
                             "); set DISPLAY, or render offscreen with --headless");
  struct Terminate {
    ~Terminate() { glfwTerminate(); }
  } terminate;
  if (!glfwVulkanSupported()) throw VulkanError("GLFW finds no Vulkan loader or driver for a window");
  int gamepad = find_gamepad();
  if (options_.device == "auto" && gamepad >= 0 && options_.device_kind != DeviceKind::hid)
    options_.device_kind = DeviceKind::gamepad;
  if (options_.device_kind == DeviceKind::gamepad && gamepad < 0)
    throw std::runtime_error("--device gamepad: no gamepad is connected (GLFW maps none)");
  if (options_.device_kind == DeviceKind::gamepad)
    std::printf("proxima-viewer: gamepad %s\n", glfwGetGamepadName(gamepad));
  build_scene();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  GLFWwindow* window = glfwCreateWindow(options_.width, options_.height, "proxima-viewer", nullptr, nullptr);
  if (!window) throw std::runtime_error("cannot open a window: " + glfw_error());
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  std::vector<const char*> extensions(names, names + count);
  VulkanContext vk(extensions, options_.validation);
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  vk_check(glfwCreateWindowSurface(vk.instance(), window, nullptr, &surface), "glfwCreateWindowSurface");
  std::string device;
  try {
    vk.pick_device(surface, samples_of(options_.msaa));
    device = vk.device_name();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    VkExtent2D extent{static_cast<uint32_t>(w), static_cast<uint32_t>(h)};
    SwapchainTarget target(vk, surface, extent);
    auto renderer = std::make_unique<Renderer>(vk, target.format(), VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                                               samples_of(options_.msaa));
    renderer->set_meshes(mesh_a_, mesh_tool());
    attach_hud(vk, *renderer);
    target.create(*renderer, extent);
    frame_camera(target.extent());

    Input input;
    input.camera = &camera_;
    input.show = &show_;
    input.mouse_device = options_.device_kind == DeviceKind::mouse;
    attach_input(window, &input);
    bool announced = false;
    const Clock::time_point animation_start = Clock::now();
    for (int i = 0;
         !glfwWindowShouldClose(window) && !g_stop && (options_.frames == 0 || i < options_.frames);) {
      glfwPollEvents();
      if (input.switch_method || input.switch_force) {
        if (input.switch_method)
          options_.method =
              options_.method == PROX_METHOD_PRECISE ? PROX_METHOD_ORIGINAL : PROX_METHOD_PRECISE;
        if (input.switch_force)
          options_.force =
              options_.force == PROX_FORCE_PRESET_HARD ? PROX_FORCE_PRESET_SOFT : PROX_FORCE_PRESET_HARD;
        input.switch_method = input.switch_force = false;
        scene_.reset();  // its threads stop first
        scene_ = std::make_unique<Scene>(options_, path_a_, path_b_);
        std::printf("proxima-viewer: method %s, force %s\n", method_name(options_.method),
                    force_name(options_.force));
      }
      if (input.mouse_device) {
        tool_target_.position.x += input.tool_drag.x;
        tool_target_.position.y += input.tool_drag.y;
        tool_target_.position.z += input.tool_drag.z;
        input.tool_drag = glm::dvec3(0.0);
      }
      if (options_.device_kind == DeviceKind::gamepad) {
        // The stick's motion over the time since the last frame, up to a quarter second: a stalled
        // frame does not fling the tool.
        const Clock::time_point now = Clock::now();
        const double seconds = std::min(0.25, std::chrono::duration<double>(now - last_input_).count());
        last_input_ = now;
        if (!apply_gamepad(gamepad, camera_, seconds, &tool_target_))
          gamepad = find_gamepad();  // unplugged: hold
      }
      if (input.mouse_device || options_.device_kind == DeviceKind::gamepad)
        scene_->push_tool_pose(tool_target_);  // every frame: a silent stream fades the force out
      glfwGetFramebufferSize(window, &w, &h);
      if (w == 0 || h == 0) {  // minimised
        glfwWaitEvents();
        continue;
      }
      input.window_height = h;
      extent = {static_cast<uint32_t>(w), static_cast<uint32_t>(h)};
      const Clock::time_point start = Clock::now();
      vk.wait_frame();  // the acquire semaphore is free again
      VkFramebuffer fb;
      if (extent.width != target.extent().width || extent.height != target.extent().height ||
          !target.acquire(&fb)) {
        target.create(*renderer, extent);
        continue;
      }
      animate(*renderer, std::chrono::duration<double>(Clock::now() - animation_start).count());
      const FrameInput in = prepare(target.extent());
      VkCommandBuffer cmd = vk.begin_frame();
      renderer->record(cmd, fb, target.extent(), in);
      vk.submit(target.acquired(), VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, target.rendered());
      const bool presented = target.present();
      vk.wait_frame();
      timing_.add(start);
      ++i;
      if (!presented) target.create(*renderer, extent);
      if (!announced) {
        std::printf("proxima-viewer: presenting on %s (Esc or Ctrl-C quits)\n", device.c_str());
        std::fflush(stdout);
        announced = true;
      }
    }
    vkDeviceWaitIdle(vk.device());
    detach_hud();
    renderer.reset();
  } catch (...) {
    detach_hud();
    vkDestroySurfaceKHR(vk.instance(), surface, nullptr);
    glfwDestroyWindow(window);
    throw;
  }
  vkDestroySurfaceKHR(vk.instance(), surface, nullptr);
  glfwDestroyWindow(window);
  return finish(device);
}

}  // namespace
}  // namespace viewer

int main(int argc, char** argv) {
  using namespace viewer;
  Options options;
  try {
    bool help = false;
    options = parse_options(argc, argv, &help);
    if (help) {
      std::fputs(kUsage, stdout);
      return 0;
    }
  } catch (const UsageError& e) {
    std::fprintf(stderr, "proxima-viewer: %s\n(proxima-viewer --help lists the options)\n",
                 e.message.c_str());
    return 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    Viewer v(options);
    return options.headless ? v.run_headless() : v.run_window();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proxima-viewer: %s\n", e.what());
    return 1;
  }
}
