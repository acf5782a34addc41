// Micro-benchmarks of the geometry kernel, and of the haptic loop's contact
// evaluation. Pairs are random unit-size triangles at the distances the
// engine sees at its leaves: close (within a tenth of their size), some
// intersecting. Run:
//   proxima_kernel_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "geometry/predicates.h"
#include "geometry/triangle_distance.h"
#include "geometry/triangle_intersection.h"
#include "geometry/triangle_screen.h"
#include "geometry/visibility.h"
#include "runtime/haptic.h"
#include "snch/snch.h"
#include "waved_sheet.h"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <random>
#include <stdexcept>
#include <vector>

namespace {

using namespace prox;

struct Pair {
  Triangle a, b;
  Vec3 na[3], nb[3];
};

// `gap` scales how far apart the pairs are: 0.1 gives mostly separated
// close pairs, 0 gives mostly intersecting ones.
std::vector<Pair> make_pairs(double gap, std::size_t count = 4096) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  auto vec = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  std::vector<Pair> pairs(count);
  for (Pair& p : pairs) {
    for (Vec3& v : p.a.v) v = vec();
    const Vec3 n = glm::normalize(glm::cross(p.a.v[1] - p.a.v[0], p.a.v[2] - p.a.v[0]));
    // b sits on a's front side, facing it, about `gap` away.
    for (Vec3& v : p.b.v) v = vec() * 0.9 + n * (0.5 + gap * (u(rng) + 0.5) * 2.0);
    for (int i = 0; i < 3; ++i) p.na[i] = n + 0.2 * vec(), p.nb[i] = -n + 0.2 * vec();
  }
  return pairs;
}

// `screen` 1: the kernel as the engine calls it; 0: without its
// single-precision screen (the same answers), side by side.
void BM_TriangleDistance(benchmark::State& state) {
  const std::vector<Pair> pairs = make_pairs(static_cast<double>(state.range(0)) / 100.0);
  const bool screen = state.range(1) != 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ % pairs.size()];
    benchmark::DoNotOptimize(screen ? geometry::triangle_distance(p.a, p.b)
                                    : geometry::triangle_distance_unscreened(p.a, p.b));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TriangleDistance)->ArgsProduct({{0, 10, 100}, {1, 0}})->ArgNames({"gap_percent", "screen"});

// The distance alone (a branch and bound's leaf), with no limit, and the
// full answer within a limit that about half the pairs are past (their
// mean distance at a 10% gap): what a search with a cutoff pays.
void BM_TriangleDistanceValue(benchmark::State& state) {
  const std::vector<Pair> pairs = make_pairs(0.1);
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ % pairs.size()];
    benchmark::DoNotOptimize(state.range(0) != 0 ? geometry::triangle_distance_value(p.a, p.b)
                                                 : geometry::triangle_distance_value_unscreened(p.a, p.b));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TriangleDistanceValue)->Arg(1)->Arg(0)->ArgName("screen");

void BM_TriangleDistanceWithin(benchmark::State& state) {
  const std::vector<Pair> pairs = make_pairs(0.1);
  std::size_t i = 0, within = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ % pairs.size()];
    geometry::TriangleDistance d;
    const bool in = state.range(0) != 0 ? geometry::triangle_distance_within(p.a, p.b, 0.43, d)
                                        : geometry::triangle_distance_within_unscreened(p.a, p.b, 0.43, d);
    within += in ? 1 : 0;
    benchmark::DoNotOptimize(d);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["within"] = static_cast<double>(within) / static_cast<double>(i);
}
BENCHMARK(BM_TriangleDistanceWithin)->Arg(1)->Arg(0)->ArgName("screen");

// The single-precision screen alone (the float path before any exact
// candidate), on the pairs above in the local coordinates the kernel gives
// it, against a limit half of them are past.
void BM_ScreenPair(benchmark::State& state) {
  std::vector<geometry::detail::LocalPair> pairs;
  for (const Pair& p : make_pairs(0.1)) pairs.push_back(geometry::detail::local_pair(p.a, p.b));
  std::size_t i = 0, settled = 0;
  for (auto _ : state) {
    const geometry::detail::LocalPair& l = pairs[i++ % pairs.size()];
    const geometry::detail::Screen s = geometry::detail::screen_pair(l.a, l.b, l.span, 0.43);
    settled += s.verdict != geometry::detail::Screen::Verdict::Unsure ? 1 : 0;
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["settled"] = static_cast<double>(settled) / static_cast<double>(i);
}
BENCHMARK(BM_ScreenPair);

void BM_TrianglesIntersect(benchmark::State& state) {
  const std::vector<Pair> pairs = make_pairs(static_cast<double>(state.range(0)) / 100.0);
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ % pairs.size()];
    benchmark::DoNotOptimize(geometry::triangles_intersect(p.a, p.b));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TrianglesIntersect)->Arg(0)->Arg(10)->ArgName("gap_percent");

void BM_VisibilityPretest(benchmark::State& state) {
  const std::vector<Pair> pairs = make_pairs(0.1);
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ % pairs.size()];
    benchmark::DoNotOptimize(geometry::visibility_pretest(p.a, p.na, p.b, p.nb));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_VisibilityPretest);

// The sound form the searches run: each vertex's spread (here 10 degrees)
// as the cosine and sine the hierarchy keeps, no trigonometry per test.
void BM_VisibilityPretestSpread(benchmark::State& state) {
  const std::vector<Pair> pairs = make_pairs(0.1);
  const geometry::Spread s = geometry::Spread::of_angle(10.0 * 3.14159265358979323846 / 180.0);
  const geometry::Spread spreads[3] = {s, s, s};
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ % pairs.size()];
    benchmark::DoNotOptimize(geometry::visibility_pretest(p.a, p.na, spreads, p.b, p.nb, spreads));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_VisibilityPretestSpread);

void BM_Orient3d(benchmark::State& state) {
  const std::vector<Pair> pairs = make_pairs(0.1);
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ % pairs.size()];
    benchmark::DoNotOptimize(geometry::orient3d(p.a.v[0], p.a.v[1], p.a.v[2], p.b.v[0]));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Orient3d);

// The exact path of orient3d: coplanar points, where the filter cannot decide.
void BM_Orient3dExactPath(benchmark::State& state) {
  const Vec3 a(0.1, 0.2, 0.3), b(1.7, 0.2, 0.3), c(0.1, 3.1, 0.3);
  Vec3 d(0.5, 0.5, 0.3);
  for (auto _ : state) {
    benchmark::DoNotOptimize(d);
    benchmark::DoNotOptimize(geometry::orient3d(a, b, c, d));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Orient3dExactPath);

// The haptic loop's evaluation of a tool's contacts at the tick's pose (the
// threads hand it up to 1,024), without (0) and with (1) the closest
// distance it tells the device.
void BM_HapticEvaluate(benchmark::State& state) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.05, 0.05), gap(0.0005, 0.005);
  runtime::ContactSnapshot s;
  for (int i = 0; i < 1024; ++i) {
    const Vec3 p(u(rng), u(rng), 0.0);
    const double d = gap(rng);
    s.contacts.push_back({p + Vec3(0.0, 0.0, d), p, Vec3(0.0, 0.0, 1.0), d});
  }
  s.sequence = 1;
  const ForceSettings force = hard_force_settings();
  const Pose pose{glm::dmat3(1.0), Vec3(0.0, 0.0, 1e-5)};
  const bool closest = state.range(0) != 0;
  double least = 0.0;
  for (auto _ : state) {
    const Wrench w = runtime::evaluate_contacts(force, s, pose, Vec3(0.0), closest ? &least : nullptr);
    benchmark::DoNotOptimize(w);
    benchmark::DoNotOptimize(least);
  }
  state.SetItemsProcessed(state.iterations() * 1024);
}
BENCHMARK(BM_HapticEvaluate)->Arg(0)->Arg(1)->ArgName("closest");

// A sheet of 2 n^2 triangles under the travelling wave of
// proxima_deform_bench, one frame a step: moving the vertices
// (Mesh::set_vertices, which recomputes the normals) and refitting its
// hierarchy (Snch::refit), each timed on its own (docs/dynamic-scenes.md has
// the whole frame's figures).
struct WavedSheet {
  Mesh mesh;
  std::vector<std::vector<double>> frames;
  explicit WavedSheet(int n) {
    Status status;
    mesh = Mesh::build(bench::sheet(n).input(), status);
    if (!status) throw std::runtime_error(status.message());
    frames.resize(8);
    for (int f = 0; f < 8; ++f) bench::wave(mesh, f, 2, 0.005, 0.1, frames[static_cast<std::size_t>(f)]);
  }
};

void BM_MeshSetVertices(benchmark::State& state) {
  WavedSheet sheet(static_cast<int>(state.range(0)));
  std::size_t f = 0;
  for (auto _ : state) {
    const Status s = sheet.mesh.set_vertices(sheet.frames[f++ % 8].data(), sheet.mesh.vertex_count());
    benchmark::DoNotOptimize(s);
  }
  state.counters["triangles"] = sheet.mesh.triangle_count();
}
BENCHMARK(BM_MeshSetVertices)->Arg(71)->Arg(173)->ArgName("cells")->Unit(benchmark::kMillisecond);

void BM_SnchRefit(benchmark::State& state) {
  WavedSheet sheet(static_cast<int>(state.range(0)));
  Snch snch(sheet.mesh);
  // Two frames' shapes ready, refitted to in turn: the loop times the refit
  // alone, on data as warm as after the mesh's own set_vertices (eight
  // shapes would not stay in the cache together).
  std::vector<Mesh> shapes;
  for (const auto& xyz : {sheet.frames[1], sheet.frames[2]}) {
    shapes.push_back(sheet.mesh);
    (void)shapes.back().set_vertices(xyz.data(), sheet.mesh.vertex_count());
  }
  std::size_t f = 0;
  for (auto _ : state) {
    snch.refit(shapes[f++ % shapes.size()]);
    benchmark::DoNotOptimize(snch.root().radius);
  }
  state.counters["triangles"] = sheet.mesh.triangle_count();
}
BENCHMARK(BM_SnchRefit)->Arg(71)->Arg(173)->ArgName("cells")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
