// proxima_coal_peer: Coal (the PyPI wheel's C++ library) as a peer of
// proxima_bench, in a process of its own. Coal's wheel brings its own octomap
// (and Boost), which cannot share a process with Debian's FCL and the octomap
// it was built against; so the bench starts this executable and asks it over
// pipes (coal_wire.h) to build meshes and time collide() with a security
// margin, which reports every triangle pair closer than the margin, the only
// peer output comparable to an LMD set. Timing is taken here, around Coal's
// call alone, so the pipe costs nothing in the figures.
#include "coal_wire.h"

#include <coal/BVH/BVH_model.h>
#include <coal/collision.h>
#include <coal/config.hh>

#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace wire = prox::bench::wire;
using Clock = std::chrono::steady_clock;
using Bvh = coal::BVHModel<coal::OBBRSS>;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

bool build(int in, int out, std::vector<std::shared_ptr<Bvh>>& meshes) {
  std::uint32_t reps = 0, nv = 0, nt = 0;
  std::vector<double> xyz;
  std::vector<std::uint32_t> abc;
  if (!wire::get(in, reps) || !wire::get(in, nv) || !wire::get(in, nt) ||
      !wire::get_vector(in, xyz, 3 * nv) || !wire::get_vector(in, abc, 3 * nt))
    return false;
  std::vector<coal::Vec3s> points(nv);
  for (std::uint32_t v = 0; v < nv; ++v) points[v] = coal::Vec3s(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
  std::vector<coal::Triangle> triangles(nt);
  for (std::uint32_t t = 0; t < nt; ++t)
    triangles[t] = coal::Triangle(abc[3 * t], abc[3 * t + 1], abc[3 * t + 2]);
  std::vector<double> seconds;
  std::shared_ptr<Bvh> bvh;
  for (std::uint32_t r = 0; r < reps; ++r) {
    const auto start = Clock::now();
    bvh = std::make_shared<Bvh>();
    bvh->beginModel(nt, nv);
    bvh->addSubModel(points, triangles);
    bvh->endModel();
    seconds.push_back(seconds_since(start));
  }
  meshes.push_back(bvh);
  return wire::put(out, static_cast<std::uint32_t>(meshes.size() - 1)) && wire::put_vector(out, seconds);
}

bool collide(int in, int out, const std::vector<std::shared_ptr<Bvh>>& meshes) {
  std::uint32_t a = 0, b = 0;
  double margin = 0.0, rotation[9], translation[3];
  if (!wire::get(in, a) || !wire::get(in, b) || !wire::get(in, margin) || !wire::get(in, rotation) ||
      !wire::get(in, translation) || a >= meshes.size() || b >= meshes.size() || !meshes[a] || !meshes[b])
    return false;
  coal::Matrix3s r;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) r(row, col) = rotation[3 * col + row];
  const coal::Transform3s ta = coal::Transform3s::Identity();
  const coal::Transform3s tb(r, coal::Vec3s(translation[0], translation[1], translation[2]));
  // No contact details (points, normals, depths) are asked for: only the
  // pairs, which is the least Coal can be asked to do for this answer.
  coal::CollisionRequest request(coal::NO_REQUEST, std::numeric_limits<std::size_t>::max());
  request.security_margin = margin;
  coal::CollisionResult result;
  const auto start = Clock::now();
  coal::collide(meshes[a].get(), ta, meshes[b].get(), tb, request, result);
  const double seconds = seconds_since(start);
  return wire::put(out, seconds) && wire::put(out, static_cast<std::uint64_t>(result.numContacts())) &&
         wire::put(out, static_cast<double>(result.distance_lower_bound));
}

}  // namespace

int main(int argc, char**) {
  if (argc > 1) {
    std::fprintf(stderr,
                 "proxima_coal_peer: started by proxima_bench, talks over its standard input and output\n");
    return 2;
  }
  const int in = 0, out = 1;
  std::vector<std::shared_ptr<Bvh>> meshes;
  for (;;) {
    char code = 0;
    if (!wire::get(in, code)) return 0;  // the bench is done
    bool ok = false;
    if (code == 'V') {
      const std::string version = COAL_VERSION;
      ok = wire::put(out, static_cast<std::uint32_t>(version.size())) &&
           wire::write_all(out, version.data(), version.size());
    } else if (code == 'M') {
      ok = build(in, out, meshes);
    } else if (code == 'C') {
      ok = collide(in, out, meshes);
    }
    if (!ok) {
      std::fprintf(stderr, "proxima_coal_peer: bad or truncated request '%c'\n", code);
      return 1;
    }
  }
}
