#include "image_out.h"

#include "common/json_writer.h"

#include <png.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace viewer {

void write_png(const std::string& path, const std::vector<uint8_t>& rgb, uint32_t width, uint32_t height) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error(path + ": cannot write");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    std::fclose(f);
    throw std::runtime_error(path + ": libpng could not start");
  }
  std::vector<png_bytep> rows(height);
  for (uint32_t y = 0; y < height; ++y)
    rows[y] = const_cast<png_bytep>(rgb.data() + std::size_t{3} * width * y);  // libpng only reads them
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    throw std::runtime_error(path + ": writing the PNG failed");
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::fclose(f) != 0) throw std::runtime_error(path + ": cannot write");
}

namespace {

void matrix(prox::JsonWriter& j, const char* key, const glm::mat4& m) {
  j.key(key).begin_array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) j.value(static_cast<double>(m[c][r]));
  j.end_array();
}

}  // namespace

void write_sidecar(const std::string& path, const Sidecar& s) {
  prox::JsonWriter j;
  j.begin_object();
  matrix(j, "view", s.view);
  matrix(j, "proj", s.proj);
  j.key("viewport")
      .begin_array()
      .value(static_cast<long long>(s.width))
      .value(static_cast<long long>(s.height))
      .end_array();
  j.key("background").begin_array();
  for (int k = 0; k < 3; ++k)
    j.value(static_cast<long long>(std::lround(255.0 * static_cast<double>(s.background[k]))));
  j.end_array();
  j.key("contacts").begin_array();
  for (std::size_t i = 0; i < s.frame->contacts.size(); ++i) {
    const proxContact& c = s.frame->contacts[i];
    j.begin_object();
    j.key("point_tool").vec3(c.pointTool);
    j.key("point_other").vec3(c.pointOther);
    j.field("distance", c.distance);
    if (i < s.frame->patches.size())
      j.key("patch_count").value(static_cast<long long>(s.frame->patches[i].count));
    j.end_object();
  }
  j.end_array();
  j.key("polylines").begin_array();
  for (const Polyline& line : s.frame->polylines) {
    j.begin_array();
    for (const glm::dvec3& p : line.points) j.vec3(p);
    if (line.closed && line.points.size() > 2) j.vec3(line.points.front());  // the closing segment, explicit
    j.end_array();
  }
  j.end_array();
  j.key("force").vec3(s.frame->wrench.force);
  j.key("torque").vec3(s.frame->wrench.torque);
  // The tool's drawn pose (a constrained tool's proxy) and its device pose.
  for (const auto& [key, pose] :
       {std::pair<const char*, const proxPose&>{"tool_pose", s.frame->tool_pose},
        std::pair<const char*, const proxPose&>{"device_pose", s.frame->device_pose}}) {
    j.key(key).begin_array();
    for (const double v : {pose.position.x, pose.position.y, pose.position.z, pose.rotation.w,
                           pose.rotation.x, pose.rotation.y, pose.rotation.z})
      j.value(v);
    j.end_array();
  }
  j.field("ghost", s.frame->ghost);
  j.end_object();
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot write");
  const std::string& text = j.str();
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fputc('\n', f) != EOF;
  if (std::fclose(f) != 0 || !ok) throw std::runtime_error(path + ": cannot write");
}

std::string frame_stem(const std::string& dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame-%04d", frame);
  return dir + "/" + name;
}

}  // namespace viewer
