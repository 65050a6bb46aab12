// swap_objects: the two objects change roles, polynomials and names unchanged, seeds inverted.
#include "engine/scene/scene_swap.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace pcsg {
namespace {

const std::string kScenes = std::string(PCSG_SOURCE_DIR) + "/scenes/";
// Inverting a pose rotates and negates coordinates of size ~5: a few ulps of 5.
constexpr double kPoseRoundOff = 1e-14;

SceneSpec example2_with_seed() {
  SceneSpec s = load_scene_file(kScenes + "example2.yaml");
  s.auto_seeds = false;
  SeedSpec seed;
  seed.pose.position = {0.25, -1.5, 3};
  seed.pose.quaternion =
      Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d(2, -1, 3).normalized()));
  s.seeds.push_back(seed);
  return s;
}

void expect_same_object(const ObjectSpec& got, const ObjectSpec& want, const char* role) {
  ASSERT_EQ(got.faces.size(), want.faces.size()) << role;
  for (size_t i = 0; i < want.faces.size(); ++i) {
    EXPECT_EQ(got.faces[i].name, want.faces[i].name) << role;
    EXPECT_EQ(got.faces[i].text, want.faces[i].text) << role;
    EXPECT_EQ(got.faces[i].g.coeffs(), want.faces[i].g.coeffs()) << role << " " << want.faces[i].name;
  }
  ASSERT_EQ(got.edges.size(), want.edges.size()) << role;
  for (size_t i = 0; i < want.edges.size(); ++i) EXPECT_EQ(got.edges[i].name, want.edges[i].name);
  EXPECT_EQ(got.name, role);
}

TEST(SceneSwap, ObjectsExchangeRolesWithTheirPolynomialsAndNames) {
  const SceneSpec s = example2_with_seed();
  const SceneSpec t = swap_objects(s);
  expect_same_object(t.A, s.B, "A");
  expect_same_object(t.B, s.A, "B");
  EXPECT_EQ(t.name, s.name + " (A and B swapped)");
  EXPECT_EQ(t.auto_seeds, s.auto_seeds);
}

TEST(SceneSwap, SeedsInvert) {
  const SceneSpec s = example2_with_seed();
  const SceneSpec t = swap_objects(s);
  ASSERT_EQ(t.seeds.size(), 1u);
  // a point q of the old A sits at X_BA q in the old B; the new pose X_AB takes it back
  const Pose& X_BA = s.seeds[0].pose;
  const Pose& X_AB = t.seeds[0].pose;
  for (const Eigen::Vector3d& q : {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-0.5, 0, 2)}) {
    EXPECT_TRUE(X_AB.apply(X_BA.apply(q)).isApprox(q, kPoseRoundOff)) << q.transpose();
    EXPECT_TRUE(X_BA.apply(X_AB.apply(q)).isApprox(q, kPoseRoundOff)) << q.transpose();
  }
  EXPECT_GE(X_AB.quaternion.w(), 0) << "canonical";
}

TEST(SceneSwap, SwappingTwiceRestoresTheScene) {
  const SceneSpec s = example2_with_seed();
  const SceneSpec back = swap_objects(swap_objects(s));
  expect_same_object(back.A, s.A, "A");
  expect_same_object(back.B, s.B, "B");
  EXPECT_EQ(back.name, s.name);
  EXPECT_TRUE(back.seeds[0].pose.position.isApprox(s.seeds[0].pose.position, kPoseRoundOff));
  EXPECT_TRUE(back.seeds[0].pose.quaternion.isApprox(s.seeds[0].pose.quaternion, kPoseRoundOff));
}

}  // namespace
}  // namespace pcsg
