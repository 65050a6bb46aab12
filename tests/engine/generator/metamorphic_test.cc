// Metamorphic test: swapping A and B (engine/scene/scene_swap.h) gives the mirrored graph.
// Every PtC alpha_A-alpha_B becomes alpha_B-alpha_A with the mirrored type (f-e <-> e-f,
// f-v <-> v-f, e-v <-> v-e), and a motion that keeps A's contact points (slidingA) keeps the
// new B's (slidingB).
#include <gtest/gtest.h>

#include <map>

#include "engine/scene/scene_swap.h"
#include "stress_support.h"

namespace pcsg {
namespace {

using testing::Generated;
using testing::example1;
using testing::generate;

PtcType mirrored(PtcType t) {
  switch (t) {
    case PtcType::FE: return PtcType::EF;
    case PtcType::EF: return PtcType::FE;
    case PtcType::FV: return PtcType::VF;
    case PtcType::VF: return PtcType::FV;
    case PtcType::EV: return PtcType::VE;
    case PtcType::VE: return PtcType::EV;
    default: return t;  // f-f, e-e-cross, e-e-touch, v-v are symmetric
  }
}

// A CF of the swapped scene written in the original scene's elements and notation.
std::string mirrored_cf(const ContactFormation& cf, const SceneGeometry& swapped,
                        const SceneGeometry& original) {
  ContactFormation out;
  for (const PtcCount& e : cf.entries()) {
    const ElementId a = original.A.find(swapped.B.element_name(e.b));
    const ElementId b = original.B.find(swapped.A.element_name(e.a));
    EXPECT_GE(a.index, 0) << swapped.B.element_name(e.b);
    EXPECT_GE(b.index, 0) << swapped.A.element_name(e.a);
    if (a.index < 0 || b.index < 0) return "?";
    out.add(a, b, mirrored(e.type), e.count);
  }
  return out.str(original);
}

// "slidingA" <-> "slidingB" in a motion name ("slidingA+rotation", ...).
std::string mirrored_motion(std::string m) {
  for (char& c : m) {
    if (&c > m.data() + 6 && std::string_view(&c - 7, 7) == "sliding" && (c == 'A' || c == 'B'))
      c = c == 'A' ? 'B' : 'A';
  }
  return m;
}

TEST(Metamorphic, MirroredMotionNamesSwapSlidingAAndB) {
  EXPECT_EQ(mirrored_motion("slidingA+rotation"), "slidingB+rotation");
  EXPECT_EQ(mirrored_motion("slidingB"), "slidingA");
  EXPECT_EQ(mirrored_motion("combined+rotation@+45deg"), "combined+rotation@+45deg");
}

// The swapped scene's graph, mirrored, against the original's: the same states (with
// repeats) and the same adjacent pairs.
// With `motion_families`, also the sliding motions of each pair mirrored (which in general
// holds only from the same seed poses on both sides: see SwappedSlidingMotionsAreMirrored).
void expect_mirrored(const Generated& original, const Generated& swapped,
                     bool motion_families = true) {
  testing::expect_witnesses_valid(swapped);

  // the states, by their mirrored CFs (with repeats)
  std::vector<std::string> want, got;
  for (const State& s : original.graph.states) want.push_back(s.cf.str(original.scene));
  for (const State& s : swapped.graph.states)
    got.push_back(mirrored_cf(s.cf, swapped.scene, original.scene));
  EXPECT_EQ(testing::sorted(got), testing::sorted(want)) << "got:\n" << testing::join(got);

  // the links, as unordered mirrored pairs, and the motions that made them, mirrored
  std::map<std::string, std::vector<std::string>> want_links, got_links;
  for (const Link& l : original.graph.links)
    if (l.kind == LinkKind::LN)
      want_links[testing::adjacent_pair(original.graph.states[l.from].cf.str(original.scene),
                                        original.graph.states[l.to].cf.str(original.scene))]
          .push_back(l.motion);
  for (const Link& l : swapped.graph.links)
    if (l.kind == LinkKind::LN)
      got_links[testing::adjacent_pair(
                    mirrored_cf(swapped.graph.states[l.from].cf, swapped.scene, original.scene),
                    mirrored_cf(swapped.graph.states[l.to].cf, swapped.scene, original.scene))]
          .push_back(mirrored_motion(l.motion));
  std::vector<std::string> want_pairs, got_pairs;
  for (const auto& [pair, motions] : want_links) want_pairs.push_back(pair);
  for (const auto& [pair, motions] : got_links) got_pairs.push_back(pair);
  EXPECT_EQ(got_pairs, want_pairs) << "got:\n" << testing::join(got_pairs);
  if (!motion_families) return;
  // each pair joined by a sliding motion on one side is joined by the mirrored one on the
  // other: the motion families correspond (the variant tried first may differ)
  for (const auto& [pair, motions] : want_links) {
    const auto it = got_links.find(pair);
    if (it == got_links.end()) continue;
    auto family = [](const std::vector<std::string>& ms, const char* f) {
      return std::any_of(ms.begin(), ms.end(),
                         [&](const std::string& m) { return m.find(f) != std::string::npos; });
    };
    for (const char* f : {"slidingA", "slidingB"})
      EXPECT_EQ(family(it->second, f), family(motions, f)) << pair << ": " << f;
  }
}

// The two lenses' original graph, read by two tests, generated once per process
// (tests/CMakeLists.txt runs the pair in one process; Example 1's: testing::example1).
SceneSpec two_lenses_spec() {
  SceneSpec spec = load_scene_file(testing::stress_path("collinear_edges.yaml"));
  spec.auto_seeds = true;  // the nine single contacts (stress_edges_test.cc)
  spec.seeds.clear();
  return spec;
}

const Generated& two_lenses() {
  static const Generated g = generate(two_lenses_spec());
  return g;
}

// A lens (faces fS, fC, edge eA) against a ball: three states, e-f becomes f-e.
TEST(Metamorphic, SwappingAAndBMirrorsTheLensOnBallGraph) {
  const SceneSpec spec = load_scene_file(testing::stress_path("weak_edge_sine_0.1.yaml"));
  const Generated original = generate(spec), swapped = generate(swap_objects(spec));
  ASSERT_EQ(original.graph.states.size(), 3u);
  expect_mirrored(original, swapped);
}

// Skipped from session 6 to session 25 (an open defect of state identity near the rims'
// touch): the swapped run held {(eA-eB, 1)} three times against the original's two, a third
// region of crossing sign + with its witness 1e-6 from the rims' symmetric touch point
// (0.7071, 0.7071, 0) not joined to the other + state. Re-measured in session 26: both runs
// hold the same states and distinct links, mirrored.
TEST(Metamorphic, SwappingAAndBMirrorsTheTwoLensGraph) {
  expect_mirrored(two_lenses(), generate(swap_objects(two_lenses_spec())),
                  /*motion_families=*/false);
}

// Two generations of Example 1, the swapped one the slower (the bowl is then A): ~200 s of
// CPU. Skipped from session 6 to session 25: the swapped run found the 3-contact state
// {(fA-e1, 2), (fA-f1, 1)} (the ellipsoid across the rim and against the wall; since session
// 17 in both hands, 11 states, 58 links) through a new contact met on a motion from
// {(fA-e1, 1), (fA-f1, 1)}, which the original's motions never reach; the original had 9
// states. Since session 26 the upward projections (GeneratorOptions::project_upward, now on by
// default) find it in the original, and both runs hold the same states and links, mirrored.
TEST(Metamorphic, SwappingAAndBMirrorsExample1sGraph) {
  const SceneSpec spec = load_scene_file(testing::scene_path("example1.yaml"));
  expect_mirrored(example1(), generate(swap_objects(spec)), /*motion_families=*/false);
}

// The scene with its seeds listed: the seed states' witnesses of a generated graph.
SceneSpec with_seeds_of(SceneSpec spec, const StateGraph& graph) {
  spec.auto_seeds = false;
  spec.seeds.clear();
  for (const State& s : graph.states)
    if (s.seed) spec.seeds.push_back(SeedSpec{s.pose, {}});
  return spec;
}

// The motion that proves a link, mirrored: sliding A in one scene is sliding B in the swapped
// one (issue 8). The motions are discretised about the smaller object (twist_frame.h's
// ReferenceBody), the same whichever is called A, so the swapped run, started from the
// original's seed poses (inverted by swap_objects), steps through the mirrored motions and
// meets the mirrored events. The seed search (seeds.cc) places A around B and is not
// mirror-symmetric: with automatic seeds on both sides the witnesses differ, and from the
// swapped witness of {(fA-e1, 1), (fA-f1, 1)} slidingB reaches {(fA-e1, 2)} where from the
// original's only combined does. Skipped from session 5 to session 28, when A was the twists'
// origin and scale (in the swapped run the bowl's, 2.1 times the ellipsoid's): then
// {(fA-e1, 2)} -- {(fA-f1, 2)} was proved by slidingA in the original, combined in the mirror.
TEST(Metamorphic, SwappedSlidingMotionsAreMirrored) {
  const SceneSpec spec = load_scene_file(testing::scene_path("example1.yaml"));
  const Generated& original = example1();
  expect_mirrored(original, generate(swap_objects(with_seeds_of(spec, original.graph))));
}

// The two lenses (edges against edges) with their seeds listed the same way: the sliding
// motions mirror too. With automatic seeds on both sides they do not, measured in session 29:
// {(eA-eB, 1)} -- {(eA-fB1, 1)} and -- {(eA-fB2, 1)} are sliding on one side, combined on the
// other (SwappingAAndBMirrorsTheTwoLensGraph compares states and links only).
TEST(Metamorphic, SwappedSlidingMotionsAreMirroredForTheTwoLenses) {
  const Generated& original = two_lenses();
  expect_mirrored(original,
                  generate(swap_objects(with_seeds_of(two_lenses_spec(), original.graph))));
}

}  // namespace
}  // namespace pcsg
