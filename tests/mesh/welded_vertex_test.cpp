// Mesh::welded_vertex: which welded vertex each input vertex became (the map
// the glTF rig uses to carry its unwelded vertices to the mesh).
#include "mesh/mesh.h"

#include <gtest/gtest.h>

#include <vector>

namespace prox {
namespace {

// Two triangles sharing an edge through duplicated positions (a UV seam),
// an unreferenced vertex, and a triangle dropped because it repeats a
// position: input 0..2, 3..5 (3 = 2's position, 4 = 1's), 6 unused, 7..9
// all at 0's position.
TEST(WeldedVertex, MapsEveryInputVertex) {
  const std::vector<double> p = {0, 0, 0, 1, 0, 0, 0, 1, 0,  //
                                 0, 1, 0, 1, 0, 0, 1, 1, 0,  //
                                 5, 5, 5,                    //
                                 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 4, 5, 7, 8, 9};
  Status status;
  const Mesh mesh = Mesh::build({p.data(), 10, idx.data(), 3}, status);
  ASSERT_TRUE(status.is_ok()) << status.message();
  ASSERT_EQ(mesh.vertex_count(), 4u);
  ASSERT_EQ(mesh.input_vertex_count(), 10u);
  // Welded in order of first appearance: 0, 1, 2, then 5's (1, 1, 0).
  const std::uint32_t want[10] = {0, 1, 2, 2, 1, 3, kNoVertex, 0, 0, 0};
  for (std::uint32_t v = 0; v < 10; ++v) {
    EXPECT_EQ(mesh.welded_vertex(v), want[v]) << "input vertex " << v;
    if (want[v] == kNoVertex) continue;
    EXPECT_EQ(mesh.vertex(want[v]), Vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2])) << "input vertex " << v;
  }
}

}  // namespace
}  // namespace prox
