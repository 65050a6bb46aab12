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

}  // namespace
}  // namespace pcsg
