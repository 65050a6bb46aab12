// NearbyTriangles (contact_context.h): the triangle pairs gathered once for a neighbourhood of
// poses must give, at every pose inside it, exactly the pairs (and so the contacts) of a full
// BVH query. Tested where it is hardest: the ellipsoid lying in the dish (paper Fig. 5b), two
// nearly conformal contacts whose inflated meshes overlap over many triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "engine/contact/contact.h"
#include "engine/contact/contact_context.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"
#include "tests/engine/contact/test_shapes.h"

namespace pcsg {
namespace {

// The ellipsoid lying in the dish (paper Fig. 5b): two f-f contacts.
Pose resting_pose() { return testkit::lying_ellipsoid_pose(); }

SceneGeometry bowl_scene() {
  return testkit::scene_of(testkit::ellipsoid_solid(1, 1.5, 2.5, "fA"), testkit::bowl_solid(1));
}

// A pose near X: a random twist about A's centre, scaled so that the context's displacement
// bound is `fraction` of `margin`.
Pose pose_near(const ContactContext& ctx, const Pose& X, double margin, double fraction,
               std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  const Eigen::Vector3d v(n(rng), n(rng), n(rng)), w(n(rng), n(rng), n(rng));
  auto at = [&](double s) { return X.displaced(s * v, s * w / 3, X.position); };
  // The bound grows monotonically with s: bisect for the wanted size.
  double lo = 0, hi = margin;
  while (ctx.displacement(X, at(hi)) < fraction * margin) hi *= 2;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (ctx.displacement(X, at(mid)) < fraction * margin ? lo : hi) = mid;
  }
  return at(lo);
}

std::vector<std::pair<int, int>> sorted(std::vector<std::pair<int, int>> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(NearbyTriangles, DisplacementBoundsTheMotionOfEveryMeshVertex) {
  const SceneGeometry scene = bowl_scene();
  const ContactContext ctx(scene);
  const Pose X = resting_pose();
  std::mt19937 rng(7);
  for (int k = 0; k < 20; ++k) {
    const Pose Y = pose_near(ctx, X, 0.05 * scene.tol.length_scale, 1.0, rng);
    double moved = 0;
    for (const Eigen::Vector3d& p : scene.mesh_A.positions)
      moved = std::max(moved, (Y.apply(p) - X.apply(p)).norm());
    EXPECT_LE(moved, ctx.displacement(X, Y)) << "pose " << k;
  }
  // A pure translation moves every point by its length (to round-off of 1e-15 L).
  Pose T = X;
  T.position += Eigen::Vector3d(0.3, -0.4, 0);
  EXPECT_NEAR(ctx.displacement(X, T), 0.5, 1e-15 * scene.tol.length_scale);
}

TEST(NearbyTriangles, GiveTheFullQuerysPairsEverywhereWithinTheMargin) {
  const SceneGeometry scene = bowl_scene();
  const ContactContext ctx(scene);
  const Pose X = resting_pose();
  // One motion step of the generator: the bracket of an event's bisection.
  const double margin = scene.tol.motion_step;
  const NearbyTriangles near = ctx.nearby_triangles(X, margin);
  std::mt19937 rng(11);
  int nonempty = 0;
  for (int k = 0; k < 24; ++k) {
    const Pose Y = pose_near(ctx, X, margin, (k % 4 + 1) / 4.0, rng);
    std::vector<std::pair<int, int>> full, filtered;
    ASSERT_TRUE(ctx.overlapping_triangles(Y, full, 1000000));
    ASSERT_TRUE(ctx.overlapping_triangles_near(Y, near, filtered, 1000000)) << "pose " << k;
    EXPECT_EQ(sorted(full), sorted(filtered)) << "pose " << k;
    nonempty += !full.empty();
  }
  // Most of these poses are in or near contact: the comparison is not between empty lists.
  EXPECT_GE(nonempty, 12);
  // Outside the margin the nearby pairs do not answer.
  std::vector<std::pair<int, int>> pairs;
  EXPECT_FALSE(
      ctx.overlapping_triangles_near(pose_near(ctx, X, margin, 1.5, rng), near, pairs, 1000000));
}

// Narrowing filters the wide set by the leaves' boxes only, so it may keep a pair whose
// ancestors' boxes a fresh traversal found apart (a child's box can stick out of its parent's);
// both hold every pair that can overlap, and the narrowed one answers like a full query.
TEST(NearbyTriangles, NarrowingAWideSetCoversWhatGatheringAfreshFinds) {
  const SceneGeometry scene = bowl_scene();
  const ContactContext ctx(scene);
  const Pose X = resting_pose();
  const double margin = scene.tol.motion_step;
  const NearbyTriangles wide = ctx.nearby_triangles(X, margin);
  std::mt19937 rng(3);
  const Pose Y = pose_near(ctx, X, margin, 0.5, rng);
  const double small = 0.25 * margin;
  const NearbyTriangles narrow = ctx.nearby_triangles(Y, small, wide);
  const NearbyTriangles fresh = ctx.nearby_triangles(Y, small);
  EXPECT_FALSE(fresh.leaves.empty());
  EXPECT_LT(narrow.leaves.size(), wide.leaves.size());
  const auto n = sorted(narrow.leaves), f = sorted(fresh.leaves);
  EXPECT_TRUE(std::includes(n.begin(), n.end(), f.begin(), f.end()));
  for (int k = 0; k < 8; ++k) {
    const Pose Z = pose_near(ctx, Y, small, (k % 4 + 1) / 4.0, rng);
    std::vector<std::pair<int, int>> full, filtered;
    ASSERT_TRUE(ctx.overlapping_triangles(Z, full, 1000000));
    ASSERT_TRUE(ctx.overlapping_triangles_near(Z, narrow, filtered, 1000000)) << "pose " << k;
    EXPECT_EQ(sorted(full), sorted(filtered)) << "pose " << k;
  }
}

TEST(NearbyTriangles, DetectionThroughThemIsIdenticalToAFullQuery) {
  const SceneGeometry scene = bowl_scene();
  const ContactContext ctx(scene);
  const Pose X = resting_pose();
  const double margin = scene.tol.motion_step;
  const NearbyTriangles near = ctx.nearby_triangles(X, margin);
  DetectOptions plain, through;
  plain.near_margin = through.near_margin = ctx.guaranteed_band();
  through.nearby = &near;
  std::mt19937 rng(5);
  std::vector<Pose> poses = {X};
  for (int k = 0; k < 8; ++k) poses.push_back(pose_near(ctx, X, margin, 0.1 * (k + 1), rng));
  for (size_t k = 0; k < poses.size(); ++k) {
    const ContactReport a = detect_contacts(ctx, poses[k], plain);
    const ContactReport b = detect_contacts(ctx, poses[k], through);
    ASSERT_EQ(a.contacts.size(), b.contacts.size()) << "pose " << k;
    ASSERT_EQ(a.near.size(), b.near.size()) << "pose " << k;
    ASSERT_EQ(a.penetrations.size(), b.penetrations.size()) << "pose " << k;
    // Bit for bit: the same pairs give the same solves from the same starts.
    for (size_t i = 0; i < a.contacts.size(); ++i) {
      EXPECT_EQ(a.contacts[i].point_B, b.contacts[i].point_B) << "pose " << k;
      EXPECT_EQ(a.contacts[i].gap, b.contacts[i].gap) << "pose " << k;
    }
    for (size_t i = 0; i < a.near.size(); ++i) EXPECT_EQ(a.near[i].gap, b.near[i].gap);
    for (size_t i = 0; i < a.penetrations.size(); ++i)
      EXPECT_EQ(a.penetrations[i].depth, b.penetrations[i].depth);
  }
  EXPECT_EQ(detect_contacts(ctx, X, through).contacts.size(), 2u);
}

// overlapping_triangles is FCL's traversal with fewer box tests: along a motion through the
// contacts (resting, pressed in, lifted off, tipped and slid) it must list exactly the pairs of
// fcl::collide, in the same order; and under a cap, the same first pairs.
TEST(OverlappingTriangles, ListExactlyFclsPairsAlongAMotion) {
  const SceneGeometry scene = bowl_scene();
  const ContactContext ctx(scene);
  const Pose X = resting_pose();
  const double L = scene.tol.length_scale;
  std::mt19937 rng(13);
  std::vector<Pose> poses;
  for (int k = 0; k <= 40; ++k) {
    // Down into the dish and up out of it, turning about the long axis and sliding sideways.
    const double s = k / 40.0;
    Pose Y = X;
    Y.position += Eigen::Vector3d(0.3 * s * L, 0, (0.04 * std::sin(2 * M_PI * s) - 0.01) * L);
    Y.quaternion =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.2 * s, Eigen::Vector3d::UnitX())) * X.quaternion;
    poses.push_back(Y);
  }
  for (int k = 0; k < 12; ++k) poses.push_back(pose_near(ctx, X, 0.05 * L, (k % 4 + 1) / 4.0, rng));
  // And lifted off the dish.
  for (int k = 1; k <= 3; ++k) {
    Pose Y = poses.back();
    Y.position.z() += 0.1 * k * L;
    poses.push_back(Y);
  }
  int nonempty = 0, penetrating = 0;
  for (size_t k = 0; k < poses.size(); ++k) {
    std::vector<std::pair<int, int>> ours, fcl;
    const bool ours_all = ctx.overlapping_triangles(poses[k], ours, 1000000);
    const bool fcl_all = ctx.overlapping_triangles_by_fcl(poses[k], fcl, 1000000);
    ASSERT_TRUE(ours_all && fcl_all) << "pose " << k;
    EXPECT_EQ(ours, fcl) << "pose " << k;
    nonempty += !fcl.empty();
    penetrating += detect_contacts(ctx, poses[k]).penetrating();
    // Under a cap both stop after the same first pairs.
    if (fcl.size() > 4) {
      std::vector<std::pair<int, int>> capped_ours, capped_fcl;
      EXPECT_FALSE(ctx.overlapping_triangles(poses[k], capped_ours, 4));
      EXPECT_FALSE(ctx.overlapping_triangles_by_fcl(poses[k], capped_fcl, 4));
      EXPECT_EQ(capped_ours, capped_fcl) << "pose " << k;
    }
  }
  // The motion passes through contact, penetration and separation.
  EXPECT_GE(nonempty, 20);
  EXPECT_GE(penetrating, 5);
  EXPECT_LT(nonempty, static_cast<int>(poses.size()));
}

// The same on the paper's examples, about every state of their stored graphs
// (tests/data/graphs/): each witness pose, moved by 1e-5 to 1e-2 of the scene size in a random
// direction and pressed towards B's origin (into penetration), so that the traversal meets the
// nearly parallel sheets of a contact, wider overlaps and separation. The nearby pairs gathered
// at each witness answer like full queries within their margin.
TEST(OverlappingTriangles, ListExactlyFclsPairsAboutTheExamplesStates) {
  for (const std::string name : {"example1", "example2"}) {
    const SceneGeometry scene = build_scene_geometry(
        load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/" + name + ".yaml"));
    const ContactContext ctx(scene);
    const double L = scene.tol.length_scale;
    std::ifstream in(std::string(PCSG_SOURCE_DIR) + "/tests/data/graphs/" + name + ".json");
    const nlohmann::json graph = nlohmann::json::parse(in);
    std::mt19937 rng(17);
    std::normal_distribution<double> n(0, 1);
    int compared = 0, nonempty = 0, penetrating = 0;
    for (const nlohmann::json& state : graph.at("states")) {
      const auto& p = state.at("pose").at("position");
      const auto& q = state.at("pose").at("quaternion");
      Pose X;
      X.position = Eigen::Vector3d(p[0], p[1], p[2]);
      X.quaternion = Eigen::Quaterniond(q[0].get<double>(), q[1], q[2], q[3]).normalized();
      std::vector<Pose> poses = {X};
      for (double s : {1e-5, 1e-4, 1e-3, 1e-2}) {
        const Eigen::Vector3d v = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
        const Eigen::Vector3d w = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
        poses.push_back(X.displaced(s * L * v, s * w, X.position));
        poses.push_back(
            X.displaced(-s * L * X.position.normalized(), Eigen::Vector3d::Zero(), X.position));
      }
      for (const Pose& Y : poses) {
        std::vector<std::pair<int, int>> ours, fcl;
        ASSERT_TRUE(ctx.overlapping_triangles(Y, ours, 1000000));
        ASSERT_TRUE(ctx.overlapping_triangles_by_fcl(Y, fcl, 1000000));
        EXPECT_EQ(ours, fcl) << name << " pose " << compared;
        if (fcl.size() > 4) {
          std::vector<std::pair<int, int>> capped_ours, capped_fcl;
          EXPECT_FALSE(ctx.overlapping_triangles(Y, capped_ours, 4));
          EXPECT_FALSE(ctx.overlapping_triangles_by_fcl(Y, capped_fcl, 4));
          EXPECT_EQ(capped_ours, capped_fcl) << name << " pose " << compared;
        }
        ++compared;
        nonempty += !fcl.empty();
        penetrating += detect_contacts(ctx, Y).penetrating();
      }
      const double margin = scene.tol.motion_step;
      const NearbyTriangles near = ctx.nearby_triangles(X, margin);
      if (!near.complete) continue;
      for (int k = 0; k < 3; ++k) {
        const Pose Y = pose_near(ctx, X, margin, (k + 1) / 3.0, rng);
        std::vector<std::pair<int, int>> full, filtered;
        ASSERT_TRUE(ctx.overlapping_triangles(Y, full, 1000000));
        ASSERT_TRUE(ctx.overlapping_triangles_near(Y, near, filtered, 1000000));
        EXPECT_EQ(sorted(full), sorted(filtered)) << name << " near pose " << k;
      }
    }
    // Contacts (the witnesses), penetrations and separations are all among the poses.
    EXPECT_GE(nonempty, compared / 2) << name;
    EXPECT_GE(penetrating, 5) << name;
    EXPECT_LT(nonempty, compared) << name;
  }
}

}  // namespace
}  // namespace pcsg
