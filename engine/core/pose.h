#pragma once
// The relative configuration of A with respect to B.
// Convention for the whole project: a pose X_BA maps A's frame into B's frame,
//   p_B = R(q) p_A + position.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>

namespace pcsg {

struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond quaternion = Eigen::Quaterniond::Identity();  // unit, w >= 0 canonical

  static Pose identity() { return Pose{}; }
  Eigen::Matrix3d rotation() const { return quaternion.toRotationMatrix(); }
  // p_B = X_BA * p_A.
  Eigen::Vector3d apply(const Eigen::Vector3d& p_A) const { return quaternion * p_A + position; }
  // v_B = R_BA * v_A (directions, normals).
  Eigen::Vector3d rotate(const Eigen::Vector3d& v_A) const { return quaternion * v_A; }
  // p_A = X_BA^-1 * p_B.
  Eigen::Vector3d apply_inverse(const Eigen::Vector3d& p_B) const {
    return quaternion.conjugate() * (p_B - position);
  }
  // X^-1: the pose of B's frame in A's (R^T, -R^T t).
  Pose inverse() const { return {-(quaternion.conjugate() * position), quaternion.conjugate()}; }
  Eigen::Isometry3d isometry() const;
  // A new pose displaced by the twist (v, w) given in B's frame: the rotation w (axis-angle)
  // is about the point `about_B`, then the translation v is added.
  Pose displaced(const Eigen::Vector3d& v_B, const Eigen::Vector3d& w_B,
                 const Eigen::Vector3d& about_B) const;
  // Unit quaternion with w >= 0, so that equal rotations print equally.
  Pose canonical() const;
  // "x y z qw qx qy qz" with full precision.
  std::string str() const;
};

// The bits of the seven coordinates (position x y z, quaternion w x y z): the key of the
// memos that answer only the very same pose (one a unit in the last place away is another).
std::array<std::uint64_t, 7> pose_bits(const Pose& X);

// The pose a fraction `f` of the way from a to b: positions interpolated, orientations
// slerped along the shorter arc.
Pose between(const Pose& a, const Pose& b, double f);

// Parses "x y z qw qx qy qz" (commas allowed); the quaternion is normalised.
// Throws UsageError naming the text when it is malformed or the quaternion is zero.
Pose parse_pose(const std::string& text);

}  // namespace pcsg
