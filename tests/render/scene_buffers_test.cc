// CPU side of the GPU buffers: faces split with their own normals along edges, and the
// back-to-front order.
#include "render/scene_buffers.h"

#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "tests/render/test_meshes.h"

namespace pcsg::render {
namespace {

// Normals are stored as floats: single precision round-off on unit vectors.
constexpr double kFloatTolerance = 1e-6;

TEST(SceneBuffersTest, EdgeVerticesGetEachFacesOwnNormal) {
  const auto lens = testing::lens("B", "f1", "f2", "e1", 3.0, 1.6, 8, 16);
  const ObjectGeometry g = prepare_object_geometry(lens.solid, lens.mesh, Object::B);
  EXPECT_EQ(g.surface_indices.size(), 3 * lens.mesh.triangles.size());
  // the rim (z = 0) appears once per face, each copy with its face's sphere normal
  int rim_copies = 0;
  for (const SurfaceVertex& v : g.surface_vertices) {
    EXPECT_EQ(v.object, 1);
    if (std::abs(v.position[2]) > 1e-6) continue;
    ++rim_copies;
    const Eigen::Vector3d p(v.position[0], v.position[1], v.position[2]);
    const Eigen::Vector3d n(v.normal[0], v.normal[1], v.normal[2]);
    const double h = v.element == 0 ? 1.6 : -1.6;  // face 0 is the cap of the lower sphere
    EXPECT_NEAR((n - (p + Eigen::Vector3d(0, 0, h)).normalized()).norm(), 0, kFloatTolerance);
  }
  EXPECT_EQ(rim_copies, 2 * 16);
  // one closed polyline of 17 points: 16 segments, 32 vertices
  EXPECT_EQ(g.edge_vertices.size(), 32u);
}

TEST(SceneBuffersTest, InconsistentMeshThrowsNamingTheSolid) {
  auto lens = testing::lens("B", "f1", "f2", "e1", 3.0, 1.6, 8, 16);
  lens.mesh.triangle_face[5] = 7;
  try {
    prepare_object_geometry(lens.solid, lens.mesh, Object::B);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("solid 'B'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("face 7"), std::string::npos) << e.what();
  }
}

TEST(SceneBuffersTest, BackToFrontOrdersByDepthThenIndex) {
  const std::vector<Eigen::Vector3f> points = {{0, 0, 1}, {0, 0, -2}, {0, 0, 0}, {5, 0, 0}};
  // eye on +z looking down: farthest = lowest z; points 2 and 3 tie, index decides
  const auto order = back_to_front(points, Eigen::Vector3f(0, 0, 10), Eigen::Vector3f(0, 0, 1));
  EXPECT_EQ(order, (std::vector<std::uint32_t>{1, 2, 3, 0}));
}

}  // namespace
}  // namespace pcsg::render
