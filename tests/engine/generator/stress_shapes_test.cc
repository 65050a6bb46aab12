// Stress scenes with extreme shapes and contact places (scenes/stress/): a needle-like
// ellipsoid, a seed next to the bifurcation where two contacts merge, contacts at the poles of
// an ellipsoid and the tips of paraboloids. Each graph must be the one the geometry implies
// (stated in the scene file's comment and here), or a clear diagnostic.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "stress_support.h"

namespace pcsg {
namespace {

using testing::adjacent_pair;
using testing::Generated;
using testing::generate;
using testing::stress_path;

// Example 1's single-contact states (Fig. 6) and their adjacency: fA against B's elements
// in the order f1, e1, f2, e2, f3, each adjacent to the next.
const std::vector<std::string> kSingles = {"{(fA-f1, 1)}", "{(fA-e1, 1)}", "{(fA-f2, 1)}",
                                           "{(fA-e2, 1)}", "{(fA-f3, 1)}"};
std::vector<std::string> chain_of_singles() {
  std::vector<std::string> adj;
  for (size_t i = 0; i + 1 < kSingles.size(); ++i)
    adj.push_back(adjacent_pair(kSingles[i], kSingles[i + 1]));
  return adj;
}

TEST(StressShapes, EllipsoidPoleOnTheDishTip) {
  const SceneSpec spec = load_scene_file(stress_path("poles_on_tips.yaml"));
  const SceneGeometry scene = build_scene_geometry(spec);
  // the seed: one exact contact at both vertices, normal along the common axis
  const ContactReport rep = detect_contacts(scene, spec.seeds.at(0).pose);
  ASSERT_EQ(rep.contacts.size(), 1u);
  const PointContact& c = rep.contacts[0];
  EXPECT_EQ(element_pair_name(scene, c.a, c.b), "fA-f1");
  const double tol = scene.tol.contact_gap;
  EXPECT_NEAR(c.point_B.z(), -15.75982 / 10.07047, tol);
  EXPECT_NEAR(c.point_B.head<2>().norm(), 0, tol);
  EXPECT_NEAR(c.normal_B.z(), 1, 1e-12) << "unit normal along the axis to round-off";
  EXPECT_NEAR(c.gap, 0, tol);
  expect_graph(generate(spec, /*search_upward=*/false), kSingles, chain_of_singles());
}

TEST(StressShapes, EllipsoidPoleOnTheBottomTipWhereTheSphereTouchesF3) {
  const SceneSpec spec = load_scene_file(stress_path("pole_on_bottom_tip.yaml"));
  const SceneGeometry scene = build_scene_geometry(spec);
  const ContactReport rep = detect_contacts(scene, spec.seeds.at(0).pose);
  ASSERT_EQ(rep.contacts.size(), 1u);
  EXPECT_EQ(element_pair_name(scene, rep.contacts[0].a, rep.contacts[0].b), "fA-f3");
  EXPECT_NEAR(rep.contacts[0].point_B.z(), -4, scene.tol.contact_gap);
  // 1e-4 deeper: a penetration of fA into f3's interior at the vertex, not at edge e2 (the
  // sphere of f2 touches f3 there tangentially and does not bound it)
  constexpr double kDeeper = 1e-4;
  Pose deeper = spec.seeds.at(0).pose;
  deeper.position.z() += kDeeper;
  const ContactReport pen = detect_contacts(scene, deeper);
  EXPECT_TRUE(pen.contacts.empty());
  ASSERT_FALSE(pen.penetrations.empty());
  for (const Penetration& p : pen.penetrations) {
    EXPECT_EQ(element_pair_name(scene, p.a, p.b), "fA-f3");
    EXPECT_LT(p.point_B.head<2>().norm(), scene.tol.distinct_points);
    // the pole's depth to first order (the curvature terms are 1e-8 over 1e-4 of depth)
    EXPECT_NEAR(p.depth, kDeeper, 1e-2 * kDeeper);
  }
  expect_graph(generate(spec, /*search_upward=*/false), kSingles, chain_of_singles());
}

// The lens (Example 2's A) standing on its tip at the bottom of the dish
// (lens_tip_in_dish.yaml): the listed seed is one contact, {(fA1-f1, 1)}, tip on tip on the
// common axis (the cap's radius of curvature there, 9/16, is below the dish's 1.2588). The LN
// graph grown from it without upward search is every single contact of the lens with B, a 3 x 5
// grid of 15 CFs and 22 adjacent pairs, the rims crossing in both senses (17 states): checked
// on Example 2's own graph in the suite (Generator.Example2SingleContactsFormTheLensGrid), and
// from this seed by the validation Validation.LensTipOnTheDishTip (tests/validation; 890 s on
// two threads in session 42, so it left the suite in session 43).
TEST(StressShapes, LensTipSeedTouchesTipOnTip) {
  const SceneSpec spec = load_scene_file(stress_path("lens_tip_in_dish.yaml"));
  const SceneGeometry scene = build_scene_geometry(spec);
  ASSERT_EQ(spec.seeds.size(), 1u);
  const ContactReport rep = detect_contacts(scene, spec.seeds[0].pose);
  EXPECT_FALSE(rep.penetrating());
  ASSERT_EQ(rep.contacts.size(), 1u);
  EXPECT_EQ(element_pair_name(scene, rep.contacts[0].a, rep.contacts[0].b), "fA1-f1");
  // the dish's tip, z = -15.75982 / 10.07047 (the scene file's comment)
  const Eigen::Vector3d tip(0, 0, -15.75982 / 10.07047);
  EXPECT_LT((rep.contacts[0].point_B - tip).norm(), scene.tol.distinct_points);
  EXPECT_LE(std::abs(rep.contacts[0].gap), scene.tol.contact_gap);
}

// The spheroid lying in the dish, axis along B's x: its two contacts are at x = +-kContactX
// (scene file comment), found here by minimising the gap of the two profiles numerically.
constexpr double kDishK = 4 / 10.07047, kDishZ0 = 15.75982 / 10.07047;
constexpr double kSpheroidC2 = 1.26006755875;
// gap(x) - gap(0) along the two profiles in the xz plane
double profile_gap(double x) { return 1 - std::sqrt(1 - x * x / kSpheroidC2) - kDishK * x * x; }
double contact_x() {
  double lo = 0, hi = 0.5;  // ternary search: profile_gap is unimodal on [0, 0.5]
  for (int k = 0; k < 200; ++k) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (profile_gap(m1) < profile_gap(m2))
      hi = m2;
    else
      lo = m1;
  }
  return 0.5 * (lo + hi);
}
// A on two contacts: its axis (A's z) along B's x, the lowest points at +-contact_x() touching.
Pose two_contact_pose() {
  Pose X;
  X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  X.position = {0, 0, 1 - kDishZ0 - profile_gap(contact_x())};
  return X;
}

TEST(StressBifurcation, AnalyticTwoContactPoseTouchesAtBothPoints) {
  const SceneGeometry scene =
      build_scene_geometry(load_scene_file(stress_path("near_matching_curvature.yaml")));
  const Pose X = two_contact_pose();
  const double x = contact_x();
  EXPECT_NEAR(x, 0.0502, 5e-5) << "the scene file's comment";
  const ElementId fA = scene.A.find("fA"), f1 = scene.B.find("f1");
  for (double side : {-1.0, 1.0}) {
    // start from the analytic contact points: A's in A's frame (on its z axis side), B's on f1
    const Eigen::Vector3d p_B(side * x, 0, kDishK * x * x - kDishZ0);
    const auto c = solve_pair(scene, X, fA, f1, PtcType::FF, X.apply_inverse(p_B), p_B);
    ASSERT_TRUE(c.has_value()) << "side " << side;
    EXPECT_NEAR(c->gap, 0, scene.tol.contact_gap) << "side " << side;
    EXPECT_NEAR(c->point_B.x(), side * x, 1e-6 * scene.tol.length_scale) << "side " << side;
  }
}

// Detection used to report one contact here (the closest triangle pair's solve); it now
// solves again from the overlap region's ends when the found contact is nearly flat
// (Tolerances::bifurcation_curvature; here 0.021 / L at each contact).
TEST(StressBifurcation, BothContactsNextToTheMergeAreDetectedAndGrow) {
  SceneSpec spec = load_scene_file(stress_path("near_matching_curvature.yaml"));
  const SceneGeometry scene = build_scene_geometry(spec);
  const Pose X = two_contact_pose();
  // the seed pose: two contacts, and no flicker as A rises through the merge: 2 contacts,
  // then none once both gaps exceed the contact tolerance
  const ContactReport at = detect_contacts(scene, X);
  ASSERT_EQ(ContactFormation::of(at.contacts).str(scene), "{(fA-f1, 2)}");
  for (const PointContact& c : at.contacts) EXPECT_NEAR(std::abs(c.point_B.x()), contact_x(), 1e-6);
  for (double rise : {1e-3, 1e-2, 1e-1, 0.5, 10.0, 100.0}) {
    Pose Y = X;
    Y.position.z() += rise * scene.tol.contact_gap;
    EXPECT_EQ(detect_contacts(scene, Y).contacts.size(), rise < 1 ? 2u : 0u) << "rise " << rise;
  }
  // from the listed seed: the seed itself, the paper's five single contacts, valid witnesses
  spec.auto_seeds = false;
  spec.seeds = {SeedSpec{X, {}}};
  const Generated g = generate(spec);
  ASSERT_FALSE(g.graph.states.empty());
  EXPECT_EQ(g.graph.states[0].cf.str(g.scene), "{(fA-f1, 2)}");
  std::vector<std::string> got;
  for (const State& s : g.graph.states) got.push_back(s.cf.str(g.scene));
  for (const std::string& s : kSingles)
    EXPECT_EQ(std::count(got.begin(), got.end(), s), 1) << s << "\n" << testing::join(got);
  testing::expect_witnesses_valid(g);
}

// A needle (semi-axes 0.025, 0.025, 2.5) has Example 1's states and two more: lying on the
// rim along a chord shorter than itself, {(fA-e1, 2)}, and leaning on the rim with its lower
// tip on the dish wall, {(fA-e1, 1), (fA-f1, 1)}. No state has a contact with f2 and another
// element (a segment tangent to the sphere meets it once, and e1 and e2 lie on it).
// {(fA-e1, 2)} is found by the seed search's off-centre pushes (seeds.cc; session 19): until
// then the graph had 7 states, no push landed the needle across the rim and no motion from
// the other states reached it (their witnesses lean on the rim at its normal cone's boundary).
void expect_needle_graph(const Generated& g) {
  std::vector<std::string> states = kSingles;
  states.insert(states.end(), {"{(fA-f1, 2)}", "{(fA-e1, 2)}", "{(fA-e1, 1), (fA-f1, 1)}"});
  std::vector<std::string> got;
  for (const State& s : g.graph.states) got.push_back(s.cf.str(g.scene));
  EXPECT_EQ(testing::sorted(got), testing::sorted(states)) << testing::join(got);
  const std::vector<std::string> adj = testing::adjacency(g.graph, g.scene);
  for (const std::string& pair : chain_of_singles())
    EXPECT_NE(std::find(adj.begin(), adj.end(), pair), adj.end()) << pair;
  testing::expect_witnesses_valid(g);
}

TEST(StressShapes, NeedleInTheDish) {
  expect_needle_graph(generate(load_scene_file(stress_path("needle_in_dish.yaml"))));
}

// With GeneratorOptions::region_samples (session 55): the needle's state {(fA-e1, 1),
// (fA-f1, 1)} has one witness, from which (and from every waypoint toward {(fA-f2, 1)}) the
// hypothesis toward {(fA-f2, 1)} fails; from a sample of its region, projected 0.137 rad and
// 0.58 from the witness, it succeeds (slidingA+rotation+separation), with its GN reverse: 28
// links against the default's 26 (measured: 42,638 queries against 22,630). The rotated frame
// (needle_rotated.yaml) has this link by default, from a second witness.
TEST(StressShapes, NeedleInTheDishWithRegionSamples) {
  GeneratorOptions opt;
  opt.region_samples = true;
  const Generated g = generate(load_scene_file(stress_path("needle_in_dish.yaml")), opt);
  expect_needle_graph(g);
  const std::vector<std::string> adj = testing::adjacency(g.graph, g.scene);
  const std::string link = adjacent_pair("{(fA-e1, 1), (fA-f1, 1)}", "{(fA-f2, 1)}");
  EXPECT_NE(std::find(adj.begin(), adj.end(), link), adj.end()) << testing::join(adj);
  EXPECT_EQ(g.graph.links.size(), 28u);
}

// The same needle with B moved far and rotated (as in example1_far_rotated.yaml): a rigid
// motion of B's frame must leave the graph unchanged (issue 5). Skipped in session 20 (8
// states, {(fA-e1, 1)} twice, no {(fA-e1, 1), (fA-f1, 1)}): B's faces, expanded about zero
// with coefficients ~1e10 before being recentred, were ~1e-7 off the needle's dish; parsed
// about B's origin (parse_inequality_about, brep_builder.cc) they are the dish to the last
// bit, and the graph had the needle's states (session 21). Skipped again in sessions 22-24 (9
// states, {(fA-e1, 1), (fA-f1, 1)} twice; with session 24's settling fix, reverted, 8 states
// and no {(fA-e2, 1)} -- {(fA-f2, 1)}). Session 25 found two defects of far frames: the pair
// solves' residual stalled at the round-off of coordinates 1.3e5 (1.3e-11 to
// 1.6e-11 against solve_residual 1.3e-11), so whether a contact had rates (the link
// {(fA-e2, 1)} -- {(fA-f2, 1)}: "contact fA-f2 has no rates at step 6") was decided by
// round-off (Tolerances::residual_at); and a join of two witnesses 0.04 rad apart failed on
// its last hop, one motion step of five needle radii (transition_motion.cc,
// kMaxLastHopPieces). With both fixed the graph is the needle's. Still open and not checked here:
// three rim witnesses lie 1e-6 to 4e-5 rad from f1's normal, on their CF's boundary
// (docs/paper-comparison.md, "Invariance").
// With the quick search (GeneratorOptions::complete_search off, the default until session 47),
// which passes; the complete search, the default since, is the next test.
TEST(StressShapes, NeedleFarFromTheOriginAndRotated) {
  GeneratorOptions quick;
  quick.complete_search = false;
  expect_needle_graph(generate(load_scene_file(stress_path("needle_far_rotated.yaml")), quick));
}

// The same with the complete search (the default since session 47). Open in sessions 47-49,
// measured (61 s, two threads, beside the test suite): 9 states, {(fA-e1, 1), (fA-f1, 1)}
// twice. The second witness is reached by one of the complete search's further motions (not
// by a symmetry image: with the image states left out, measured, it is still there) and joins
// the first by none of the joins, as session 40 saw in Example 1 with B moved under session
// 39's rule. The needle's own frame and its rotated frame keep 8 states with either search.
// Session 48 (docs/paper-comparison.md): the two are one region, since the own frame's witness
// of the CF, moved into the far frame, joins both there; the first witness's rim normal is
// 1.4e-6 rad from f1's, but pushed 0.18 rad into the cone it still joins neither the second
// directly nor through a roadmap holding every member of both states. Session 50: the
// tangent walk (state_identity.h, joined_by_tangent_walk) joins them, and the graph is the
// needle's (8 states, 26 links, 32,854 queries on one thread).
TEST(StressShapes, NeedleFarFromTheOriginAndRotatedWithTheCompleteSearch) {
  expect_needle_graph(generate(load_scene_file(stress_path("needle_far_rotated.yaml"))));
}

// The same rotation without the translation: no cancellation, only B's orientation differs.
// Skipped in session 21 (6 states, no {(fA-f1, 2)}, no {(fA-e1, 1), (fA-f1, 1)}): the seed
// search's pushes down the dish landed a tip in the wall, where detection read the needle as
// apart (its solve wandered to a minimum 2.3 away; ExampleScenes.NeedleTipPokedIntoThe-
// RotatedDishIsAPenetration), so their approach bisections found no touching pose. Since
// detection retries such a solve and otherwise looks for the penetration, the graph has the
// needle's states (session 22).
TEST(StressShapes, NeedleRotatedAboutTheOrigin) {
  expect_needle_graph(generate(load_scene_file(stress_path("needle_rotated.yaml"))));
}

}  // namespace
}  // namespace pcsg
