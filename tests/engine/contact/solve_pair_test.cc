// solve_pair: tracking one pair through a motion (the generator's keep action, paper Section
// III-C), and its refusal once the contact has left the elements.
#include <gtest/gtest.h>

#include <stdexcept>

#include "engine/contact/contact.h"
#include "engine/contact/contact_classification.h"
#include "engine/contact/pair_solver.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"
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

// A ball of radius 1 on a ball of radius 4 whose centre is 1.3e6 (1e5 sizes) from B's origin,
// ten times as far as in scenes/stress/*_far_rotated.yaml: the residual of a contact there
// cannot fall below the round-off of its coordinates (eps * 1.3e6 = 2.9e-10, against
// solve_residual 1.39e-11 for L = 13.9), so a solve stopping at solve_residual converged only
// where round-off happened to land below it (measured without Tolerances::residual_at: 240 of
// the 400 solves below failed; at the stress scenes' 1e4 sizes the round-off straddles
// solve_residual, and the far needle's contact rates failed by it). Every one converges now,
// to a contact exact to 1e-9 L.
TEST(SolvePair, ConvergesAtTheRoundOffOfFarCoordinates) {
  const SceneGeometry scene = testkit::far_balls_scene();
  const ElementId a = scene.A.find("fA"), b = scene.B.find("fB");
  const Eigen::Vector3d& centre = testkit::kFarBallsCentre;
  int converged = 0, solves = 0;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      // A touching B from direction u, its pose turned so that A's point is not trivial
      const double theta = 0.15 + 0.14 * i, phi = 0.31 * j;
      const Eigen::Vector3d u(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
      Pose X;
      X.position = centre + 5 * u;
      X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * i + 0.07 * j, u.unitOrthogonal()));
      const Eigen::Vector3d p_A = X.apply_inverse(centre + 4 * u);
      // starts off the solution by 1e-3 of the scene
      const Eigen::Vector3d off = 1e-2 * Eigen::Vector3d(0.3, -0.2, 0.1);
      const PairSolution sol =
          solve_pair_problem(scene, X, a, b, PtcType::FF, p_A + off, centre + 4 * u - off);
      ++solves;
      if (!sol.converged) continue;
      ++converged;
      EXPECT_NEAR(sol.contact.gap, 0, 1e-9 * scene.tol.length_scale) << i << " " << j;
      EXPECT_LT((sol.contact.p_B - (centre + 4 * u)).norm(), 1e-9 * scene.tol.length_scale);
    }
  EXPECT_EQ(converged, solves);
}

// Detection's solves (resolve_contact) stop at Tolerances::detection_solve_max_iterations, the
// other solves at solve_max_iterations: from a start a quarter turn off the contact, the pair
// needs m iterations; detection finds the contact with a cap of m and reports a solve that does
// not converge with m - 1, whatever solve_max_iterations says.
TEST(SolvePair, DetectionsSolvesStopAtTheirOwnIterationCap) {
  SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(1, "fA"), testkit::sphere_solid(2, "fB"));
  const ElementId a = scene.A.find("fA"), b = scene.B.find("fB");
  const Pose X = at({3.5, 0, 0});
  const Eigen::Vector3d start_A(0, 0, -1), start_B(0, 2, 0);
  int m = 1;
  while (m <= scene.tol.solve_max_iterations &&
         !solve_pair_problem(scene, X, a, b, PtcType::FF, start_A, start_B, m).converged)
    ++m;
  ASSERT_LE(m, scene.tol.solve_max_iterations);
  ASSERT_GE(m, 3) << "the start must need several iterations";
  scene.tol.solve_max_iterations = 2 * m;
  scene.tol.detection_solve_max_iterations = m;
  const ResolvedContact found = resolve_contact(scene, X, a, b, start_A, start_B);
  ASSERT_TRUE(found.found && found.minimum) << found.reason;
  EXPECT_NEAR(found.contact.gap, 0.5, kExact * scene.tol.length_scale);
  scene.tol.detection_solve_max_iterations = m - 1;
  const ResolvedContact capped = resolve_contact(scene, X, a, b, start_A, start_B);
  EXPECT_FALSE(capped.found);
  EXPECT_TRUE(capped.diverged);
}

TEST(SolvePair, RejectsATypeThatDoesNotJoinTheElements) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::sphere_solid(1, "fA"), testkit::lens_solid(1, 0.6));
  EXPECT_THROW(solve_pair(scene, at({2, 0, 0}), scene.A.find("fA"), scene.B.find("eL"),
                          PtcType::FF, {-1, 0, 0}, {0.8, 0, 0}),
               std::invalid_argument);
}

// Example 2's B: its sphere band f2 and its bottom f3 (x^2 + y^2 - 4z <= 16) are tangent at
// f3's apex (0, 0, -4), a vertex of f3's mesh, so rim e2's two face gradients are parallel
// there and the rim has no tangent. An e-e-touch solve started there (a mesh start of the
// detection, session 38: Example 2 moved by a small rigid motion, a join of the mirror-image
// phase) fed non-finite rows to Eigen's JacobiSVD, which read out of bounds and the run died
// of a segmentation fault. It must refuse instead.
TEST(SolvePair, RefusesATouchStartWhereTheRimHasNoTangent) {
  const SceneGeometry scene =
      build_scene_geometry(load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/example2.yaml"));
  Pose X;  // that join's rotation; any pose will do (the rows fail on B's point alone)
  X.position = {-0.96, -3.71, -2.28};
  X.quaternion = Eigen::Quaterniond(0.7404495, 0.1163922, 0.6619570, 0.0005776).normalized();
  const Eigen::Vector3d apex(0, 0, -4), on_eA(-0.90500371231668908, -1.1962308642954385, 0);
  const PairSolution sol = solve_pair_problem(scene, X, scene.A.find("eA"), scene.B.find("e2"),
                                              PtcType::EETouch, on_eA, apex);
  EXPECT_FALSE(sol.converged);
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
