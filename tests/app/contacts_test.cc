// End-to-end: `pcsg contacts` on paper Example 1 (scenes/example1.yaml), reading its --json
// output: the seed CF {(fA-f1, 2)} at the closed-form resting pose, --snap onto it from a
// raised pose, penetration, and the usage errors (exit code 2).
#include <gtest/gtest.h>

#include "run_pcsg.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

namespace {

using nlohmann::json;

// Example 1's dish z = a r^2 - b and its length scale L (B's bounding-box diagonal, ~13).
constexpr double kDishA = 4 / 10.07047;
constexpr double kDishB = 15.75982 / 10.07047;
constexpr double kLengthScale = 13.0158;
// Gaps at the closed-form pose and after --snap: 1e-10 L, the brief's bar (solves reach 1e-15;
// the pose is printed with 17 digits, so nothing is lost in the text).
constexpr double kTouching = 1e-10 * kLengthScale;

using pcsg::testing::ExeRun;
using pcsg::testing::run_pcsg;

std::string example1() { return std::string(PCSG_SOURCE_DIR) + "/scenes/example1.yaml"; }

// The ellipsoid lying on its side (long axis along x) at height h: q = 90 degrees about y.
std::string lying_pose(double h) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "\"0 0 %.17g %.17g 0 %.17g 0\"", h, std::sqrt(0.5), std::sqrt(0.5));
  return buf;
}

double resting_height() { return 6.25 * kDishA + 1 / (25 * kDishA) - kDishB; }

TEST(ContactsCommand, ReportsTheSeedOfExample1) {
  const ExeRun r = run_pcsg("contacts " + example1() + " --pose " + lying_pose(resting_height()) +
                            " --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["cf"], "{(fA-f1, 2)}");
  EXPECT_FALSE(j["penetrating"].get<bool>());
  ASSERT_EQ(j["contacts"].size(), 2u);
  for (const auto& c : j["contacts"]) {
    EXPECT_EQ(c["pair"], "fA-f1");
    EXPECT_EQ(c["type"], "f-f");
    EXPECT_LT(std::abs(c["gap"].get<double>()), kTouching);
    EXPECT_FALSE(c["contact_plane"].is_null());
  }
}

TEST(ContactsCommand, SnapsARaisedPoseOntoTheSeed) {
  const ExeRun r = run_pcsg("contacts " + example1() + " --pose " +
                            lying_pose(resting_height() + 0.05) +
                            " --snap \"{(fA-f1, 2)}\" --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json j = json::parse(r.out);
  ASSERT_FALSE(j["snap"].is_null());
  EXPECT_EQ(j["snap"]["cf"], "{(fA-f1, 2)}");
  EXPECT_EQ(j["cf"], "{(fA-f1, 2)}");
  for (const auto& c : j["contacts"]) EXPECT_LT(std::abs(c["gap"].get<double>()), kTouching);
  // The text form prints the projected pose and both contacts.
  const ExeRun t = run_pcsg("contacts " + example1() + " --pose " +
                            lying_pose(resting_height() + 0.05) + " --snap \"{(fA-f1, 2)}\"");
  ASSERT_EQ(t.exit_code, 0);
  EXPECT_NE(t.out.find("projected pose"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("CF       {(fA-f1, 2)}"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("penetration: none"), std::string::npos) << t.out;
}

TEST(ContactsCommand, ReportsPenetrationNotContacts) {
  const ExeRun r = run_pcsg("contacts " + example1() + " --pose " +
                            lying_pose(resting_height() - 0.01) + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json j = json::parse(r.out);
  EXPECT_TRUE(j["penetrating"].get<bool>());
  EXPECT_TRUE(j["contacts"].empty());
  ASSERT_FALSE(j["penetrations"].empty());
  EXPECT_GT(j["penetrations"][0]["depth"].get<double>(), 0);
}

TEST(ContactsCommand, BadPoseOrFormationIsAUsageError) {
  const ExeRun pose = run_pcsg("contacts " + example1() + " --pose \"0 0 1 1 0 0\"", true);
  EXPECT_EQ(pose.exit_code, 2);
  EXPECT_NE(pose.out.find("expected 7 numbers"), std::string::npos) << pose.out;
  const ExeRun cf = run_pcsg("contacts " + example1() + " --pose " + lying_pose(1.1) +
                                 " --snap \"{(fA-f9, 1)}\"",
                             true);
  EXPECT_EQ(cf.exit_code, 2);
  EXPECT_NE(cf.out.find("\"fA-f9\" is not a pair"), std::string::npos) << cf.out;
  const ExeRun impossible = run_pcsg("contacts " + example1() + " --pose " +
                                         lying_pose(resting_height()) + " --snap \"{(fA-f1, 3)}\"",
                                     true);
  EXPECT_EQ(impossible.exit_code, 1);
  EXPECT_NE(impossible.out.find("cannot snap onto {(fA-f1, 3)}"), std::string::npos)
      << impossible.out;
}

}  // namespace
