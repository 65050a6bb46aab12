// ReportCache (report_cache.h): a repeated detection query is answered from the context's
// recent reports, and the answer is the report a fresh query gives.
#include <gtest/gtest.h>

#include "engine/contact/contact.h"
#include "engine/contact/contact_context.h"
#include "tests/engine/contact/test_shapes.h"

namespace pcsg {
namespace {

// The ellipsoid lying in the dish (paper Fig. 5b): two f-f contacts.
Pose resting_pose() { return testkit::lying_ellipsoid_pose(); }

void expect_same_report(const ContactReport& x, const ContactReport& y) {
  ASSERT_EQ(x.contacts.size(), y.contacts.size());
  for (size_t i = 0; i < x.contacts.size(); ++i) {
    EXPECT_TRUE(x.contacts[i].a == y.contacts[i].a && x.contacts[i].b == y.contacts[i].b);
    EXPECT_EQ(x.contacts[i].point_B, y.contacts[i].point_B);  // bit for bit
    EXPECT_EQ(x.contacts[i].gap, y.contacts[i].gap);
  }
  EXPECT_EQ(x.near.size(), y.near.size());
  EXPECT_EQ(x.penetrations.size(), y.penetrations.size());
}

TEST(ReportCache, RepeatedQueryIsRecalledAndEqualsAFreshOne) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::ellipsoid_solid(1, 1.5, 2.5, "fA"), testkit::bowl_solid(1));
  const ContactContext ctx(scene);
  const Pose X = resting_pose();
  const ContactReport first = detect_contacts(ctx, X);
  EXPECT_FALSE(first.recalled);
  ASSERT_EQ(first.contacts.size(), 2u);
  const ContactReport again = detect_contacts(ctx, X);
  EXPECT_TRUE(again.recalled);
  expect_same_report(first, again);
  // A fresh context (no recent reports) gives the same report.
  const ContactContext fresh(scene);
  const ContactReport anew = detect_contacts(fresh, X);
  EXPECT_FALSE(anew.recalled);
  expect_same_report(anew, again);
}

TEST(ReportCache, AnotherPoseOrMarginIsQueriedAnew) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::ellipsoid_solid(1, 1.5, 2.5, "fA"), testkit::bowl_solid(1));
  const ContactContext ctx(scene);
  const Pose X = resting_pose();
  detect_contacts(ctx, X);
  // the same pose with a near margin: another query (its report has the near minima too)
  DetectOptions near;
  near.near_margin = scene.tol.candidate_band;
  EXPECT_FALSE(detect_contacts(ctx, X, near).recalled);
  EXPECT_TRUE(detect_contacts(ctx, X, near).recalled);
  // one ulp higher: another pose, another query
  Pose Y = X;
  Y.position.z() = std::nextafter(Y.position.z(), INFINITY);
  EXPECT_FALSE(detect_contacts(ctx, Y).recalled);
  // asked not to recall (`pcsg bench` times detection itself): detected again, same report
  DetectOptions fresh;
  fresh.recall = false;
  const ContactReport again = detect_contacts(ctx, Y, fresh);
  EXPECT_FALSE(again.recalled);
  expect_same_report(again, detect_contacts(ctx, Y));
}

// A query that stops at its first penetration (a motion's collision verdict) gets the first
// penetration of the full report alone, whichever report the cache held; a full query is
// never answered by a report cut short, and its answer replaces that one.
TEST(ReportCache, ReportsCutShortAtAPenetrationAnswerOnlyQueriesThatStopThere) {
  const SceneGeometry scene =
      testkit::scene_of(testkit::ellipsoid_solid(1, 1.5, 2.5, "fA"), testkit::bowl_solid(1));
  const double L = scene.tol.length_scale;
  Pose X = resting_pose();
  X.position.z() -= 1e-2 * L;  // both f-f contacts sunk into the dish
  DetectOptions fresh;
  fresh.recall = false;
  const ContactReport full = detect_contacts(ContactContext(scene), X, fresh);
  ASSERT_EQ(full.penetrations.size(), 2u);
  EXPECT_FALSE(full.cut_short);
  DetectOptions stop;
  stop.stop_at_penetration = true;
  auto expect_first_alone = [&](const ContactReport& r) {
    EXPECT_TRUE(r.cut_short);
    ASSERT_EQ(r.penetrations.size(), 1u);
    EXPECT_TRUE(r.penetrations[0].a == full.penetrations[0].a &&
                r.penetrations[0].b == full.penetrations[0].b);
    EXPECT_EQ(r.penetrations[0].point_B, full.penetrations[0].point_B);  // bit for bit
    EXPECT_EQ(r.penetrations[0].depth, full.penetrations[0].depth);
    EXPECT_TRUE(r.contacts.empty() && r.near.empty());
  };
  {
    const ContactContext ctx(scene);
    const ContactReport cut = detect_contacts(ctx, X, stop);  // detected, cut short
    EXPECT_FALSE(cut.recalled);
    expect_first_alone(cut);
    expect_first_alone(detect_contacts(ctx, X, stop));    // recalled
    const ContactReport whole = detect_contacts(ctx, X);  // not from the cut one
    EXPECT_FALSE(whole.recalled);
    EXPECT_FALSE(whole.cut_short);
    expect_same_report(whole, full);
    EXPECT_TRUE(detect_contacts(ctx, X).recalled);  // the full one replaced it
  }
  {
    const ContactContext ctx(scene);
    detect_contacts(ctx, X);  // the full report first
    const ContactReport cut = detect_contacts(ctx, X, stop);
    EXPECT_TRUE(cut.recalled);
    expect_first_alone(cut);
  }
  // Where nothing penetrates, stopping changes nothing.
  const ContactContext ctx(scene);
  const ContactReport resting = detect_contacts(ctx, resting_pose(), stop);
  EXPECT_FALSE(resting.cut_short);
  ASSERT_EQ(resting.contacts.size(), 2u);
  expect_same_report(resting, detect_contacts(ContactContext(scene), resting_pose(), fresh));
}

TEST(ReportCache, KeepsAtMostItsCapacityDroppingTheOldest) {
  ReportCache cache(2);
  ContactReport r;
  r.failed_solves = 1;
  Pose X;
  const ReportCache::Key k0 = ReportCache::key(X, 0);
  X.position.x() = 1;
  const ReportCache::Key k1 = ReportCache::key(X, 0);
  X.position.x() = 2;
  const ReportCache::Key k2 = ReportCache::key(X, 0);
  cache.remember(k0, r);
  cache.remember(k1, r);
  cache.remember(k2, r);
  EXPECT_FALSE(cache.recall(k0).has_value());
  ASSERT_TRUE(cache.recall(k1).has_value());
  EXPECT_EQ(cache.recall(k2)->failed_solves, 1);
}

}  // namespace
}  // namespace pcsg
