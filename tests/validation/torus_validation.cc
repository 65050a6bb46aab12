// Validations of the torus (scenes/torus.yaml) in other units and frames: each generation is
// compared with the torus's own-frame graph generated in the same process (about 2 minutes per
// generation on two threads), so no stored signature can go stale. The suite checks the own
// frame (TorusGraph); the paper's examples have their invariance tests in the suite
// (Generator.Example1*, Metamorphic.*) and validations (example2_validation.cc).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../engine/generator/stress_support.h"

namespace pcsg {
namespace {

using testing::Generated;

const Generated& own_frame() {
  static const Generated g =
      testing::generate(load_scene_file(testing::scene_path("torus.yaml")), GeneratorOptions{});
  return g;
}

// The same distinct CFs, distinct links and number of states of each CF as the own frame, and
// every witness exact; a difference is listed by what only one side has.
void expect_own_frames_graph(const Generated& g) {
  const Generated& own = own_frame();
  const testing::GraphSignature want = testing::signature(own.graph, own.scene);
  const testing::GraphSignature have = testing::signature(g.graph, g.scene);
  EXPECT_TRUE(have.states == want.states)
      << "states only here:\n"
      << testing::join(testing::only_in(have.states, want.states))
      << "states only in the own frame:\n"
      << testing::join(testing::only_in(want.states, have.states));
  EXPECT_TRUE(have.links == want.links)
      << "links only here:\n"
      << testing::join(testing::only_in(have.links, want.links)) << "links only in the own frame:\n"
      << testing::join(testing::only_in(want.links, have.links));
  std::vector<std::string> counts = testing::state_counts(g.graph, g.scene);
  std::vector<std::string> own_counts = testing::state_counts(own.graph, own.scene);
  EXPECT_TRUE(counts == own_counts)
      << "counts only here:\n"
      << testing::join(testing::only_in(counts, own_counts)) << "counts only in the own frame:\n"
      << testing::join(testing::only_in(own_counts, counts));
  testing::expect_witnesses_valid(g);
}

// Failed when added (session 65): the own frame's ring-contact states (below) were missing,
// {(fA-e2, 2), (fA-f2, 1)} (two states) and {(fA-e2, 2), (fA-f2, 2)} with their 8 distinct links;
// the other 12 states and their links agreed. Passes since no witness touches along a curve.
TEST(Validation, TorusAtLengthUnit1eMinus3) {
  expect_own_frames_graph(testing::generate(
      scaled_scene(load_scene_file(testing::scene_path("torus.yaml")), 1e-3), GeneratorOptions{}));
}

TEST(Validation, TorusAtLengthUnit1e3) {
  expect_own_frames_graph(testing::generate(
      scaled_scene(load_scene_file(testing::scene_path("torus.yaml")), 1e3), GeneratorOptions{}));
}

// Failed when added (session 65): 13 states and 66 links against the own frame's 15 and 80
// (the same with detection's solves capped at 30 or 50 iterations). The own frame's
// {(fA-e2, 2), (fA-f2, 1)} (two states) and {(fA-e2, 2), (fA-f2, 2)} were missing and
// {(fA-e1, 2), (fA-f2, 1)} new. At the witnesses of all four the torus's axis passed through
// the centre of B's sphere band f2 and the tube touched f2 along an arc (relative curvature
// zero to round-off): ring contacts, not point contacts, whose reported points depend on the
// frame (docs/paper-comparison.md, "The torus in other frames and units"). Passes since no
// witness touches along a curve (Tolerances::ring_curvature): 12 states, 58 links.
TEST(Validation, TorusMovedByASmallRigidMotion) {
  expect_own_frames_graph(testing::generate(
      load_scene_file(testing::stress_path("torus_moved.yaml")), GeneratorOptions{}));
}

}  // namespace
}  // namespace pcsg
