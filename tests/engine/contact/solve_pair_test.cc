// solve_pair: tracking one pair through a motion (the generator's keep action, paper Section
// III-C), and its refusal once the contact has left the elements.
#include <gtest/gtest.h>

#include <stdexcept>

#include "engine/contact/contact.h"
#include "tests/engine/contact/test_shapes.h"

namespace pcsg {
namespace {

// Closed-form answers are met to solver round-off: 1e-12 of the scene size.
constexpr double kExact = 1e-12;

Pose at(const Eigen::Vector3d& p) {
  Pose X;
  X.position = p;
  return X;
}

TEST(SolvePair, TracksASphereMovingOverASphere) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(1, "fA"), testkit::sphere_solid(2, "fB"));
  const ElementId a = scene.A.find("fA"), b = scene.B.find("fB");
  Eigen::Vector3d p_A(0, 0, -1), p_B(0, 0, 2);
  // Along an arc, apart by a varying gap: the solve follows from the previous points.
  for (int k = 0; k <= 20; ++k) {
    const double angle = 0.05 * k, gap = 0.01 * k;
    const Eigen::Vector3d u(std::sin(angle), 0, std::cos(angle));
    const auto c = solve_pair(scene, at((3 + gap) * u), a, b, PtcType::FF, p_A, p_B);
    ASSERT_TRUE(c.has_value()) << "step " << k;
    EXPECT_NEAR(c->gap, gap, kExact * scene.tol.length_scale);
    EXPECT_LT((c->p_B - 2 * u).norm(), kExact * scene.tol.length_scale);
    EXPECT_EQ(c->residual.size(), 1);
    p_A = c->p_A;
    p_B = c->p_B;
  }
}

TEST(SolvePair, RefusesWhenThePointLeavesTheFace) {
  // A ball against the lens's rim from the side: the closest point of fU's sphere lies below
  // the rim, outside the face, so fA-fU is not a contact there (fA-eL is).
  const SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(0.5, "fA"), testkit::lens_solid(1, 0.6));
  const ElementId a = scene.A.find("fA");
  const Pose X = at({1.3, 0, 0});
  EXPECT_FALSE(solve_pair(scene, X, a, scene.B.find("fU"), PtcType::FF, {-0.5, 0, 0},
                          {0.8, 0, 0.01})
                   .has_value());
  const auto rim = solve_pair(scene, X, a, scene.B.find("eL"), PtcType::FE, {-0.5, 0, 0},
                              {0.8, 0, 0});
  ASSERT_TRUE(rim.has_value());
  EXPECT_NEAR(rim->gap, 0, kExact * scene.tol.length_scale);
}

TEST(SolvePair, RejectsATypeThatDoesNotJoinTheElements) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(1, "fA"), testkit::lens_solid(1, 0.6));
  EXPECT_THROW(solve_pair(scene, at({2, 0, 0}), scene.A.find("fA"), scene.B.find("eL"),
                          PtcType::FF, {-1, 0, 0}, {0.8, 0, 0}),
               std::invalid_argument);
}

TEST(PtcType, NamesKindsCodimensionsPlanesAndLines) {
  const PtcType all[] = {PtcType::FF, PtcType::FE, PtcType::EF, PtcType::EECross,
                         PtcType::EETouch, PtcType::FV, PtcType::VF, PtcType::EV,
                         PtcType::VE, PtcType::VV};
  for (PtcType t : all) EXPECT_EQ(parse_ptc_type(ptc_type_name(t)), t);
  EXPECT_FALSE(parse_ptc_type("f-x").has_value());
  EXPECT_STREQ(ptc_type_name(PtcType::EECross), "e-e-cross");
  EXPECT_EQ(ptc_codimension(PtcType::FF), 1);
  EXPECT_EQ(ptc_codimension(PtcType::EECross), 1);
  EXPECT_EQ(ptc_codimension(PtcType::VE), 2);
  EXPECT_EQ(ptc_codimension(PtcType::EETouch), 3);
  EXPECT_EQ(ptc_codimension(PtcType::VV), 3);
  EXPECT_EQ(ptc_type_between(ElementKind::Edge, ElementKind::Edge), PtcType::EECross);
  EXPECT_EQ(ptc_type_between(ElementKind::Vertex, ElementKind::Face), PtcType::VF);
  EXPECT_EQ(ptc_kind_a(PtcType::EV), ElementKind::Edge);
  EXPECT_EQ(ptc_kind_b(PtcType::EV), ElementKind::Vertex);
  // Section II-B: planes for f-f, f-e, e-f, f-v, v-f, e-e-cross; lines for v-e, e-v, touch.
  for (PtcType t : all) {
    const bool plane = t == PtcType::FF || t == PtcType::FE || t == PtcType::EF ||
                       t == PtcType::FV || t == PtcType::VF || t == PtcType::EECross;
    const bool line = t == PtcType::VE || t == PtcType::EV || t == PtcType::EETouch;
    EXPECT_EQ(has_contact_plane(t), plane) << ptc_type_name(t);
    EXPECT_EQ(has_contact_line(t), line) << ptc_type_name(t);
  }
}

}  // namespace
}  // namespace pcsg
