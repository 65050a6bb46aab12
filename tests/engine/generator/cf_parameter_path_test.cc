#include "engine/generator/cf_parameter_path.h"

#include <gtest/gtest.h>

#include "engine/generator/state_identity.h"
#include "generator_test_support.h"

namespace pcsg {
namespace {

// Round-off of poses built from unit frames and of the detector's contact points.
constexpr double kPoseTolerance = 1e-9;

// The three-sphere lens's edge e_s2_s3 passes through s1's centre, the origin (on both unit
// spheres about (1, 0, 0) and (1/2, sqrt(3)/2, 0)), along z, its normal cone spanned by
// (-1, 0, 0) and (-1/2, -sqrt(3)/2, 0). B's rim e2 (sphere band x^2 + y^2 + z^2 = 16 against
// the bottom x^2 + y^2 - 4z = 16) is the circle of radius 4 in z = 0, its cone spanned by
// (1, 0, 0) and (2, 0, -1)/sqrt(5). A crossing of the two at the origin and (4, 0, 0), each
// normal mid-cone, the edges at `twist` about the normal.
ContactChart rim_crossing(double twist, double rim_angle) {
  ContactChart c;
  c.p_A = Eigen::Vector3d::Zero();
  c.normal_A = Eigen::Vector3d(-1.5, -std::sqrt(3.0) / 2, 0).normalized();
  c.ref_A = Eigen::Vector3d::UnitZ();
  const Eigen::AngleAxisd about_z(rim_angle, Eigen::Vector3d::UnitZ());
  c.p_B = about_z * Eigen::Vector3d(4, 0, 0);
  c.normal_B =
      about_z * (Eigen::Vector3d(1, 0, 0) + Eigen::Vector3d(2, 0, -1).normalized()).normalized();
  c.ref_B = about_z * Eigen::Vector3d::UnitY();
  c.twist = twist;
  return c;
}

SceneGeometry three_spheres() {
  return build_scene_geometry(load_scene_file(testing::scene_path("three_spheres.yaml")));
}

// The pose built from a chart has exactly that contact, and the chart read back from the
// detected contact builds the same pose.
TEST(CfParameterPath, ChartBuildsItsContactAndReadsBack) {
  const SceneGeometry scene = three_spheres();
  const Pose X = pose_of_chart(rim_crossing(-M_PI / 2, 0.3));
  const ContactReport rep = detect_contacts(scene, X);
  ASSERT_FALSE(rep.penetrating());
  ASSERT_EQ(rep.contacts.size(), 1u);
  const PointContact& c = rep.contacts[0];
  EXPECT_EQ(c.type, PtcType::EECross);
  EXPECT_EQ(scene.A.element_name(c.a), "e_s2_s3");
  EXPECT_EQ(scene.B.element_name(c.b), "e2");
  EXPECT_NEAR(c.p_A.norm(), 0, kPoseTolerance);
  const ContactChart back =
      chart_of(scene, X, c, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX());
  const Pose Y = pose_of_chart(back);
  EXPECT_NEAR((Y.position - X.position).norm(), 0, kPoseTolerance);
  EXPECT_NEAR(Y.quaternion.angularDistance(X.quaternion), 0, kPoseTolerance);
}

// Two crossings of one sign, the crossing angle far apart (-170 and -10 degrees) and the
// rim points a quarter turn apart: one region, joined along the parameters. Of opposite
// signs they are never joined (a crossing sign is a region invariant, state_identity.h).
TEST(CfParameterPath, JoinsCrossingsOfOneSignOnly) {
  const SceneGeometry scene = three_spheres();
  const Pose a = pose_of_chart(rim_crossing(-170 * M_PI / 180, 0));
  const Pose b = pose_of_chart(rim_crossing(-10 * M_PI / 180, M_PI / 2));
  const Pose c = pose_of_chart(rim_crossing(10 * M_PI / 180, M_PI / 2));
  const ContactFormation cf = ContactFormation::of(detect_contacts(scene, a).contacts);
  ASSERT_EQ(cf.cardinality(), 1);
  ASSERT_TRUE(ContactFormation::of(detect_contacts(scene, b).contacts) == cf);
  ASSERT_TRUE(ContactFormation::of(detect_contacts(scene, c).contacts) == cf);
  MotionCounters counters;
  EXPECT_TRUE(joined_by_parameter_path(scene, a, b, cf, counters));
  EXPECT_FALSE(joined_by_parameter_path(scene, a, c, cf, counters));
}

}  // namespace
}  // namespace pcsg
