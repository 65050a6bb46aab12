// MeshIndex (contact_context.h): the per-face vertex lists that pair_local_minima starts from
// must be exactly the vertices of each face's triangles, ascending, as the scan of every
// triangle they replace gave them (the starts' order, and so the solves, depend on it).
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "engine/contact/contact_context.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"

namespace pcsg {
namespace {

void expect_face_vertices(const Solid& solid, const SolidMesh& mesh, const MeshIndex& index,
                          const std::string& what) {
  ASSERT_EQ(index.face_vertices.size(), solid.faces.size()) << what;
  std::set<int> listed_anywhere;
  for (size_t f = 0; f < solid.faces.size(); ++f) {
    std::set<int> want;
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
      if (mesh.triangle_face[t] == static_cast<int>(f))
        for (int k = 0; k < 3; ++k) want.insert(mesh.triangles[t][k]);
    const std::vector<int>& got = index.face_vertices[f];
    EXPECT_FALSE(got.empty()) << what << " face " << f;
    EXPECT_EQ(got, std::vector<int>(want.begin(), want.end())) << what << " face " << f;
    listed_anywhere.insert(got.begin(), got.end());
  }
  // every vertex of a triangle belongs to some face's list
  for (const Eigen::Vector3i& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(listed_anywhere.count(tri[k])) << what;
}

TEST(MeshIndex, FaceVerticesAreEachFacesTriangleVerticesAscending) {
  // faces meeting at edges (Example 1's dish) and at vertices (the three-sphere lens)
  for (const std::string name : {"example1", "example2", "three_spheres"}) {
    const SceneGeometry scene = build_scene_geometry(
        load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/" + name + ".yaml"));
    const ContactContext ctx(scene);
    expect_face_vertices(scene.A, scene.mesh_A, ctx.index_A(), name + " A");
    expect_face_vertices(scene.B, scene.mesh_B, ctx.index_B(), name + " B");
  }
}

}  // namespace
}  // namespace pcsg
