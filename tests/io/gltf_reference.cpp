#include "gltf_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <stdexcept>

namespace gltf_reference {
namespace {

using M = std::array<double, 16>;  // column-major: element (row r, column c) at 4 c + r
using json = nlohmann::json;

std::uint32_t u32(const unsigned char* p) {
  return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
         std::uint32_t{p[3]} << 24;
}

std::vector<unsigned char> base64(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned bits = 0;
  int count = 0;
  for (const char ch : text) {
    int v;
    if (ch >= 'A' && ch <= 'Z')
      v = ch - 'A';
    else if (ch >= 'a' && ch <= 'z')
      v = ch - 'a' + 26;
    else if (ch >= '0' && ch <= '9')
      v = ch - '0' + 52;
    else if (ch == '+')
      v = 62;
    else if (ch == '/')
      v = 63;
    else
      continue;  // '=' padding
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<unsigned char>((bits >> count) & 0xFF));
    }
  }
  return out;
}

M identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

M multiply(const M& a, const M& b) {
  M r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a[4 * k + row] * b[4 * c + k];
      r[4 * c + row] = s;
    }
  return r;
}

std::array<double, 3> apply(const M& m, const std::array<double, 3>& p) {
  std::array<double, 3> r{};
  for (int row = 0; row < 3; ++row)
    r[row] = m[row] * p[0] + m[4 + row] * p[1] + m[8 + row] * p[2] + m[12 + row];
  return r;
}

// Translation t, rotation q (x, y, z, w), scale s: T R S.
M compose(const std::array<double, 3>& t, std::array<double, 4> q, const std::array<double, 3>& s) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& x : q) x /= n;
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  // Rotation matrix rows (the textbook form), then columns scaled.
  const double r[3][3] = {{1 - 2 * y * y - 2 * z * z, 2 * x * y - 2 * z * w, 2 * x * z + 2 * y * w},
                          {2 * x * y + 2 * z * w, 1 - 2 * x * x - 2 * z * z, 2 * y * z - 2 * x * w},
                          {2 * x * z - 2 * y * w, 2 * y * z + 2 * x * w, 1 - 2 * x * x - 2 * y * y}};
  M m = identity();
  for (int row = 0; row < 3; ++row)
    for (int c = 0; c < 3; ++c) m[4 * c + row] = r[row][c] * s[c];
  for (int row = 0; row < 3; ++row) m[12 + row] = t[row];
  return m;
}

std::vector<double> numbers(const json& j, std::vector<double> fallback) {
  if (!j.is_array()) return fallback;
  std::vector<double> v;
  for (const auto& x : j) v.push_back(x.get<double>());
  return v;
}

struct Local {
  std::array<double, 3> t{0, 0, 0}, s{1, 1, 1};
  std::array<double, 4> r{0, 0, 0, 1};
  bool matrix = false;
  M m = identity();
  std::vector<double> weights;
  bool has_weights = false;
};

// The value of sampler `s` at `time`: `width` numbers.
std::vector<double> sample_at(const Document& doc, const json& s, int width, bool rotation, double time) {
  const std::vector<double> in = accessor(doc, s["input"].get<int>());
  const std::vector<double> out = accessor(doc, s["output"].get<int>());
  const std::string mode = s.value("interpolation", std::string("LINEAR"));
  const bool cubic = mode == "CUBICSPLINE";
  const std::size_t group = static_cast<std::size_t>(width) * (cubic ? 3 : 1);
  const auto value = [&](std::size_t k, int part) {  // part: 0 in-tangent, 1 value, 2 out-tangent
    const std::size_t base = k * group + (cubic ? static_cast<std::size_t>(part * width) : 0);
    return std::vector<double>(out.begin() + static_cast<long>(base),
                               out.begin() + static_cast<long>(base + width));
  };
  std::vector<double> r;
  const std::size_t n = in.size();
  if (time <= in[0]) {
    r = value(0, 1);
  } else if (time >= in[n - 1]) {
    r = value(n - 1, 1);
  } else {
    std::size_t k = 0;
    while (!(in[k + 1] > time)) ++k;
    const double dt = in[k + 1] - in[k];
    const double u = (time - in[k]) / dt;
    if (mode == "STEP") {
      r = value(k, 1);
    } else if (!cubic) {
      const std::vector<double> a = value(k, 1), b = value(k + 1, 1);
      if (rotation) {
        const auto q = slerp({a[0], a[1], a[2], a[3]}, {b[0], b[1], b[2], b[3]}, u);
        r.assign(q.begin(), q.end());
      } else {
        for (int c = 0; c < width; ++c)
          r.push_back((1 - u) * a[static_cast<std::size_t>(c)] + u * b[static_cast<std::size_t>(c)]);
      }
    } else {
      const std::vector<double> p0 = value(k, 1), m0 = value(k, 2), p1 = value(k + 1, 1),
                                m1 = value(k + 1, 0);
      for (int c = 0; c < width; ++c) {
        const std::size_t i = static_cast<std::size_t>(c);
        r.push_back((2 * u * u * u - 3 * u * u + 1) * p0[i] + (u * u * u - 2 * u * u + u) * dt * m0[i] +
                    (-2 * u * u * u + 3 * u * u) * p1[i] + (u * u * u - u * u) * dt * m1[i]);
      }
    }
  }
  if (rotation) {
    const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    for (double& x : r) x /= len;
  }
  return r;
}

}  // namespace

std::array<double, 4> slerp(const std::array<double, 4>& a, const std::array<double, 4>& b_in, double t) {
  std::array<double, 4> b = b_in;
  double cosine = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  if (cosine < 0) {
    cosine = -cosine;
    for (double& x : b) x = -x;
  }
  std::array<double, 4> r{};
  if (cosine > 1 - 1e-6) {
    double len = 0;
    for (int i = 0; i < 4; ++i)
      r[static_cast<std::size_t>(i)] =
          a[static_cast<std::size_t>(i)] * (1 - t) + b[static_cast<std::size_t>(i)] * t;
    for (double x : r) len += x * x;
    for (double& x : r) x /= std::sqrt(len);
    return r;
  }
  const double angle = std::acos(cosine);
  const double wa = std::sin((1 - t) * angle) / std::sin(angle), wb = std::sin(t * angle) / std::sin(angle);
  for (std::size_t i = 0; i < 4; ++i) r[i] = wa * a[i] + wb * b[i];
  return r;
}

Document parse(const std::vector<unsigned char>& bytes) {
  Document doc;
  std::vector<unsigned char> bin;
  if (bytes.size() >= 20 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
    const std::uint32_t json_length = u32(&bytes[12]);
    doc.json = json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
    const std::size_t next = 20 + json_length;
    if (next + 8 <= bytes.size()) {
      const std::uint32_t bin_length = u32(&bytes[next]);
      bin.assign(bytes.begin() + static_cast<long>(next + 8),
                 bytes.begin() + static_cast<long>(next + 8 + bin_length));
    }
  } else {
    doc.json = json::parse(bytes.begin(), bytes.end());
  }
  for (const auto& buffer : doc.json["buffers"]) {
    if (!buffer.contains("uri")) {
      doc.buffers.push_back(bin);
      continue;
    }
    const std::string uri = buffer["uri"].get<std::string>();
    const std::size_t comma = uri.find(',');
    if (uri.rfind("data:", 0) != 0 || comma == std::string::npos)
      throw std::runtime_error("only data: URIs and the GLB chunk are read: " + uri.substr(0, 40));
    doc.buffers.push_back(base64(uri.substr(comma + 1)));
  }
  return doc;
}

Document open(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot open " + path);
  return parse(std::vector<unsigned char>(std::istreambuf_iterator<char>(file), {}));
}

std::vector<double> accessor(const Document& doc, int index, int* components_out) {
  const json& a = doc.json["accessors"][static_cast<std::size_t>(index)];
  if (a.contains("sparse")) throw std::runtime_error("sparse accessors are not read here");
  static const std::map<std::string, int> kComponents = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT4", 16}};
  const int components = kComponents.at(a["type"].get<std::string>());
  if (components_out) *components_out = components;
  const int type = a["componentType"].get<int>();
  const bool normalized = a.value("normalized", false);
  const std::size_t size = type == 5126 || type == 5125 ? 4 : type == 5122 || type == 5123 ? 2 : 1;
  const std::size_t count = a["count"].get<std::size_t>();
  const json& view = doc.json["bufferViews"][a["bufferView"].get<std::size_t>()];
  const std::vector<unsigned char>& buffer = doc.buffers.at(view["buffer"].get<std::size_t>());
  const std::size_t stride = view.value("byteStride", std::size_t{0}) != 0
                                 ? view["byteStride"].get<std::size_t>()
                                 : size * static_cast<std::size_t>(components);
  const unsigned char* base =
      buffer.data() + view.value("byteOffset", std::size_t{0}) + a.value("byteOffset", std::size_t{0});
  std::vector<double> out;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t c = 0; c < static_cast<std::size_t>(components); ++c) {
      const unsigned char* p = base + i * stride + c * size;
      double v = 0;
      switch (type) {
        case 5126: {
          float f;
          const std::uint32_t bits = u32(p);
          std::memcpy(&f, &bits, 4);
          v = f;
          break;
        }
        case 5125:
          v = u32(p);
          break;
        case 5123:
          v = p[0] + 256.0 * p[1];
          if (normalized) v /= 65535.0;
          break;
        case 5122:
          v = static_cast<std::int16_t>(p[0] | p[1] << 8);
          if (normalized) v = std::max(v / 32767.0, -1.0);
          break;
        case 5121:
          v = p[0];
          if (normalized) v /= 255.0;
          break;
        case 5120:
          v = static_cast<std::int8_t>(p[0]);
          if (normalized) v = std::max(v / 127.0, -1.0);
          break;
        default:
          throw std::runtime_error("component type " + std::to_string(type));
      }
      out.push_back(v);
    }
  return out;
}

std::vector<std::array<double, 9>> triangles(const Document& doc, int animation, double seconds) {
  const json& nodes = doc.json["nodes"];
  const std::size_t node_count = nodes.size();
  std::vector<Local> local(node_count);
  std::vector<int> parent(node_count, -1);
  for (std::size_t n = 0; n < node_count; ++n) {
    const json& node = nodes[n];
    Local& l = local[n];
    if (node.contains("matrix")) {
      l.matrix = true;
      const std::vector<double> m = numbers(node["matrix"], {});
      std::copy(m.begin(), m.end(), l.m.begin());
    }
    const std::vector<double> t = numbers(node.value("translation", json()), {0, 0, 0});
    const std::vector<double> r = numbers(node.value("rotation", json()), {0, 0, 0, 1});
    const std::vector<double> s = numbers(node.value("scale", json()), {1, 1, 1});
    l.t = {t[0], t[1], t[2]};
    l.r = {r[0], r[1], r[2], r[3]};
    l.s = {s[0], s[1], s[2]};
    if (node.contains("weights")) {
      l.weights = numbers(node["weights"], {});
      l.has_weights = true;
    }
    for (const auto& child : node.value("children", json::array()))
      parent[child.get<std::size_t>()] = static_cast<int>(n);
  }
  if (animation >= 0) {
    const json& a = doc.json["animations"][static_cast<std::size_t>(animation)];
    for (const auto& channel : a["channels"]) {
      const std::size_t n = channel["target"]["node"].get<std::size_t>();
      const std::string path = channel["target"]["path"].get<std::string>();
      const json& s = a["samplers"][channel["sampler"].get<std::size_t>()];
      Local& l = local[n];
      if (path == "translation") {
        const auto v = sample_at(doc, s, 3, false, seconds);
        l.t = {v[0], v[1], v[2]};
      } else if (path == "scale") {
        const auto v = sample_at(doc, s, 3, false, seconds);
        l.s = {v[0], v[1], v[2]};
      } else if (path == "rotation") {
        const auto v = sample_at(doc, s, 4, true, seconds);
        l.r = {v[0], v[1], v[2], v[3]};
      } else if (path == "weights") {
        const json& mesh = doc.json["meshes"][nodes[n]["mesh"].get<std::size_t>()];
        const int targets = static_cast<int>(mesh["primitives"][0]["targets"].size());
        l.weights = sample_at(doc, s, targets, false, seconds);
        l.has_weights = true;
      }
    }
  }
  // World matrices by walking up to the root, every time (simple, not fast).
  const std::function<M(std::size_t)> world = [&](std::size_t n) -> M {
    const Local& l = local[n];
    const M m = l.matrix ? l.m : compose(l.t, l.r, l.s);
    return parent[n] < 0 ? m : multiply(world(static_cast<std::size_t>(parent[n])), m);
  };

  std::vector<std::array<double, 9>> result;
  const std::function<void(std::size_t)> visit = [&](std::size_t n) {
    const json& node = nodes[n];
    if (node.contains("mesh")) {
      const json& mesh = doc.json["meshes"][node["mesh"].get<std::size_t>()];
      const M node_world = world(n);
      std::vector<M> joint_matrices;
      if (node.contains("skin")) {
        const json& skin = doc.json["skins"][node["skin"].get<std::size_t>()];
        std::vector<double> ibm;
        if (skin.contains("inverseBindMatrices")) ibm = accessor(doc, skin["inverseBindMatrices"].get<int>());
        std::size_t j = 0;
        for (const auto& joint : skin["joints"]) {
          M inverse = identity();
          if (!ibm.empty())
            std::copy(ibm.begin() + static_cast<long>(16 * j), ibm.begin() + static_cast<long>(16 * j + 16),
                      inverse.begin());
          joint_matrices.push_back(multiply(world(joint.get<std::size_t>()), inverse));
          ++j;
        }
      }
      for (const auto& primitive : mesh["primitives"]) {
        const json& attributes = primitive["attributes"];
        const std::vector<double> positions = accessor(doc, attributes["POSITION"].get<int>());
        const std::size_t count = positions.size() / 3;
        std::vector<double> morphed = positions;
        if (primitive.contains("targets")) {
          std::vector<double> weights =
              local[n].has_weights ? local[n].weights : numbers(mesh.value("weights", json()), {});
          weights.resize(primitive["targets"].size(), 0.0);
          std::size_t t = 0;
          for (const auto& target : primitive["targets"]) {
            if (target.contains("POSITION")) {
              const std::vector<double> delta = accessor(doc, target["POSITION"].get<int>());
              for (std::size_t i = 0; i < morphed.size(); ++i) morphed[i] += weights[t] * delta[i];
            }
            ++t;
          }
        }
        std::vector<std::array<double, 3>> placed(count);
        if (joint_matrices.empty()) {
          for (std::size_t v = 0; v < count; ++v)
            placed[v] = apply(node_world, {morphed[3 * v], morphed[3 * v + 1], morphed[3 * v + 2]});
        } else {
          std::vector<std::vector<double>> joints, weights;
          for (int set = 0; attributes.contains("JOINTS_" + std::to_string(set)); ++set) {
            joints.push_back(accessor(doc, attributes["JOINTS_" + std::to_string(set)].get<int>()));
            weights.push_back(accessor(doc, attributes["WEIGHTS_" + std::to_string(set)].get<int>()));
          }
          for (std::size_t v = 0; v < count; ++v) {
            double sum = 0;
            for (const auto& w : weights) sum += w[4 * v] + w[4 * v + 1] + w[4 * v + 2] + w[4 * v + 3];
            std::array<double, 3> p{0, 0, 0};
            for (std::size_t set = 0; set < joints.size(); ++set)
              for (std::size_t k = 0; k < 4; ++k) {
                const double w = weights[set][4 * v + k] / sum;
                if (w == 0) continue;
                const auto q = apply(joint_matrices[static_cast<std::size_t>(joints[set][4 * v + k])],
                                     {morphed[3 * v], morphed[3 * v + 1], morphed[3 * v + 2]});
                for (int c = 0; c < 3; ++c)
                  p[static_cast<std::size_t>(c)] += w * q[static_cast<std::size_t>(c)];
              }
            placed[v] = p;
          }
        }
        const std::vector<double> indices = accessor(doc, primitive["indices"].get<int>());
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
          std::array<double, 9> tri{};
          for (std::size_t k = 0; k < 3; ++k)
            for (std::size_t c = 0; c < 3; ++c)
              tri[3 * k + c] = placed[static_cast<std::size_t>(indices[i + k])][c];
          result.push_back(tri);
        }
      }
    }
    for (const auto& child : node.value("children", json::array())) visit(child.get<std::size_t>());
  };
  const json& scenes = doc.json["scenes"];
  const std::size_t scene = doc.json.value("scene", std::size_t{0});
  for (const auto& root : scenes[scene]["nodes"]) visit(root.get<std::size_t>());
  return result;
}

}  // namespace gltf_reference
