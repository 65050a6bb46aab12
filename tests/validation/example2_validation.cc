// Validations: long generations of Example 2 (15-45 min of CPU each on this project's 2-core
// machine) against its stored signatures, in the frames and units the suite's stress tests
// check on Example 1. They are not CTest tests: with them the suite outgrew CI's 90 minutes
// (session 42: 9,930 s of CPU). `bash scripts/validate.sh` runs them (a change to the engine's
// motions, events or tolerances should); each result is recorded in docs/performance-history.md.
// The suite keeps Example 2's own frame (Generator.Example2*), and the properties these check
// on Example 1 in every frame (stress_test.cc, metamorphic_test.cc).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../engine/generator/stress_support.h"

namespace pcsg {
namespace {

using testing::generate;
using testing::Generated;
using testing::stress_path;

// Example 2 from `file` (scenes/stress/), against the stored signature `signature`
// (tests/data/signatures/), every witness exact.
void expect_example2_signature(const std::string& file, const std::string& signature,
                               bool complete_search) {
  GeneratorOptions opt;
  opt.complete_search = complete_search;
  const Generated g = generate(load_scene_file(stress_path(file)), opt);
  testing::expect_stored_signature(testing::signature(g.graph, g.scene), signature);
  testing::expect_witnesses_valid(g);
  // With the complete search, as many states of each CF as the own frame (session 50: a
  // failed join shows here, not in the signature).
  if (complete_search)
    testing::expect_stored_state_counts(testing::state_counts(g.graph, g.scene),
                                        signature + "_states");
}

// Example 2 scaled by 1e-4 and by 1e4 (example2_scaled_*.yaml), quick search (the default until
// session 47): Example 2's stored signature. Passed in session 41's CI (~1,300 s each, two threads
// beside another test); before that, from session 9 on, in the suite.
TEST(Validation, Example2AtLengthUnit1eMinus4) {
  expect_example2_signature("example2_scaled_1e-4.yaml", "example2", false);
}

TEST(Validation, Example2AtLengthUnit1e4) {
  expect_example2_signature("example2_scaled_1e4.yaml", "example2", false);
}

// B 1e4 L from the origin and rotated (example2_far_rotated.yaml), quick search: 29 CFs and
// 149 distinct links since session 21 (B's faces parsed about B's origin, brep_builder.cc);
// passed in session 41's CI (1,236 s).
TEST(Validation, Example2FarFromTheOriginAndRotated) {
  expect_example2_signature("example2_far_rotated.yaml", "example2", false);
}

// The same three with the complete search, the default since session 47: Example 2's complete
// signature (example2_complete.txt, 33 CFs and 211 distinct links), as its own frame has it.
TEST(Validation, Example2AtLengthUnit1eMinus4WithTheCompleteSearch) {
  expect_example2_signature("example2_scaled_1e-4.yaml", "example2_complete", true);
}

TEST(Validation, Example2AtLengthUnit1e4WithTheCompleteSearch) {
  expect_example2_signature("example2_scaled_1e4.yaml", "example2_complete", true);
}

// Far and rotated: open in session 48 (1,025 s, two threads, beside the test suite) with one
// link more than the complete signature, {(fA2-e1, 2)} -> {(fA1-e1, 1)}, without its image under
// the lens turned over, a link no LN hypothesis makes. It was the mirror image of
// {(eA-e1, 1), (fA2-e1, 1)} -> {(fA1-e1, 1)}: that state's witness, reflected, read
// {(fA2-e1, 2)} (its lens-rim contact on fA2 beside the rim), and its links were mirrored onto
// a {(fA2-e1, 2)} state. Since session 49 an image counts only where it reads its state's CF
// mapped by the symmetry (Builder::image_at). Passes since (54 states, 648 links, 880,403
// queries; 864 s on one thread beside another run). Its fifth {(fA1-e1, 2)} (the own frame had
// four) was joined in session 50 by the tangent walk (joined_by_tangent_walk), which left both
// frames 49 states, the same number of each CF (878,232 queries here, the walk last).
TEST(Validation, Example2FarFromTheOriginAndRotatedWithTheCompleteSearch) {
  expect_example2_signature("example2_far_rotated.yaml", "example2_complete", true);
}

// Example 2 scaled by 1e-4 with B's frame 1e4 L from the origin and rotated
// (example2_far_rotated_scaled_1e-4.yaml), complete search. Open from session 42 to 48 as
// StressFrames.Example2ScaledBy1eMinus4FarAndRotatedWithTheCompleteSearch (1,767 s, two
// threads, beside a few short tests): all 33 CFs and 211 links, and two links more,
// {(fA2-e1, 2)} -> {(eA-f2, 1)} and {(fA2-e1, 2)} -> {(fA1-e1, 1)}, without their images, links
// no LN hypothesis makes: the mirror images of {(eA-e1, 1), (fA2-e1, 1)} -> {(eA-f2, 1)} and
// -> {(fA1-e1, 1)} through a mirror image read on another CF (above).
TEST(Validation, Example2ScaledBy1eMinus4FarAndRotatedWithTheCompleteSearch) {
  expect_example2_signature("example2_far_rotated_scaled_1e-4.yaml", "example2_complete", true);
}

// B moved by a small rigid motion (example2_moved.yaml) with GeneratorOptions::complete_search:
// the signature of Example 2's own frame with it (example2_complete.txt, 33 CFs and 211 distinct
// links). The quick search has 27 CFs here (StressFrames.Example2MovedByASmallRigidMotion,
// skipped). Passed in session 41's CI (2,425 s, two threads), and in session 44 with its cuts
// of the complete search (1,036 s, two threads, beside another validation). Failed in session
// 52, the first run with the states-per-CF check: 51 states, {(eA-e1, 1), (fA1-f1, 1)} and its
// image 3 states each against the own frame's 2 (498 s). Passes since session 53, whose images
// that no join reaches take their state from the inverse image's join (580 s, two threads).
TEST(Validation, Example2MovedWithTheCompleteSearch) {
  expect_example2_signature("example2_moved.yaml", "example2_complete", true);
}

// The same motion with every length multiplied by 1e4 (example2_moved_scaled_1e4.yaml), complete
// search: the same signature. Passed in session 42 (2,193 s, two threads, beside other tests),
// and in session 44 with its cuts of the complete search (1,163 s, beside the test suite). Failed
// in session 52 as the moved frame above, the same two CFs one state too many (488 s); passes
// since session 53's fix (595 s, two threads).
TEST(Validation, Example2ScaledBy1e4AndMovedWithTheCompleteSearch) {
  expect_example2_signature("example2_moved_scaled_1e4.yaml", "example2_complete", true);
}

// The lens standing on its tip at the bottom of the dish (lens_tip_in_dish.yaml; the seed is
// checked by StressShapes.LensTipSeedTouchesTipOnTip): the LN graph grown from that one contact
// without upward search holds every single contact of the lens with B, the 3 x 5 grid of 15 CFs
// and its 22 adjacent pairs, and the rims crossing in both senses, one state each (17 states).
// The suite checks the same grid on Example 2's own graph
// (Generator.Example2SingleContactsFormTheLensGrid). Passed in session 42 (890 s, two threads).
TEST(Validation, LensTipOnTheDishTip) {
  const testing::LensGrid grid = testing::lens_single_contact_grid();
  ASSERT_EQ(grid.adjacent.size(), 22u);
  std::vector<std::string> states = grid.cfs;
  states.insert(states.end(), {"{(eA-e1, 1)}", "{(eA-e2, 1)}"});
  const Generated g =
      generate(load_scene_file(stress_path("lens_tip_in_dish.yaml")), /*search_upward=*/false);
  ASSERT_EQ(g.graph.states.at(0).cf.str(g.scene), "{(fA1-f1, 1)}");
  std::vector<std::string> singles;
  for (const State& s : g.graph.states)
    if (s.cf.cardinality() == 1) singles.push_back(s.cf.str(g.scene));
  EXPECT_EQ(testing::sorted(singles), testing::sorted(states))
      << "got single-contact states:\n"
      << testing::join(testing::sorted(singles));
  const std::vector<std::string> adj = testing::single_contact_adjacency(g.graph, g.scene);
  EXPECT_EQ(adj, grid.adjacent) << "got adjacency:\n" << testing::join(adj);
  testing::expect_witnesses_valid(g);
  testing::expect_both_crossing_regions(g, "eA-e1");
  testing::expect_both_crossing_regions(g, "eA-e2");
}

}  // namespace
}  // namespace pcsg
