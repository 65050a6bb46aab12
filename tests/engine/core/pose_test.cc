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

// X^-1 undoes X on points (and X on X^-1), and maps B's origin to -R^T t.
TEST(Pose, InverseUndoesThePose) {
  const Pose X = parse_pose("0.3 -1.2 2.5, 0.9 0.1 -0.3 0.2");
  const Pose Xi = X.inverse();
  const Eigen::Vector3d p(0.4, 2, -7);
  EXPECT_TRUE(Xi.apply(X.apply(p)).isApprox(p, 1e-14));
  EXPECT_TRUE(X.apply(Xi.apply(p)).isApprox(p, 1e-14));
  EXPECT_TRUE(Xi.apply(Eigen::Vector3d::Zero()).isApprox(X.apply_inverse(Eigen::Vector3d::Zero())));
  EXPECT_TRUE(Xi.inverse().position.isApprox(X.position, 1e-14));
}

}  // namespace
}  // namespace pcsg
