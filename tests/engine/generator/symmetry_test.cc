#include "engine/generator/symmetry.h"

#include <gtest/gtest.h>

#include "engine/generator/state_identity.h"
#include "engine/scene/scene_swap.h"
#include "generator_test_support.h"

namespace pcsg {
namespace {

SceneGeometry scene(const std::string& name) {
  return build_scene_geometry(load_scene_file(testing::scene_path(name)));
}

// Round-off of the axis from a least-squares null vector of O(1) conditions.
constexpr double kAxisTolerance = 1e-9;
// Two exact solves of one contact point (solve residual ~1e-12 of the scene's length, ~10).
constexpr double kSamePoint = 1e-9;

void expect_axis(const std::optional<SymmetryAxis>& axis, const Eigen::Vector3d& point,
                 const Eigen::Vector3d& direction, double length_scale) {
  ASSERT_TRUE(axis.has_value());
  EXPECT_NEAR(std::abs(axis->direction.dot(direction.normalized())), 1.0, kAxisTolerance);
  // The axis passes through `point`: its distance to the line is ~0.
  const Eigen::Vector3d r = point - axis->point;
  EXPECT_NEAR((r - axis->direction * axis->direction.dot(r)).norm(), 0,
              kAxisTolerance * length_scale);
}

// B of the paper's examples is a solid of revolution about z (x and y enter only as
// x^2 + y^2); the lens of Example 2 and the torus too. The ellipsoid (three different
// semi-axes) and the three-sphere lens (a three-fold symmetry only) are not.
TEST(Symmetry, AxesOfTheShippedScenes) {
  const SceneGeometry ex1 = scene("example1.yaml"), ex2 = scene("example2.yaml");
  const SceneGeometry torus = scene("torus.yaml"), three = scene("three_spheres.yaml");
  const double L = ex1.tol.length_scale;
  expect_axis(axis_of_revolution(ex1.B, ex1.tol), {0, 0, 0}, {0, 0, 1}, L);
  EXPECT_FALSE(axis_of_revolution(ex1.A, ex1.tol).has_value());
  expect_axis(axis_of_revolution(ex2.A, ex2.tol), {0, 0, 0}, {0, 0, 1}, L);
  expect_axis(axis_of_revolution(torus.A, torus.tol), {0, 0, 0}, {0, 0, 1}, L);
  EXPECT_FALSE(axis_of_revolution(three.A, three.tol).has_value());
}

// The axis moves with B and scales with the scene.
TEST(Symmetry, AxisFollowsScalingAndRigidMotion) {
  const SceneSpec spec = load_scene_file(testing::scene_path("example1.yaml"));
  Pose X;
  X.position = {3.0, -2.0, 5.0};
  X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 2).normalized()));
  const SceneGeometry moved = build_scene_geometry(moved_scene(spec, X));
  expect_axis(axis_of_revolution(moved.B, moved.tol), X.position, X.rotate({0, 0, 1}),
              moved.tol.length_scale);
  for (double s : {1e-3, 1e3}) {
    const SceneGeometry scaled = build_scene_geometry(scaled_scene(spec, s));
    expect_axis(axis_of_revolution(scaled.B, scaled.tol), {0, 0, 0}, {0, 0, 1},
                scaled.tol.length_scale);
  }
}

// Turning a witness about B's axis keeps its contacts exactly (the point of the symmetry).
TEST(Symmetry, TurningAboutBsAxisKeepsTheContacts) {
  const SceneGeometry ex2 = scene("example2.yaml");
  const SceneSymmetry sym = SceneSymmetry::of(ex2);
  ASSERT_TRUE(sym.B && sym.A);
  // A witness of {(eA-f1, 1)} from a run of the generator: the lens's rim on the dish.
  const Pose w = parse_pose(
      "-0.24660227524736344 0.93589654115046006 1.1693264145690472 0.5389870201911241 "
      "-0.54072412486306964 -0.092215921983104313 -0.6392234637349965");
  ASSERT_EQ(ContactFormation::of(detect_contacts(ex2, w).contacts).str(ex2), "{(eA-f1, 1)}");
  for (double angle : {0.5, 2.0, -2.9}) {
    for (const Pose& t : {turned_about_B(w, *sym.B, angle),
                          turned_about_A(w, *sym.A, angle)}) {
      const ContactReport rep = detect_contacts(ex2, t);
      EXPECT_FALSE(rep.penetrating());
      EXPECT_EQ(ContactFormation::of(rep.contacts).str(ex2), "{(eA-f1, 1)}");
      for (const PointContact& c : rep.contacts)
        EXPECT_LE(std::abs(c.gap), ex2.tol.contact_gap);
    }
  }
}

// The ellipsoid's three axes are half-turn axes (x, y, z each enter squared); the torus's x
// and y axes too (its z axis, of revolution, is left out: the continuous turn covers it).
// The lens's half turns exchange its caps fA1 and fA2, and the three-sphere lens's exchange
// two spheres: none maps every element onto itself.
TEST(Symmetry, HalfTurnAxesOfTheShippedScenes) {
  const SceneGeometry ex1 = scene("example1.yaml"), ex2 = scene("example2.yaml");
  const SceneGeometry torus = scene("torus.yaml"), three = scene("three_spheres.yaml");
  auto directions = [](const SceneGeometry& g) {
    std::vector<Eigen::Vector3d> out;
    for (const SymmetryAxis& h : SceneSymmetry::of(g).half_turns_A) {
      EXPECT_LE(h.point.norm(), g.tol.distinct_points);
      out.push_back(h.direction);
    }
    return out;
  };
  const std::vector<Eigen::Vector3d> e1 = directions(ex1), t = directions(torus);
  ASSERT_EQ(e1.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(e1[k], Eigen::Vector3d::Unit(k));
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0], Eigen::Vector3d::UnitX());
  EXPECT_EQ(t[1], Eigen::Vector3d::UnitY());
  EXPECT_TRUE(directions(ex2).empty());
  EXPECT_TRUE(directions(three).empty());
  // B of every shipped scene, the bowl, has none (a half turn across its axis turns it
  // over); swapped, the ellipsoid is B and its three axes serve there.
  EXPECT_TRUE(SceneSymmetry::of(ex1).half_turns_B.empty());
  const SceneGeometry swapped = build_scene_geometry(
      swap_objects(load_scene_file(testing::scene_path("example1.yaml"))));
  const SceneSymmetry sym = SceneSymmetry::of(swapped);
  EXPECT_TRUE(sym.half_turns_A.empty());
  EXPECT_EQ(sym.half_turns_B.size(), 3u);
}

// Half turns that exchange elements: Example 2's lens turned upside down about x or y through
// its centre (fA1 <-> fA2, its rim onto itself), the three-sphere lens about the axis through
// its two vertices (spheres 2 and 3 exchanged); none for the ellipsoid, whose half turns keep
// every element, nor for the bowl.
TEST(Symmetry, RelabellingHalfTurnsOfTheShippedScenes) {
  const SceneGeometry ex1 = scene("example1.yaml"), ex2 = scene("example2.yaml");
  const SceneGeometry three = scene("three_spheres.yaml");
  EXPECT_TRUE(SceneSymmetry::of(ex1).relabelling_A.empty());
  const SceneSymmetry s2 = SceneSymmetry::of(ex2);
  ASSERT_EQ(s2.relabelling_A.size(), 2u);
  EXPECT_EQ(s2.relabelling_A[0].direction, Eigen::Vector3d::UnitX());
  EXPECT_EQ(s2.relabelling_A[1].direction, Eigen::Vector3d::UnitY());
  EXPECT_TRUE(s2.relabelling_B.empty());
  const SceneSymmetry s3 = SceneSymmetry::of(three);
  ASSERT_EQ(s3.relabelling_A.size(), 1u);
  EXPECT_EQ(s3.relabelling_A[0].direction, Eigen::Vector3d::UnitY());
  // The turn is a symmetry: a witness and its turned pose touch with the same points in B's
  // frame, the lens's faces exchanged.
  // (a witness of {(fA1-f2, 1)} from an Example 2 run: the lens's lower cap on the band)
  Pose X;
  X.position = {2.7713575129415453, -3.6917931604822436, 3.6994016746080214};
  X.quaternion = Eigen::Quaterniond(0.9509975793710119, 0.21414117258639462, 0.19765917043229464,
                                    -0.10333447913362272);
  const ContactReport a = detect_contacts(ex2, X);
  const ContactReport b = detect_contacts(ex2, turned_about_A(X, s2.relabelling_A[0], M_PI));
  ASSERT_EQ(a.contacts.size(), 1u);
  ASSERT_EQ(b.contacts.size(), 1u);
  EXPECT_NEAR((a.contacts[0].point_B - b.contacts[0].point_B).norm(), 0, kSamePoint);
  EXPECT_EQ(ex2.A.element_name(a.contacts[0].a), "fA1");
  EXPECT_EQ(ex2.A.element_name(b.contacts[0].a), "fA2");
  EXPECT_EQ(ex2.B.element_name(b.contacts[0].b), "f2");
}

// Where the symmetries put the elements: the lens turned over exchanges its caps and keeps
// its rim, and so does its equatorial mirror; its planes through the axis and the bowl's keep
// every element. A CF's image follows the map ({(fA1-e1, 1)} turned over is {(fA2-e1, 1)}),
// so that a re-detected image reading another CF (a witness on its region's boundary) can be
// told from the state's image (Builder::image_at).
TEST(Symmetry, ElementMapsOfTheShippedScenes) {
  const SceneGeometry ex2 = scene("example2.yaml");
  const SceneSymmetry s2 = SceneSymmetry::of(ex2);
  const Solid& A = ex2.A;
  auto name = [&](const ElementMap& m, const char* element) {
    return A.element_name(m(A.find(element)));
  };
  ASSERT_EQ(s2.relabelling_A_elements.size(), s2.relabelling_A.size());
  for (const ElementMap& m : s2.relabelling_A_elements) {
    EXPECT_EQ(name(m, "fA1"), "fA2");
    EXPECT_EQ(name(m, "fA2"), "fA1");
    EXPECT_EQ(name(m, "eA"), "eA");
    EXPECT_FALSE(m.identity());
  }
  ASSERT_EQ(s2.mirror_A_elements.size(), 3u);
  int exchanging = 0;
  for (const ElementMap& m : s2.mirror_A_elements) {
    exchanging += m.identity() ? 0 : 1;
    EXPECT_EQ(name(m, "eA"), "eA");
  }
  EXPECT_EQ(exchanging, 1);  // the equatorial plane
  // the plane mirror_image uses
  EXPECT_TRUE(s2.mirror_A_elements[0].identity());
  ASSERT_EQ(s2.mirror_B_elements.size(), s2.mirrors_B.size());
  for (const ElementMap& m : s2.mirror_B_elements) EXPECT_TRUE(m.identity());
  const ContactFormation cf = ContactFormation::parse("{(fA1-e1, 2), (fA1-f1, 1)}", ex2);
  EXPECT_EQ(image_cf(cf, &s2.relabelling_A_elements[0], nullptr).str(ex2),
            "{(fA2-e1, 2), (fA2-f1, 1)}");
  EXPECT_EQ(image_cf(cf, &s2.mirror_A_elements[0], &s2.mirror_B_elements[0]), cf);
  // Example 1: the ellipsoid and the dish move no element under any of their symmetries.
  const SceneSymmetry s1 = SceneSymmetry::of(scene("example1.yaml"));
  for (const ElementMap& m : s1.mirror_A_elements) EXPECT_TRUE(m.identity());
  for (const ElementMap& m : s1.mirror_B_elements) EXPECT_TRUE(m.identity());
  EXPECT_TRUE(s1.relabelling_A_elements.empty());
}

// Planes of mirror symmetry: the ellipsoid's three principal planes; the bowl's planes
// through its axis (both coordinate planes holding z are found, no more); the lens's too, and
// its equatorial plane (which exchanges its caps). Moving B moves its planes with it.
TEST(Symmetry, MirrorPlanesOfTheShippedScenes) {
  const SceneGeometry ex1 = scene("example1.yaml"), ex2 = scene("example2.yaml");
  const SceneSymmetry s1 = SceneSymmetry::of(ex1);
  ASSERT_EQ(s1.mirrors_A.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(std::abs(s1.mirrors_A[k].normal.dot(Eigen::Vector3d::Unit(k))), 1, 1e-12);
    EXPECT_LE(s1.mirrors_A[k].point.norm(), ex1.tol.distinct_points);
  }
  ASSERT_EQ(s1.mirrors_B.size(), 2u);
  for (const MirrorPlane& m : s1.mirrors_B) {
    EXPECT_NEAR(m.normal.z(), 0, kAxisTolerance);  // the plane holds B's axis, z
    EXPECT_LE(m.point.head<2>().norm(), kAxisTolerance * ex1.tol.length_scale);
  }
  EXPECT_EQ(SceneSymmetry::of(ex2).mirrors_A.size(), 3u);
  // B moved rigidly: its two planes still hold its (moved) axis.
  const SceneSpec spec = load_scene_file(testing::scene_path("example1.yaml"));
  Pose X;
  X.position = {3.0, -2.0, 5.0};
  X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 2).normalized()));
  const SceneGeometry moved = build_scene_geometry(moved_scene(spec, X));
  const std::vector<MirrorPlane> planes = SceneSymmetry::of(moved).mirrors_B;
  ASSERT_EQ(planes.size(), 2u);
  for (const MirrorPlane& m : planes) {
    EXPECT_NEAR(m.normal.dot(X.rotate({0, 0, 1})), 0, kAxisTolerance);
    EXPECT_NEAR(m.normal.dot(m.point - X.position), 0, kAxisTolerance * moved.tol.length_scale);
  }
}

// The mirror image of a configuration touches B at the mirror images of its contact points,
// on the same elements, with nothing else: Example 1's witness of {(fA-e1, 1), (fA-f1, 1)}
// (the ellipsoid across the dish, resting on the rim at one end and on the wall at the other).
// Reflecting twice gives the pose back.
TEST(Symmetry, MirroredWitnessTouchesAtTheMirroredPoints) {
  const SceneGeometry ex1 = scene("example1.yaml");
  const SceneSymmetry sym = SceneSymmetry::of(ex1);
  ASSERT_FALSE(sym.mirrors_A.empty());
  ASSERT_FALSE(sym.mirrors_B.empty());
  const Pose w = parse_pose(
      "-1.6051845970692638 0.062473738619869046 2.1463896956523372 0.32220403692657712 "
      "-0.24932582355730321 0.7620407517878649 0.50330416738814643");
  const ContactReport a = detect_contacts(ex1, w);
  ASSERT_EQ(ContactFormation::of(a.contacts).str(ex1), "{(fA-e1, 1), (fA-f1, 1)}");
  for (const MirrorPlane& in_A : sym.mirrors_A) {
    const Pose m = mirrored(w, in_A, sym.mirrors_B[0]);
    const ContactReport b = detect_contacts(ex1, m);
    EXPECT_FALSE(b.penetrating());
    ASSERT_EQ(b.contacts.size(), 2u);
    for (const PointContact& c : a.contacts) {
      const Eigen::Vector3d image = sym.mirrors_B[0].reflect(c.point_B);
      bool found = false;
      for (const PointContact& d : b.contacts)
        found = found || (d.b == c.b && d.a == c.a && (d.point_B - image).norm() <= kSamePoint);
      EXPECT_TRUE(found) << ex1.B.element_name(c.b);
    }
    const Pose back = mirrored(m, in_A, sym.mirrors_B[0]);
    EXPECT_NEAR((back.position - w.position).norm(), 0, 1e-12 * ex1.tol.length_scale);
    EXPECT_NEAR(back.quaternion.angularDistance(w.quaternion), 0, 1e-12);
  }
}

// Two witnesses of {(fA-e1, 2)} (the ellipsoid across the rim) that Example 1's run reached
// from {(fA-f1, 2)} and from {(fA-e1, 1), (fA-f1, 1)}: they differ by about a half turn about
// the ellipsoid's long axis (z), and the joining test proves them one state by a travel
// toward the second turned by pi (docs/paper-comparison.md).
TEST(Symmetry, HalfTurnJoinsExample1sTwoRimWitnesses) {
  const SceneGeometry ex1 = scene("example1.yaml");
  const Pose a = parse_pose(
      "-1.2458376367372204 1.4932461536876056 2.770980613225761 0.4727947445479537 "
      "0.10082561465575791 0.699850742423232 0.5258405302815436");
  const Pose b = parse_pose(
      "-1.35671726510476 1.7453745777250886 3.163909075691247 0.6906250200450014 "
      "-0.602534669516488 0.1981324817804587 -0.3474659312537192");
  const ContactFormation cf = ContactFormation::of(detect_contacts(ex1, a).contacts);
  ASSERT_EQ(cf.str(ex1), "{(fA-e1, 2)}");
  ASSERT_TRUE(ContactFormation::of(detect_contacts(ex1, b).contacts) == cf);
  MotionCounters counters;
  EXPECT_TRUE(joined_within_cf(ex1, a, b, cf, counters, SceneSymmetry::of(ex1)));
}

}  // namespace
}  // namespace pcsg
