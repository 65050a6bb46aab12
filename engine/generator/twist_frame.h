#pragma once
// Small motions of A as scaled twists s = (v, L w) about a reference point o (B's frame): A's
// point p moves with velocity v + w x (p - o). Scaling the angular part by A's size L makes a
// unit twist move A's points by about one length unit whichever part moves, so least-norm
// motions balance translation and rotation (paper Section III-B: each small motion step is a
// small translation combined with a small rotation).
#include <Eigen/Core>

#include "engine/core/pose.h"

namespace pcsg {

using Twist = Eigen::Matrix<double, 6, 1>;

struct TwistFrame {
  Eigen::Vector3d origin_B = Eigen::Vector3d::Zero();  // o: A's centre at the current pose
  double length = 1.0;                                  // L: A's size (bbox diagonal / 2)

  // The pose after the motion s applied to X.
  Pose apply(const Pose& X, const Twist& s) const {
    return X.displaced(s.head<3>(), s.tail<3>() / length, origin_B);
  }
  // Converts a Jacobian with respect to a twist about B's origin (columns v, w; points move
  // with v + w x p) into one with respect to the scaled twist about o.
  Eigen::MatrixXd from_origin_jacobian(const Eigen::MatrixXd& J) const {
    Eigen::MatrixXd out(J.rows(), 6);
    Eigen::Matrix3d o_hat;
    o_hat << 0, -origin_B.z(), origin_B.y(), origin_B.z(), 0, -origin_B.x(), -origin_B.y(),
        origin_B.x(), 0;
    // v_origin = v_o + o x w  =>  dr = Jv v_o + (Jv [o]x + Jw) w, and w = s_w / L.
    out.leftCols<3>() = J.leftCols<3>();
    out.rightCols<3>() = (J.leftCols<3>() * o_hat + J.rightCols<3>()) / length;
    return out;
  }
  // Displacement bound of A's points under s (within a factor of ~2).
  static double displacement(const Twist& s) { return s.head<3>().norm() + s.tail<3>().norm(); }
};

}  // namespace pcsg
