// Example 1's SceneGeometry end to end from its scene file. Under -fsanitize=address,undefined
// this is the reported "bad free when SceneGeometry is destroyed" scenario: building, copying,
// moving and destroying it must be clean, and every per-vertex and per-corner array of the
// meshes must match the vertex and triangle counts (a mismatch is what a stale or mixed build,
// with SolidMesh laid out differently in two translation units, would show first).
#include "engine/geometry/scene_geometry.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "engine/scene/scene.h"

namespace pcsg {
namespace {

void expect_consistent(const SolidMesh& mesh, const Solid& solid, const char* what) {
  SCOPED_TRACE(what);
  const std::size_t nv = mesh.positions.size(), nt = mesh.triangles.size();
  ASSERT_GT(nt, 0u);
  EXPECT_EQ(mesh.normals.size(), nv);
  EXPECT_EQ(mesh.vertex_edge.size(), nv);
  EXPECT_EQ(mesh.vertex_vertex.size(), nv);
  EXPECT_EQ(mesh.triangle_face.size(), nt);
  EXPECT_EQ(mesh.corner_normals.size(), 3 * nt);
  EXPECT_EQ(mesh.edge_polylines.size(), solid.edges.size());
  for (const auto& T : mesh.triangles)
    for (int q = 0; q < 3; ++q) {
      ASSERT_GE(T[q], 0);
      ASSERT_LT(static_cast<std::size_t>(T[q]), nv);
    }
}

TEST(SceneGeometry, Example1BuildsCopiesAndDestroysCleanly) {
  SceneGeometry g =
      build_scene_geometry(load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/example1.yaml"));
  ASSERT_EQ(g.A.faces.size(), 1u);
  ASSERT_EQ(g.B.faces.size(), 3u);
  expect_consistent(g.mesh_A, g.A, "A");
  expect_consistent(g.mesh_B, g.B, "B");
  // a copy and a move leave two independent owners; all three are destroyed at scope exit
  const SceneGeometry copy = g;
  const SceneGeometry moved = std::move(g);
  EXPECT_EQ(copy.mesh_B.vertex_vertex, moved.mesh_B.vertex_vertex);
  EXPECT_EQ(copy.mesh_A.positions.size(), moved.mesh_A.positions.size());
}

}  // namespace
}  // namespace pcsg
