// Contact detection against closed-form answers, one test per PtC type of paper Section II-B,
// plus penetration. Scenes are built by hand (test_shapes.h); each test checks the contact's
// pair, type, point, normal and gap, and its Jacobian against finite differences.
#include <gtest/gtest.h>

#include "engine/contact/contact_context.h"
#include "engine/contact/contact_formation.h"
#include "engine/contact/pair_solver.h"
#include "tests/engine/contact/test_shapes.h"

namespace pcsg {
namespace {

using testkit::MeshedSolid;

// Closed-form answers are met to solver round-off: 1e-12 of the scene size (the brief's bar).
constexpr double kExact = 1e-12;
// Unit normals and tangents from points exact to 1e-12 L: curvatures ~1 / L make them exact
// to ~1e-12; 1e-11 leaves a margin for the Hessian's round-off.
constexpr double kExactDirection = 1e-11;
// Central differences with a step of 1e-6 L: truncation ~1e-12, round-off ~1e-10 (relative);
// 1e-6 checks the analytic Jacobian to well below any plausible formula error.
constexpr double kFdStep = 1e-6;
constexpr double kFdTolerance = 1e-6;

Pose pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  Pose X;
  X.position = p;
  X.quaternion = q.normalized();
  return X;
}

// The Jacobian of a contact's residual rows against central differences of re-solved pairs.
void expect_jacobian_matches(const SceneGeometry& scene, const Pose& X, const PointContact& c) {
  const double L = scene.tol.length_scale;
  for (int k = 0; k < 6; ++k) {
    Eigen::VectorXd r[2];
    for (int side = 0; side < 2; ++side) {
      const double h = (side ? 1 : -1) * kFdStep * (k < 3 ? L : 1.0);
      Eigen::Vector3d v = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
      (k < 3 ? v : w)[k % 3] = h;
      const Pose Y = X.displaced(v, w, Eigen::Vector3d::Zero());
      const PairSolution s = solve_pair_problem(scene, Y, c.a, c.b, c.type, c.p_A, c.p_B);
      ASSERT_TRUE(s.converged) << "re-solve at the displaced pose " << k;
      r[side] = s.contact.residual;
    }
    const double h = kFdStep * (k < 3 ? L : 1.0);
    const Eigen::VectorXd fd = (r[1] - r[0]) / (2 * h);
    for (int i = 0; i < fd.size(); ++i)
      EXPECT_NEAR(c.jacobian(i, k), fd[i], kFdTolerance * (k < 3 ? 1.0 : L))
          << ptc_type_name(c.type) << " row " << i << " column " << k;
  }
}

struct Expected {
  std::string pair;
  PtcType type;
  Eigen::Vector3d point, normal;
  double gap;
};

void expect_single_contact(const SceneGeometry& scene, const Pose& X, const Expected& e) {
  ContactContext ctx(scene);
  const ContactReport rep = detect_contacts(ctx, X);
  const double L = scene.tol.length_scale;
  ASSERT_FALSE(rep.penetrating());
  ASSERT_EQ(rep.contacts.size(), 1u) << ContactFormation::of(rep.contacts).str(scene);
  const PointContact& c = rep.contacts[0];
  EXPECT_EQ(element_pair_name(scene, c.a, c.b), e.pair);
  EXPECT_EQ(c.type, e.type) << ptc_type_name(c.type);
  EXPECT_LT((c.point_B - e.point).norm(), kExact * L) << c.point_B.transpose();
  EXPECT_LT((c.normal_B - e.normal).norm(), kExactDirection) << c.normal_B.transpose();
  EXPECT_NEAR(c.gap, e.gap, kExact * L);
  EXPECT_EQ(c.residual.size(), ptc_codimension(c.type));
  expect_jacobian_matches(scene, X, c);
}

TEST(ContactDetection, SphereRestingOnSphereIsFaceFace) {
  const double rA = 1, rB = 2;
  const SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(rA, "fA"), testkit::sphere_solid(rB, "fB"));
  const Eigen::Vector3d u = Eigen::Vector3d(1, 2, 3).normalized();
  const Pose X = pose((rA + rB) * u, Eigen::Quaterniond(0.3, -0.2, 0.5, 0.1));
  expect_single_contact(scene, X, {"fA-fB", PtcType::FF, rB * u, u, 0.0});
}

TEST(ContactDetection, SphereGapAndPenetrationAreMeasured) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(1, "fA"), testkit::sphere_solid(2, "fB"));
  ContactContext ctx(scene);
  const double L = scene.tol.length_scale;
  const Eigen::Vector3d u = Eigen::Vector3d(-2, 1, 1).normalized();
  // Apart by a quarter of the band: a near-contact, not a contact.
  const double gap = 0.25 * ctx.guaranteed_band();
  DetectOptions near;
  near.near_margin = ctx.guaranteed_band();
  const ContactReport apart = detect_contacts(ctx, pose((3 + gap) * u), near);
  EXPECT_TRUE(apart.contacts.empty());
  EXPECT_FALSE(apart.penetrating());
  ASSERT_EQ(apart.near.size(), 1u);
  EXPECT_NEAR(apart.near[0].gap, gap, kExact * L);
  // Penetrating by 1e-3 L: reported with its depth and place, never as a contact.
  const double depth = 1e-3 * L;
  const ContactReport in = detect_contacts(ctx, pose((3 - depth) * u));
  EXPECT_TRUE(in.contacts.empty());
  ASSERT_EQ(in.penetrations.size(), 1u);
  EXPECT_NEAR(in.penetrations[0].depth, depth, kExact * L);
  EXPECT_LT((in.penetrations[0].point_B - (2 - depth / 2) * u).norm(), kExact * L);
  // Deep inside, surfaces apart: the containment test.
  const ContactReport inside = detect_contacts(ctx, pose(Eigen::Vector3d(0.1, 0, 0)));
  EXPECT_TRUE(inside.contacts.empty());
  EXPECT_TRUE(inside.penetrating());
}

TEST(ContactDetection, EllipsoidOnParaboloidAtKnownTangentPoint) {
  // B: paper Example 2's double paraboloid; A: an ellipsoid touching its upper cap fA2
  // (z = 2 - 8 r^2 / 9) at P = (0.6, 0, 1.68), tilted.
  const double a = 0.5, b = 0.3, c = 0.4;
  const SceneGeometry scene = testkit::scene_of(testkit::ellipsoid_solid(a, b, c, "fE"),
                                                testkit::double_paraboloid_solid());
  const Eigen::Vector3d P(0.6, 0, 2 - 8 * 0.36 / 9);
  const Eigen::Vector3d n = Eigen::Vector3d(16 * 0.6, 0, 9).normalized();
  const Eigen::Quaterniond q = Eigen::Quaterniond(0.9, 0.1, -0.3, 0.2).normalized();
  // The ellipsoid's point whose outward normal is -n (in A's frame).
  const Eigen::Vector3d m = q.conjugate() * (-n);
  const Eigen::Vector3d s(a * a * m.x(), b * b * m.y(), c * c * m.z());
  const Eigen::Vector3d p_A = s / std::sqrt(m.dot(s));
  expect_single_contact(scene, pose(P - (q * p_A), q), {"fE-fA2", PtcType::FF, P, n, 0.0});
}

TEST(ContactDetection, LensEdgeStandingOnSphereIsEdgeFace) {
  // A: a lens standing on its rim (edge circle of radius 0.8 in B's xz plane) on a ball.
  const SceneGeometry scene =
      testkit::scene_of(testkit::lens_solid(1, 0.6), testkit::sphere_solid(2, "fB"));
  const Eigen::Quaterniond q(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()));
  expect_single_contact(scene, pose({0, 0, 2.8}, q),
                        {"eL-fB", PtcType::EF, {0, 0, 2}, Eigen::Vector3d::UnitZ(), 0.0});
}

TEST(ContactDetection, SphereAgainstLensRimIsFaceEdge) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(0.5, "fA"), testkit::lens_solid(1, 0.6));
  expect_single_contact(scene, pose({1.3, 0, 0}),
                        {"fA-eL", PtcType::FE, {0.8, 0, 0}, Eigen::Vector3d::UnitX(), 0.0});
}

TEST(ContactDetection, CrossingRimsAreEdgeEdgeCross) {
  // A's rim in B's xz plane, B's rim in its xy plane: tangents z and y at (0.8, 0, 0).
  const SceneGeometry scene =
      testkit::scene_of(testkit::lens_solid(1, 0.6), testkit::lens_solid(1, 0.6));
  const Eigen::Quaterniond q(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()));
  expect_single_contact(scene, pose({1.6, 0, 0}, q),
                        {"eL-eL", PtcType::EECross, {0.8, 0, 0}, Eigen::Vector3d::UnitX(), 0.0});
}

TEST(ContactDetection, CoplanarTangentRimsAreEdgeEdgeTouch) {
  // Both rims in the xy plane, externally tangent at (0.8, 0, 0): collinear tangents (y).
  const SceneGeometry scene =
      testkit::scene_of(testkit::lens_solid(1, 0.6), testkit::lens_solid(1, 0.6));
  expect_single_contact(scene, pose({1.6, 0, 0}),
                        {"eL-eL", PtcType::EETouch, {0.8, 0, 0}, Eigen::Vector3d::UnitX(), 0.0});
  const ContactReport rep = detect_contacts(scene, pose({1.6, 0, 0}));
  ASSERT_EQ(rep.contacts.size(), 1u);
  const auto line = contact_line(rep.contacts[0]);
  ASSERT_TRUE(line.has_value());
  EXPECT_LT(line->direction_B.cross(Eigen::Vector3d::UnitY()).norm(), kExactDirection);
  EXPECT_FALSE(contact_plane(rep.contacts[0]).has_value());
}

TEST(ContactDetection, ThreeBallVertexRestingOnSphereIsVertexFace) {
  // A's vertex vB = (0, 0, -0.8) rests on the top of a ball of radius 2.
  const SceneGeometry scene =
      testkit::scene_of(testkit::three_ball_solid(1, 0.6), testkit::sphere_solid(2, "fB"));
  expect_single_contact(scene, pose({0, 0, 2.8}),
                        {"vB-fB", PtcType::VF, {0, 0, 2}, Eigen::Vector3d::UnitZ(), 0.0});
}


TEST(ContactDetection, ThreeBallVertexAgainstLensRimIsVertexEdge) {
  // A's vertex vB, turned to point along -x, touches B's rim at (0.8, 0, 0).
  const SceneGeometry scene =
      testkit::scene_of(testkit::three_ball_solid(1, 0.6), testkit::lens_solid(1, 0.6));
  const Eigen::Quaterniond q(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  const Pose X = pose({1.6, 0, 0}, q);
  expect_single_contact(scene, X,
                        {"vB-eL", PtcType::VE, {0.8, 0, 0}, Eigen::Vector3d::UnitX(), 0.0});
  const auto line = contact_line(detect_contacts(scene, X).contacts.at(0));
  ASSERT_TRUE(line.has_value());
  EXPECT_LT(line->direction_B.cross(Eigen::Vector3d::UnitY()).norm(), kExactDirection);
}

TEST(ContactDetection, LensRimOnThreeBallVertexIsEdgeVertex) {
  // A's rim stands in B's xz plane on B's upward vertex vT = (0, 0, 0.8).
  const SceneGeometry scene =
      testkit::scene_of(testkit::lens_solid(1, 0.6), testkit::three_ball_solid(1, 0.6));
  const Eigen::Quaterniond q(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()));
  expect_single_contact(scene, pose({0, 0, 1.6}, q),
                        {"eL-vT", PtcType::EV, {0, 0, 0.8}, Eigen::Vector3d::UnitZ(), 0.0});
}

TEST(ContactDetection, ThreeBallVerticesTouchingAreVertexVertex) {
  const SceneGeometry scene = testkit::scene_of(testkit::three_ball_solid(1, 0.6),
                                                testkit::three_ball_solid(1, 0.6));
  const Eigen::Quaterniond q(Eigen::AngleAxisd(M_PI / 3, Eigen::Vector3d::UnitZ()));
  expect_single_contact(scene, pose({0, 0, 1.6}, q),
                        {"vB-vT", PtcType::VV, {0, 0, 0.8}, Eigen::Vector3d::Zero(), 0.0});
}

TEST(ContactDetection, SphereOnThreeBallVertexIsFaceVertex) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(0.5, "fA"), testkit::three_ball_solid(1, 0.6));
  expect_single_contact(scene, pose({0, 0, 1.3}),
                        {"fA-vT", PtcType::FV, {0, 0, 0.8}, Eigen::Vector3d::UnitZ(), 0.0});
}

}  // namespace
}  // namespace pcsg
