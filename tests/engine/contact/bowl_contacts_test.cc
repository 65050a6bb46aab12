// Paper Example 1's situation (Fig. 5b): an ellipsoid lying on its side in the concave dish f1
// touches it at two symmetric points, the seed CF {(fA-f1, 2)}. Closed form in the symmetry
// plane y = 0: the ellipse (x / 2.5)^2 + (z - h)^2 = 1 meets the parabola z = a x^2 - b in a
// double root when h = 6.25 a + 1 / (25 a) - b, at z - h = -1 / (12.5 a).
#include <gtest/gtest.h>

#include "engine/contact/contact_context.h"
#include "engine/contact/contact_formation.h"
#include "tests/engine/contact/test_shapes.h"

namespace pcsg {
namespace {

using K = testkit::BowlConstants;

// Closed-form answers are met to solver round-off: 1e-12 of the scene size.
constexpr double kExact = 1e-12;
// Unit normals from points exact to 1e-12 L: curvatures ~1 / L make them exact to ~1e-12;
// 1e-11 leaves a margin for the Hessian's round-off.
constexpr double kExactDirection = 1e-11;

struct Resting {
  double h, x, z;  // centre height, contact points (+-x, 0, z)
};

Resting resting() {
  Resting r;
  r.h = 6.25 * K::a + 1 / (25 * K::a) - K::b;
  r.z = r.h - 1 / (12.5 * K::a);
  r.x = std::sqrt((r.z + K::b) / K::a);
  return r;
}

// A's long axis (z, semi-axis 2.5) along B's x, its short one (x, 1) vertical.
Pose lying(double height, double scale = 1) {
  Pose X;
  X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  X.position = {0, 0, height * scale};
  return X;
}

SceneGeometry bowl_scene(double s = 1) {
  return testkit::scene_of(testkit::ellipsoid_solid(1 * s, 1.5 * s, 2.5 * s, "fA"),
                           testkit::bowl_solid(s));
}

TEST(BowlContacts, EllipsoidLyingInTheDishTouchesAtTwoSymmetricPoints) {
  const SceneGeometry scene = bowl_scene();
  const Resting r = resting();
  const ContactReport rep = detect_contacts(scene, lying(r.h));
  const double L = scene.tol.length_scale;
  ASSERT_FALSE(rep.penetrating());
  EXPECT_EQ(ContactFormation::of(rep.contacts).str(scene), "{(fA-f1, 2)}");
  ASSERT_EQ(rep.contacts.size(), 2u);
  for (const PointContact& c : rep.contacts) {
    const double sx = c.point_B.x() > 0 ? 1 : -1;
    EXPECT_LT((c.point_B - Eigen::Vector3d(sx * r.x, 0, r.z)).norm(), kExact * L);
    // The dish's outward normal grad(15.76 - 4 r^2 + 10.07 z) points up and inward.
    const Eigen::Vector3d n = Eigen::Vector3d(-8 * sx * r.x, 0, 10.07047).normalized();
    EXPECT_LT((c.normal_B - n).norm(), kExactDirection);
    EXPECT_LT(std::abs(c.gap), kExact * L);
  }
}

TEST(BowlContacts, RaisedEllipsoidGivesTwoNearContactsAndLoweredOnePenetrates) {
  const SceneGeometry scene = bowl_scene();
  ContactContext ctx(scene);
  const Resting r = resting();
  const double L = scene.tol.length_scale;
  DetectOptions near;
  near.near_margin = ctx.guaranteed_band();
  const double lift = 0.2 * ctx.guaranteed_band();
  const ContactReport up = detect_contacts(ctx, lying(r.h + lift), near);
  EXPECT_TRUE(up.contacts.empty());
  EXPECT_FALSE(up.penetrating());
  ASSERT_EQ(up.near.size(), 2u);
  for (const PointContact& c : up.near) {
    // Raising A by d moves the gap by d cos(angle of the normal to z) to first order.
    EXPECT_GT(c.gap, 0);
    EXPECT_LT(c.gap, lift);
  }
  const ContactReport down = detect_contacts(ctx, lying(r.h - 1e-4 * L));
  EXPECT_TRUE(down.contacts.empty());
  EXPECT_EQ(down.penetrations.size(), 2u);
}

TEST(BowlContacts, SameContactsWhenTheSceneIsScaled) {
  // Scale invariance (Tolerances): 1e-3 and 1e3 give the same CF and the points scaled.
  const Resting r = resting();
  for (double s : {1e-3, 1e3}) {
    const SceneGeometry scene = bowl_scene(s);
    const ContactReport rep = detect_contacts(scene, lying(r.h, s));
    EXPECT_EQ(ContactFormation::of(rep.contacts).str(scene), "{(fA-f1, 2)}") << "scale " << s;
    ASSERT_EQ(rep.contacts.size(), 2u);
    for (const PointContact& c : rep.contacts)
      EXPECT_LT((c.point_B.cwiseAbs() - Eigen::Vector3d(r.x, 0, std::abs(r.z)) * s).norm(),
                kExact * scene.tol.length_scale)
          << "scale " << s;
  }
}

}  // namespace
}  // namespace pcsg
