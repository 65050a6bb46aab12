#include "engine/core/pose.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>

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

// pose_bits tells poses apart by every bit of every coordinate, in the order x y z, w x y z:
// equal poses give equal keys, one a unit in the last place away (in any coordinate) another,
// and +0 and -0 (equal as numbers) two.
TEST(Pose, BitsTellEveryCoordinateApart) {
  const Pose X = parse_pose("0.1 -2 3e5, 0.5 0.5 -0.5 0.5");
  EXPECT_EQ(pose_bits(X), pose_bits(parse_pose("0.1 -2 3e5, 0.5 0.5 -0.5 0.5")));
  const std::array<double, 7> c = {0.1, -2, 3e5, 0.5, 0.5, -0.5, 0.5};
  for (int i = 0; i < 7; ++i) {
    double bits_of_c;
    std::memcpy(&bits_of_c, &pose_bits(X)[i], sizeof bits_of_c);
    EXPECT_EQ(bits_of_c, c[i]) << "coordinate " << i;
    std::array<double, 7> d = c;
    d[i] = std::nextafter(d[i], 1e300);
    Pose Y;
    Y.position = Eigen::Vector3d(d[0], d[1], d[2]);
    Y.quaternion = Eigen::Quaterniond(d[3], d[4], d[5], d[6]);
    EXPECT_NE(pose_bits(Y), pose_bits(X)) << "coordinate " << i;
  }
  Pose zero, negative_zero;
  negative_zero.position.x() = -0.0;
  EXPECT_NE(pose_bits(zero), pose_bits(negative_zero));
}

}  // namespace
}  // namespace pcsg
