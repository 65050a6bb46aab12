#include "engine/generator/state_identity.h"

#include <gtest/gtest.h>

#include "engine/scene/scene_swap.h"
#include "generator_test_support.h"

namespace pcsg {
namespace {

Pose pose(double x, double y, double z, double qw, double qx, double qy, double qz) {
  Pose X;
  X.position = {x, y, z};
  X.quaternion = Eigen::Quaterniond(qw, qx, qy, qz);
  return X;
}

// Joins `a` and `b`, two witnesses of one CF and region signature, through the roadmap; checks
// first that both are witnesses of that CF (exact detection, no penetration).
void expect_roadmap_joins(const SceneGeometry& scene, const Pose& a, const Pose& b) {
  const ContactReport ra = detect_contacts(scene, a), rb = detect_contacts(scene, b);
  ASSERT_FALSE(ra.penetrating());
  ASSERT_FALSE(rb.penetrating());
  const ContactFormation cf = ContactFormation::of(ra.contacts);
  ASSERT_TRUE(ContactFormation::of(rb.contacts) == cf) << cf.str(scene);
  ASSERT_EQ(region_signature(ra.contacts), region_signature(rb.contacts));
  MotionCounters counters;
  RoadmapStats stats;
  EXPECT_TRUE(joined_by_roadmap(scene, a, b, cf, region_signature(ra.contacts), counters, &stats))
      << stats.nodes << " nodes, " << stats.motions << " motions";
  // Not by the two witnesses alone: through sampled nodes.
  EXPECT_GT(stats.nodes, 2);
  // Run with two threads (a batch of edges at a time, the later ones of a batch dropped
  // when an earlier one joins their ends): the same roadmap, motions and counters.
  MotionCounters counters2;
  RoadmapStats stats2;
  EXPECT_TRUE(joined_by_roadmap(scene, a, b, cf, region_signature(ra.contacts), counters2, &stats2,
                                /*threads=*/2));
  EXPECT_EQ(stats2.nodes, stats.nodes);
  EXPECT_EQ(stats2.motions, stats.motions);
  EXPECT_EQ(counters2.detections, counters.detections);
  EXPECT_EQ(counters2.pair_solves, counters.pair_solves);
  EXPECT_EQ(counters2.steps, counters.steps);
}

// Example 1 with A and B swapped held {(e1-fA, 1), (f1-fA, 1)} twice (session 13): the rim
// and dish wall contacts 4.2 apart (state 1), and 0.05 apart on either side of the rim (state
// 9, next to the 3-contact state {(e1-fA, 2), (f1-fA, 1)}). Every
// join of the generation (straight, through midpoints, along the contact's parameters) failed;
// the roadmap joins them (measured: 11 nodes, 21 motions).
TEST(StateIdentity, RoadmapJoinsExample1SwappedsTwoRimAndWallWitnesses) {
  const SceneGeometry scene =
      build_scene_geometry(swap_objects(load_scene_file(testing::scene_path("example1.yaml"))));
  expect_roadmap_joins(
      scene,
      pose(0.165957885048531, -2.1117654854645274, -1.4822339955325352, 0.7304750807591127,
           -0.49777347982211567, 0.09249943856522658, -0.45833565543263993),
      pose(-0.5848871571877374, -2.991979097004453, -1.804062826181004, 0.6762704114951521,
           -0.5262491936025655, 0.1568705729897572, -0.49103130256501204));
}

// The needle in the dish (stress scene) held {(fA-e1, 1), (fA-f1, 1)} twice, witnesses with
// centres 3.6 apart that no join of the generation reached (measured: the roadmap joins them
// with 21 nodes, 31 motions).
TEST(StateIdentity, RoadmapJoinsTheNeedlesTwoRimAndWallWitnesses) {
  const SceneGeometry scene = build_scene_geometry(
      load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/stress/needle_in_dish.yaml"));
  expect_roadmap_joins(
      scene,
      pose(-1.4201245785527112, 0.6248458746360905, 1.5863419234474048, 0.37789276973307423,
           -0.004536403639454959, 0.8185200806156546, 0.4326677169080541),
      pose(-2.4568073877961267, -2.4569828097405924, 3.1966268149873294, 0.14237031656267723,
           -2.1600698102067937e-05, 0.979523240991942, 0.14235488348453268));
}

// The needle's far frame (stress scene: B's frame 1.3e5 from the origin and rotated) held
// {(fA-e1, 1), (fA-f1, 1)} twice (sessions 47-49), with the complete search: the tip on the
// rim with the other tip near the dish's bottom, and the needle lying across the dish's top.
// Session 48 showed them one region (both join the own frame's witness, moved there), but
// every join before the tangent walk fails between them: the straight motions, the midpoints,
// the parameter paths, the roadmap. Projections from poses a small piece off the CF start
// their tip contacts from detection, which misses a penetrating tip, and land on another branch
// (0.0015 L deep); the walk starts them from the contacts just left. Measured: joined with 568
// collision queries (session 50).
TEST(StateIdentity, TangentWalkJoinsTheFarNeedlesTwoRimAndWallWitnesses) {
  const SceneGeometry scene = build_scene_geometry(load_scene_file(
      std::string(PCSG_SOURCE_DIR) + "/scenes/stress/needle_far_rotated.yaml"));
  const Pose a = pose(119999.41260182612, -50001.61559530288, 20000.00770252468,
                      0.6627118796673848, -0.7062311976682716, 0.03380885918357511,
                      0.24679428888948376);
  const Pose b = pose(120001.15265350569, -50002.81144485555, 19999.535736571645,
                      0.12646898196397824, -0.9350683648913268, -0.11698523081717857,
                      -0.3097857410390398);
  const ContactReport ra = detect_contacts(scene, a), rb = detect_contacts(scene, b);
  ASSERT_FALSE(ra.penetrating());
  ASSERT_FALSE(rb.penetrating());
  const ContactFormation cf = ContactFormation::of(ra.contacts);
  ASSERT_EQ(cf.str(scene), "{(fA-e1, 1), (fA-f1, 1)}");
  ASSERT_TRUE(ContactFormation::of(rb.contacts) == cf);
  const SceneSymmetry symmetry = SceneSymmetry::of(scene);
  MotionCounters direct;
  EXPECT_FALSE(joined_within_cf(scene, a, b, cf, direct, symmetry));
  MotionCounters walked;
  EXPECT_TRUE(joined_by_tangent_walk(scene, a, b, cf, walked, symmetry));
  EXPECT_GT(walked.steps, 0);
}

// Example 1's two hands: {(fA-e1, 1), (fA-f1, 1)} and {(fA-e1, 2), (fA-f1, 1)} each twice,
// mirror images across the plane y = 0. Session 17 found them two regions by sampling (61
// witnesses of the 2-contact CF, each joining those of its own hand only; evidence, not a
// proof: docs/paper-comparison.md), and Example 1's graph keeps both. A walk that joined them
// would be the first path found between them, to be examined before any graph merged them.
// Measured: 825 and 919 collision queries spent without a join (session 50).
TEST(StateIdentity, TangentWalkDoesNotJoinExample1sMirrorHands) {
  const SceneGeometry scene =
      build_scene_geometry(load_scene_file(testing::scene_path("example1.yaml")));
  const SceneSymmetry symmetry = SceneSymmetry::of(scene);
  const std::pair<Pose, Pose> hands[] = {
      {pose(-1.6051845970692638, 0.062473738619869046, 2.146389695652337, 0.3222040369265771,
            -0.2493258235573032, 0.7620407517878649, 0.5033041673881464),
       pose(-1.6051845970692638, -0.06247373861986905, 2.146389695652337, 0.5033041673881464,
            0.7620407517878649, -0.2493258235573032, 0.3222040369265771)},
      {pose(-2.343817497804932, -0.4617399322169134, 3.079596681620572, 0.1793461838818267,
            -0.16531494405236488, 0.8617316732774343, 0.4448869956185087),
       pose(-2.343817497804932, 0.4617399322169134, 3.079596681620572, 0.4448869956185087,
            0.8617316732774343, -0.16531494405236488, 0.1793461838818267)}};
  for (const auto& [a, b] : hands) {
    const ContactReport ra = detect_contacts(scene, a), rb = detect_contacts(scene, b);
    ASSERT_FALSE(ra.penetrating());
    ASSERT_FALSE(rb.penetrating());
    const ContactFormation cf = ContactFormation::of(ra.contacts);
    ASSERT_TRUE(ContactFormation::of(rb.contacts) == cf) << cf.str(scene);
    MotionCounters counters;
    EXPECT_FALSE(joined_by_tangent_walk(scene, a, b, cf, counters, symmetry)) << cf.str(scene);
  }
}

}  // namespace
}  // namespace pcsg
