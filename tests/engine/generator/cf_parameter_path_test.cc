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
  // Nor does a roadmap of the region (state_identity.h) reach the other sign.
  const RegionSignature sig = region_signature(detect_contacts(scene, a).contacts);
  ASSERT_NE(sig, region_signature(detect_contacts(scene, c).contacts));
  RoadmapStats stats;
  EXPECT_FALSE(joined_by_roadmap(scene, a, c, cf, sig, counters, &stats));
  EXPECT_GT(stats.motions, 0);
}

Pose pose(double x, double y, double z, double qw, double qx, double qy, double qz) {
  Pose X;
  X.position = {x, y, z};
  X.quaternion = Eigen::Quaterniond(qw, qx, qy, qz);
  return X;
}

// Witnesses that transitions leave on a region's boundary: Example 2's lens rim crossing the
// dish's rims, as session-6 runs of Example 2 reported them (states 6 and 16, 18 and 20 of
// that graph: one region each, by the crossing sign and the solids' symmetry, yet unjoined).
// Witness 16's normal lies on the boundary of e1's cone (at the fraction 1 of it, f2's end),
// 18's on eA's (1.002, just past it) and 20's on e2's (1.001); 6, 16 and 20 cross at 0.008 to
// 0.012 rad, next to e-e-touch. A walk that kept a witness's own normal at its end made
// waypoints that detection reads as the neighbouring face's contact (eA-f2, fA2-e2, eA-f3),
// and no join was found; one whose normals lie a little inside the cones at its ends joins
// each pair.
TEST(CfParameterPath, JoinsWitnessesWhoseNormalsLieOnTheirConesBoundaries) {
  const SceneGeometry scene =
      build_scene_geometry(load_scene_file(testing::scene_path("example2.yaml")));
  const SceneSymmetry symmetry = SceneSymmetry::of(scene);
  const std::pair<Pose, Pose> pairs[] = {
      {pose(1.830166987592919, -2.41511256808837, 3.928208186016847, 0.6688741623005037,
            -0.5341099279435503, -0.5122972793156209, -0.06989590463501978),
       pose(2.774159595118654, -3.6764985005931985, 2.8805499366523084, 0.9826436403226555,
            -0.10550260835686125, -0.10701675262902861, -0.10875702469300993)},
      {pose(-3.2532180809341735, 4.223122516140463, -0.6919380378682578, 0.23632793264086724,
            0.7035198080399171, 0.66983624067939, -0.022986922840481976),
       pose(3.0539747556624586, -4.051969512103499, -1.047171120766506, 0.920377414023663,
            0.27658200050422344, 0.25598446394129826, -0.104306121454509)}};
  const char* cfs[] = {"{(eA-e1, 1)}", "{(eA-e2, 1)}"};
  for (int k = 0; k < 2; ++k) {
    const auto& [a, b] = pairs[k];
    const ContactReport ra = detect_contacts(scene, a), rb = detect_contacts(scene, b);
    ASSERT_FALSE(ra.penetrating() || rb.penetrating());
    const ContactFormation cf = ContactFormation::of(ra.contacts);
    ASSERT_EQ(cf.str(scene), cfs[k]);
    ASSERT_TRUE(ContactFormation::of(rb.contacts) == cf);
    // One region by the invariant: the same crossing sign.
    ASSERT_EQ(region_signature(ra.contacts), region_signature(rb.contacts));
    MotionCounters counters;
    EXPECT_TRUE(joined_by_parameter_path(scene, a, b, cf, counters, symmetry)) << cfs[k];
  }
}

}  // namespace
}  // namespace pcsg
