// The deforming test shape of the deformation benchmarks (proxima_deform_bench,
// proxima_kernel_bench's refit entries): a square sheet, and a travelling wave
// that moves its vertices frame by frame.
#pragma once

#include "mesh/mesh.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace prox::bench {

struct Shape {
  std::string name;
  std::vector<double> positions;  // x y z per vertex
  std::vector<std::uint32_t> indices;

  MeshInput input() const {
    return {positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
            static_cast<std::uint32_t>(indices.size() / 3)};
  }
};

// A square sheet of n x n cells, two triangles each, side 0.2 m, facing +z.
inline Shape sheet(int n) {
  Shape s{"sheet-" + std::to_string(2 * n * n), {}, {}};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.positions.insert(s.positions.end(), {0.2 * i / n, 0.2 * j / n, 0.0});
  const auto row = static_cast<std::uint32_t>(n + 1);
  for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(n); ++j)
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
      const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      s.indices.insert(s.indices.end(), {a, b, d, a, d, c});
    }
  return s;
}

// The wave at frame f of a 60 Hz animation: each vertex moved along `axis`
// by amplitude * sin(2 pi (x / wavelength - f / 60)), x along the first axis.
inline void wave(const Mesh& rest, int frame, int axis, double amplitude, double wavelength,
                 std::vector<double>& out) {
  out.resize(3 * std::size_t{rest.vertex_count()});
  for (std::uint32_t v = 0; v < rest.vertex_count(); ++v) {
    Vec3 p = rest.vertex(v);
    p[axis] += amplitude * std::sin(2.0 * kPi * (p.x / wavelength - frame / 60.0));
    for (int c = 0; c < 3; ++c) out[3 * std::size_t{v} + static_cast<std::size_t>(c)] = p[c];
  }
}

}  // namespace prox::bench
