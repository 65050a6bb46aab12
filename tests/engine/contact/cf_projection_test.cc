// Projection onto a contact formation's configurations (contact_formation.h), on hand-built
// scenes: codimension 1, 2 x 1 (two contacts of one pair) and 3 (e-e-touch, v-v), and the
// reasons given when it cannot succeed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <thread>

#include "engine/contact/contact_context.h"
#include "engine/contact/contact_formation.h"
#include "engine/contact/pair_seeds.h"
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

bool same_bits(const Pose& a, const Pose& b) {
  return std::memcmp(a.position.data(), b.position.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(a.quaternion.coeffs().data(), b.quaternion.coeffs().data(),
                     4 * sizeof(double)) == 0;
}

bool same_minima(const std::vector<PointContact>& a, const std::vector<PointContact>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k)
    if (a[k].p_A != b[k].p_A || a[k].p_B != b[k].p_B || a[k].gap != b[k].gap) return false;
  return true;
}

// PairMinimaMemo (pair_seeds.h) gives pair_local_minima's answer, keyed by the exact pose and
// pair: the same pose again is found (not sampled again), a pose one ulp away or another pair
// is not.
TEST(PairMinimaMemo, AnswersAsTheSamplingDoesForTheExactInputs) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::ellipsoid_solid(1, 1.5, 2.5, "fA"), testkit::bowl_solid());
  ContactContext ctx(scene);
  const ContactFormation cf = ContactFormation::parse("{(fA-f1, 2)}", scene);
  const PtcCount& e = cf.entries().front();
  const Pose X = pose({0.05, -0.03, 1.3}, turn(M_PI / 2, Eigen::Vector3d::UnitY()));
  const std::vector<PointContact> want = pair_local_minima(ctx, X, e.a, e.b, e.type);
  ASSERT_EQ(want.size(), 2u);  // the ellipsoid above the dish: two distance minima
  PairMinimaMemo memo;
  EXPECT_TRUE(same_minima(memo.get(ctx, X, e.a, e.b, e.type), want));
  EXPECT_EQ(memo.size(), 1u);
  EXPECT_TRUE(same_minima(memo.get(ctx, X, e.a, e.b, e.type), want));
  EXPECT_EQ(memo.size(), 1u);
  EXPECT_EQ(memo.computed(), 1u);  // found, not sampled again
  Pose Y = X;
  Y.position.z() = std::nextafter(X.position.z(), 2.0);
  EXPECT_TRUE(
      same_minima(memo.get(ctx, Y, e.a, e.b, e.type), pair_local_minima(ctx, Y, e.a, e.b, e.type)));
  EXPECT_EQ(memo.size(), 2u);
  EXPECT_EQ(memo.computed(), 2u);
  const ElementId rim{ElementKind::Edge, 0};
  memo.get(ctx, X, e.a, rim, PtcType::FE);
  EXPECT_EQ(memo.size(), 3u);
}

// A projection that takes its starts from the memo ends at the same pose, bit for bit, as one
// that samples them itself; a second projection from the same pose finds them there.
TEST(CfProjection, WithAMinimaMemoEndsWhereItWouldWithout) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::ellipsoid_solid(1, 1.5, 2.5, "fA"), testkit::bowl_solid());
  ContactContext ctx(scene);
  const ContactFormation cf = ContactFormation::parse("{(fA-f1, 2)}", scene);
  // Above the dish by more than detection's band: the starts come from sampling.
  const Pose start = pose({0.05, -0.03, 1.3}, turn(M_PI / 2, Eigen::Vector3d::UnitY()));
  const ProjectionResult plain = project_onto_cf(ctx, start, cf);
  ASSERT_TRUE(plain.ok) << plain.reason;
  PairMinimaMemo memo;
  ProjectionOptions options;
  options.minima = &memo;
  for (int k = 0; k < 2; ++k) {
    const ProjectionResult memoised = project_onto_cf(ctx, start, cf, options);
    ASSERT_TRUE(memoised.ok) << memoised.reason;
    EXPECT_TRUE(same_bits(memoised.pose, plain.pose)) << k;
    EXPECT_EQ(memo.size(), 1u) << k;
    EXPECT_EQ(memo.computed(), 1u) << k;
  }
}

}  // namespace
}  // namespace pcsg
