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

TEST(StressScenes, FarRotatedFileHoldsExample1Moved) {
  const SceneSpec got = load_scene_file(stress_path("example1_far_rotated.yaml"));
  const SceneSpec want = moved_scene(example(1), far_rotation());
  testing::expect_faces_proportional(got.A, want.A, kFileCoefficients);
  testing::expect_faces_proportional(got.B, want.B, kFileCoefficients);
}

// Both length units in one test: three generations of Example 1 (~5 s each on one core).
TEST(StressScaling, Example1AtLengthUnits1eMinus4And1e4AndIllScaledObjects) {
  const Generated ref = generate(example(1));
  for (const char* file : {"example1_scaled_1e-4.yaml", "example1_scaled_1e4.yaml",
                           "example1_ill_scaled_objects.yaml"}) {
    SCOPED_TRACE(file);
    expect_same_graph(generate(load_scene_file(stress_path(file))), ref);
  }
}

// Three generations of Example 2: disabled by default for its run time (one generation took
// 171 s of CPU at the time of writing, beyond the test budget); run it with
// --gtest_also_run_disabled_tests --gtest_filter='*Example2AtLengthUnits*'.
TEST(StressScaling, DISABLED_Example2AtLengthUnits1eMinus4And1e4) {
  const Generated ref = generate(example(2));
  for (const char* file : {"example2_scaled_1e-4.yaml", "example2_scaled_1e4.yaml"}) {
    SCOPED_TRACE(file);
    expect_same_graph(generate(load_scene_file(stress_path(file))), ref);
  }
}

TEST(StressFrames, Example1FarFromTheOriginAndRotated) {
  GTEST_SKIP() << "engine defect (geometry kernel, numerics far from the origin): B's faces "
                  "are evaluated from expanded monomial coefficients in the world frame; "
                  "1.32e5 (1e4 L) from the origin the constant terms reach 1.7e10, a value "
                  "near the surface cancels ~10 digits (g error ~4e-6, distance error ~5e-7 = "
                  "4e-8 L against solve_residual 1e-12 L), and build_scene_geometry throws "
                  "\"the edge where faces f1 and f2 meet: the curve cannot be followed past "
                  "(120001, -50003.9, 19999.2)\". Translation alone fails the same way from "
                  "1e3 L; at 1e2 L it builds, but the graph has 6 CFs (lacking {(fA-f1, 2)}, "
                  "{(fA-e1, 2)}, {(fA-e1, 1), (fA-f1, 1)}; adding {(fA-e1, 1), (fA-f2, 1)}, "
                  "which no convex A can touch) and witness gaps of 6.5e-11 (5e-12 L). The "
                  "rotation alone (t = 0) gives Example 1's 8 CFs, in 8 states against 10.";
  const Generated ref = generate(example(1));
  expect_same_graph(generate(load_scene_file(stress_path("example1_far_rotated.yaml"))), ref);
}

TEST(StressCoefficients, Example1IllScaledWithinB) {
  GTEST_SKIP() << "engine defect (geometry kernel, engine/geometry/surface.cc "
                  "project_onto_curve): the Gauss-Newton step onto the curve g1 = g2 = 0 "
                  "inverts J J^T with unnormalised gradient rows and cuts eigenvalues below "
                  "kPseudoInverseCut times the largest; faces scaled 1e8 apart (f1 x 1e-8 "
                  "against f2 x 1e8) give eigenvalues 1e16 apart, the small one is cut, and "
                  "build_scene_geometry throws \"edge 'e1': faces f1 and f2 never meet on the "
                  "boundary of object B\" (1e6 apart still works). Normalising each row (and "
                  "residual) by its gradient norm would make the step scale-free.";
  const Generated ref = generate(example(1));
  expect_same_graph(generate(load_scene_file(stress_path("example1_ill_scaled.yaml"))), ref);
}

}  // namespace
}  // namespace pcsg
