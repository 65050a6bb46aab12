// Validations of pcsg's own scenes in other units and frames: the torus (scenes/torus.yaml) and
// the three-sphere lens (scenes/three_spheres.yaml), each in B's paper body. Each generation is
// compared with the scene's own-frame graph generated in the same process (one to four minutes
// per generation on two threads), so no stored signature can go stale. The suite checks the own
// frames (TorusGraph, ThreeSpheresGraph); the paper's examples have their invariance tests in the
// suite (Generator.Example1*, Metamorphic.*) and validations (example2_validation.cc).
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "../engine/generator/stress_support.h"

namespace pcsg {
namespace {

using testing::Generated;

// The own frame's graph of scenes/<file>, generated once per process.
const Generated& own_frame(const std::string& file) {
  static std::map<std::string, Generated> cache;
  auto it = cache.find(file);
  if (it == cache.end())
    it = cache
             .emplace(file, testing::generate(load_scene_file(testing::scene_path(file)),
                                              GeneratorOptions{}))
             .first;
  return it->second;
}

// The same distinct CFs, distinct links and number of states of each CF as the own frame of
// scenes/<file>, and every witness exact; a difference is listed by what only one side has.
void expect_own_frames_graph(const std::string& file, const Generated& g) {
  const Generated& own = own_frame(file);
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

void expect_scaled_like_own_frame(const std::string& file, double unit) {
  expect_own_frames_graph(
      file, testing::generate(scaled_scene(load_scene_file(testing::scene_path(file)), unit),
                              GeneratorOptions{}));
}

void expect_moved_like_own_frame(const std::string& file, const std::string& moved_file) {
  expect_own_frames_graph(file, testing::generate(load_scene_file(testing::stress_path(moved_file)),
                                                  GeneratorOptions{}));
}

// Failed when added (session 65): the own frame's ring-contact states (below) were missing,
// {(fA-e2, 2), (fA-f2, 1)} (two states) and {(fA-e2, 2), (fA-f2, 2)} with their 8 distinct links;
// the other 12 states and their links agreed. Passes since no witness touches along a curve.
TEST(Validation, TorusAtLengthUnit1eMinus3) { expect_scaled_like_own_frame("torus.yaml", 1e-3); }

TEST(Validation, TorusAtLengthUnit1e3) { expect_scaled_like_own_frame("torus.yaml", 1e3); }

// Failed when added (session 65): 13 states and 66 links against the own frame's 15 and 80
// (the same with detection's solves capped at 30 or 50 iterations). The own frame's
// {(fA-e2, 2), (fA-f2, 1)} (two states) and {(fA-e2, 2), (fA-f2, 2)} were missing and
// {(fA-e1, 2), (fA-f2, 1)} new. At the witnesses of all four the torus's axis passed through
// the centre of B's sphere band f2 and the tube touched f2 along an arc (relative curvature
// zero to round-off): ring contacts, not point contacts, whose reported points depend on the
// frame (docs/paper-comparison.md, "The torus in other frames and units"). Passes since no
// witness touches along a curve (Tolerances::ring_curvature): 12 states, 58 links.
TEST(Validation, TorusMovedByASmallRigidMotion) {
  expect_moved_like_own_frame("torus.yaml", "torus_moved.yaml");
}

// The three-sphere lens (46 states, 296 links in its own frame): at 1e-3 and 1e3 the same
// states and links (session 66, 63 s and 32 s on two threads).
TEST(Validation, ThreeSpheresAtLengthUnit1eMinus3) {
  expect_scaled_like_own_frame("three_spheres.yaml", 1e-3);
}

TEST(Validation, ThreeSpheresAtLengthUnit1e3) {
  expect_scaled_like_own_frame("three_spheres.yaml", 1e3);
}

// Fails (since added, session 66): the same 46 states, but 280 links against 296, and of the
// links between a lens face on B's upper rim and a lens vertex on it ({(s_i-e1, 1)} <->
// {(v123-e1, 1)} and the upper vertex's) the own frame has s1's and s2's, this frame s3's; and
// {(v123-e1, 1)} <-> {(v123-f2, 1)} there, {(v123-e2, 1)} <-> {(v123-f2, 1)} here. By the lens's
// three-fold symmetry every one of these links exists; each frame proves some by a single
// feasible candidate among many that slide off the rim or reach an edge next to the vertex
// first, and the generator's symmetry closure knows half turns and mirrors, not a three-fold
// turn. Incompleteness of the generator, decided by round-off (docs/paper-comparison.md).
TEST(Validation, ThreeSpheresMovedByASmallRigidMotion) {
  expect_moved_like_own_frame("three_spheres.yaml", "three_spheres_moved.yaml");
}

}  // namespace
}  // namespace pcsg
