#include "engine/core/pose.h"

#include <gtest/gtest.h>

#include "engine/core/error.h"

namespace pcsg {
namespace {

TEST(Pose, ParsesAndApplies) {
  const Pose X = parse_pose("1 2 3, 0.7071067811865476 0 0 0.7071067811865476");
  // 90 degrees about z: x_A = (1,0,0) maps to (0,1,0) + position.
  EXPECT_TRUE(X.apply({1, 0, 0}).isApprox(Eigen::Vector3d(1, 3, 3), 1e-12));
  EXPECT_TRUE(X.apply_inverse(X.apply({0.3, -2, 5})).isApprox(Eigen::Vector3d(0.3, -2, 5)));
}

TEST(Pose, RejectsMalformedText) {
  EXPECT_THROW(parse_pose("1 2 3"), UsageError);
  EXPECT_THROW(parse_pose("1 2 3 1 0 0 zero"), UsageError);
  EXPECT_THROW(parse_pose("1 2 3 0 0 0 0"), UsageError);
}

TEST(Pose, DisplacedRotatesAboutThePoint) {
  Pose X;
  X.position = {1, 0, 0};
  const Pose Y = X.displaced({0, 0, 0}, {0, 0, M_PI / 2}, {0, 0, 0});
  EXPECT_TRUE(Y.position.isApprox(Eigen::Vector3d(0, 1, 0), 1e-12));
}

}  // namespace
}  // namespace pcsg
