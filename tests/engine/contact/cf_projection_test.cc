// Projection onto a contact formation's configurations (contact_formation.h), on hand-built
// scenes: codimension 1, 2 x 1 (two contacts of one pair) and 3 (e-e-touch, v-v), and the
// reasons given when it cannot succeed.
#include <gtest/gtest.h>

#include <thread>

#include "engine/contact/contact_context.h"
#include "engine/contact/contact_formation.h"
#include "tests/engine/contact/test_shapes.h"

namespace pcsg {
namespace {

// The brief's bar for projected contacts: gaps below 1e-10 of the scene size.
constexpr double kSnapped = 1e-10;

Pose pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  Pose X;
  X.position = p;
  X.quaternion = q.normalized();
  return X;
}

Eigen::Quaterniond turn(double angle, const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

void expect_projects(const SceneGeometry& scene, const Pose& start, const std::string& text) {
  ContactContext ctx(scene);
  const ContactFormation cf = ContactFormation::parse(text, scene);
  const ProjectionResult proj = project_onto_cf(ctx, start, cf);
  ASSERT_TRUE(proj.ok) << proj.reason;
  EXPECT_LE(proj.max_residual, scene.tol.solve_residual);
  ASSERT_EQ(static_cast<int>(proj.contacts.size()), cf.cardinality());
  for (const PointContact& c : proj.contacts) {
    EXPECT_LT(std::abs(c.gap), kSnapped * scene.tol.length_scale);
    EXPECT_LT(c.residual.cwiseAbs().maxCoeff(), kSnapped * scene.tol.length_scale);
  }
  const ContactReport rep = detect_contacts(ctx, proj.pose);
  EXPECT_FALSE(rep.penetrating());
  EXPECT_EQ(ContactFormation::of(rep.contacts).str(scene), text);
}

TEST(CfProjection, SphereOntoSphere) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(1, "fA"), testkit::sphere_solid(2, "fB"));
  expect_projects(scene, pose({0.4, 0.2, 3.2}, turn(0.3, {1, 1, 0})), "{(fA-fB, 1)}");
}

TEST(CfProjection, EllipsoidIntoTheBowlAtTwoPoints) {
  const SceneGeometry scene = testkit::scene_of(testkit::ellipsoid_solid(1, 1.5, 2.5, "fA"),
                                                testkit::bowl_solid());
  const Pose start = pose({0.05, -0.03, 1.1},
                          turn(0.04, {1, 2, 0}) * turn(M_PI / 2, Eigen::Vector3d::UnitY()));
  expect_projects(scene, start, "{(fA-f1, 2)}");
}

TEST(CfProjection, RimsOntoTouchingWithCollinearTangents) {
  // Codimension 3: the rims must meet and their tangents align (paper Section II-B).
  const SceneGeometry scene =
      testkit::scene_of(testkit::lens_solid(1, 0.6), testkit::lens_solid(1, 0.6));
  expect_projects(scene, pose({1.62, 0.03, 0.01}, turn(0.05, {1, 0.3, 0.2})), "{(eL-eL, 1, touch)}");
}

TEST(CfProjection, VerticesOntoEachOther) {
  const SceneGeometry scene = testkit::scene_of(testkit::three_ball_solid(1, 0.6),
                                                testkit::three_ball_solid(1, 0.6));
  expect_projects(scene, pose({0.02, -0.03, 1.63}, turn(M_PI / 3 + 0.05, {0.1, 0, 1})),
                  "{(vB-vT, 1)}");
}

TEST(CfProjection, ReportsWhyItCannot) {
  const SceneGeometry scene = testkit::scene_of(testkit::ellipsoid_solid(1, 1.5, 2.5, "fA"),
                                                testkit::bowl_solid());
  ContactContext ctx(scene);
  const Pose start = pose({0, 0, 1.1}, turn(M_PI / 2, Eigen::Vector3d::UnitY()));
  // The ellipsoid lying in the dish has two distance minima to it, not three.
  const ProjectionResult three =
      project_onto_cf(ctx, start, ContactFormation::parse("{(fA-f1, 3)}", scene));
  EXPECT_FALSE(three.ok);
  EXPECT_NE(three.reason.find("found 2 of the 3 local distance minima of fA-f1"),
            std::string::npos)
      << three.reason;
  // Touching the bottom face f3 from inside the dish goes through B: it penetrates or fails.
  const ProjectionResult bottom =
      project_onto_cf(ctx, start, ContactFormation::parse("{(fA-f3, 1)}", scene));
  EXPECT_FALSE(bottom.ok);
  EXPECT_FALSE(bottom.reason.empty());
}

TEST(CfProjection, DetectionIsThreadSafeOnASharedContext) {
  const SceneGeometry scene = testkit::scene_of(testkit::ellipsoid_solid(1, 1.5, 2.5, "fA"),
                                                testkit::bowl_solid());
  const ContactContext ctx(scene);
  std::vector<Pose> poses;
  for (int k = 0; k < 40; ++k)
    poses.push_back(pose({0.01 * k, 0, 1.0 + 0.002 * k}, turn(M_PI / 2, Eigen::Vector3d::UnitY())));
  auto run = [&](std::vector<std::string>& out) {
    for (const Pose& X : poses) {
      const ContactReport rep = detect_contacts(ctx, X);
      out.push_back(ContactFormation::of(rep.contacts).str(scene) +
                    (rep.penetrating() ? " penetrating" : ""));
    }
  };
  std::vector<std::string> serial, a, b;
  run(serial);
  std::thread ta(run, std::ref(a)), tb(run, std::ref(b));
  ta.join();
  tb.join();
  EXPECT_EQ(a, serial);
  EXPECT_EQ(b, serial);
}

}  // namespace
}  // namespace pcsg
