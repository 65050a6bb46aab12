// Valid scene files: the paper's two examples and the optional parts of the format.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "engine/scene/scene.h"

namespace pcsg {
namespace {

const std::string kScenes = std::string(PCSG_SOURCE_DIR) + "/scenes/";
// Exact arithmetic on short decimals: a few ulps of values of size ~100.
constexpr double kExact = 1e-12;
// The paper prints the dish's coefficients to 7 digits, so its quoted surface points satisfy
// the equation to ~1e-5 relative only.
constexpr double kPaperDigits = 1e-4;

const FaceSpec& face(const ObjectSpec& o, const std::string& name) {
  for (const FaceSpec& f : o.faces)
    if (f.name == name) return f;
  throw std::runtime_error("no face " + name + " in object " + o.name);
}

TEST(SceneLoader, ExampleOneLoads) {
  const SceneSpec s = load_scene_file(kScenes + "example1.yaml");
  EXPECT_EQ(s.name, "Example 1: ellipsoid and bowl-topped body (paper Fig. 5)");
  EXPECT_EQ(s.path, kScenes + "example1.yaml");
  EXPECT_EQ(s.A.name, "A");
  EXPECT_EQ(s.B.name, "B");
  ASSERT_EQ(s.A.faces.size(), 1u);
  ASSERT_EQ(s.B.faces.size(), 3u);
  EXPECT_EQ(s.B.faces[0].name, "f1");  // file order is kept
  EXPECT_EQ(s.B.faces[2].name, "f3");
  EXPECT_TRUE(s.auto_seeds);
  EXPECT_TRUE(s.seeds.empty());

  // the ellipsoid's semi-axes 1, 1.5, 2.5; inside is g <= 0
  const Polynomial& gA = face(s.A, "fA").g;
  EXPECT_NEAR(gA.value({1, 0, 0}), 0, kExact);
  EXPECT_NEAR(gA.value({0, -1.5, 0}), 0, kExact);
  EXPECT_NEAR(gA.value({0, 0, 2.5}), 0, kExact);
  EXPECT_LT(gA.value({0, 0, 0}), 0);

  // B: the dish's lowest point, the sphere band, the convex bottom
  const Polynomial& g1 = face(s.B, "f1").g;
  EXPECT_NEAR(g1.value({0, 0, -1.56495}), 0, kPaperDigits * 15.75982);
  EXPECT_LT(g1.value({0, 0, -3}), 0);
  const Polynomial& g2 = face(s.B, "f2").g;
  EXPECT_NEAR(g2.value({0, 4, 0}), 0, kExact);
  EXPECT_NEAR(g2.value({2.4, 0, -3.2}), 0, kExact);
  const Polynomial& g3 = face(s.B, "f3").g;
  EXPECT_NEAR(g3.value({0, 0, -4}), 0, kExact);
  EXPECT_NEAR(g3.value({4, 0, 0}), 0, kExact);
  EXPECT_LT(g3.value({0, 0, 0}), 0);

  ASSERT_EQ(s.B.edges.size(), 2u);
  EXPECT_EQ(s.B.edges[0].name, "e1");
  EXPECT_EQ(s.B.edges[0].face1, "f1");
  EXPECT_EQ(s.B.edges[0].face2, "f2");
  EXPECT_EQ(s.B.edges[1].face1, "f2");
  EXPECT_EQ(s.B.edges[1].face2, "f3");
  EXPECT_TRUE(s.B.vertices.empty());
}

TEST(SceneLoader, LocationsPointIntoTheFile) {
  const SceneSpec s = load_scene_file(kScenes + "example1.yaml");
  // line 8: `      f1: "4x^2 + ..."`: the text's first character follows the quote at column 11
  const FaceSpec& f1 = face(s.B, "f1");
  EXPECT_EQ(f1.where.file, kScenes + "example1.yaml");
  EXPECT_EQ(f1.where.line, 8);
  EXPECT_EQ(f1.where.column, 12);
  EXPECT_EQ(f1.text, "4x^2 + 4y^2 - 10.07047z >= 15.75982");
  EXPECT_EQ(s.B.edges[0].where.line, 12);
  EXPECT_EQ(s.B.edges[0].where.column, 7);
  EXPECT_EQ(s.B.where.line, 6);
  EXPECT_EQ(s.B.where.column, 3);
}

TEST(SceneLoader, ExampleTwoLoads) {
  const SceneSpec s = load_scene_file(kScenes + "example2.yaml");
  ASSERT_EQ(s.A.faces.size(), 2u);
  // the lens: two paraboloid caps meeting on the circle r = 1.5 at z = 0, apexes at z = -+2
  const Polynomial& g1 = face(s.A, "fA1").g;
  const Polynomial& g2 = face(s.A, "fA2").g;
  EXPECT_NEAR(g1.value({0, 0, -2}), 0, kExact);
  EXPECT_NEAR(g2.value({0, 0, 2}), 0, kExact);
  EXPECT_NEAR(g1.value({1.5, 0, 0}), 0, kExact);
  EXPECT_NEAR(g2.value({0, 1.5, 0}), 0, kExact);
  EXPECT_LT(g1.value({0, 0, 0}), 0);
  EXPECT_LT(g2.value({0, 0, 0}), 0);
  ASSERT_EQ(s.A.edges.size(), 1u);
  EXPECT_EQ(s.A.edges[0].name, "eA");
  EXPECT_EQ(s.B.faces.size(), 3u);
  EXPECT_TRUE(s.auto_seeds);
}

TEST(SceneLoader, SeedsVerticesAndDefaults) {
  const SceneSpec s = parse_scene(
      "objects:\n"
      "  A: {faces: {fA: x^2 + y^2 + z^2 <= 1}}\n"
      "  B:\n"
      "    faces: {f1: \"x^2 + y^2 + z^2 <= 16\", f2: \"x^2 + y^2 - 4z <= 16\",\n"
      "            f3: \"x^2 + z^2 <= 9\"}\n"
      "    vertices: {v1: [f3, f1, f2]}\n"
      "seeds:\n"
      "  - {position: [0, 0, 5.5], quaternion: [2, 0, 0, 0]}\n"
      "  - position: [1, 2, 3]\n"
      "    quaternion: [-1, 0, 0, -1]\n",
      "dir/my_scene.yaml");
  EXPECT_EQ(s.name, "my_scene") << "without name: the file's stem";
  EXPECT_EQ(s.path, "dir/my_scene.yaml");
  ASSERT_EQ(s.B.vertices.size(), 1u);
  EXPECT_EQ(s.B.vertices[0].faces, (std::vector<std::string>{"f3", "f1", "f2"}));
  EXPECT_FALSE(s.auto_seeds);
  ASSERT_EQ(s.seeds.size(), 2u);
  EXPECT_TRUE(s.seeds[0].pose.position.isApprox(Eigen::Vector3d(0, 0, 5.5)));
  // quaternions are normalised and made canonical (w >= 0)
  EXPECT_NEAR(s.seeds[0].pose.quaternion.w(), 1.0, kExact);
  const Eigen::Quaterniond& q = s.seeds[1].pose.quaternion;
  EXPECT_NEAR(q.w(), std::sqrt(0.5), kExact);
  EXPECT_NEAR(q.z(), std::sqrt(0.5), kExact);
  EXPECT_EQ(s.seeds[1].where.line, 9);
  // a plain (unquoted) inequality is fine too
  EXPECT_NEAR(face(s.A, "fA").g.value({0, 0, 1}), 0, kExact);
}

}  // namespace
}  // namespace pcsg
