#pragma once
// Small motions of A as scaled twists s = (v, L w) about a reference point o (B's frame): A's
// point p moves with velocity v + w x (p - o). o and L are the centre and size of the smaller
// object (ReferenceBody below). Scaling the angular part by L makes a unit twist move that
// object's points by about one length unit whichever part moves, so least-norm
// motions balance translation and rotation (paper Section III-B: each small motion step is a
// small translation combined with a small rotation).
#include <Eigen/Core>
#include <algorithm>

#include "engine/core/pose.h"
#include "engine/geometry/scene_geometry.h"

namespace pcsg {

using Twist = Eigen::Matrix<double, 6, 1>;

struct TwistFrame {
  Eigen::Vector3d origin_B = Eigen::Vector3d::Zero();  // o: the reference centre, B's frame
  double length = 1.0;                                 // L: its size (bbox diagonal / 2)

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
  // Displacement bound of the reference body's points under s (within a factor of ~2).
  static double displacement(const Twist& s) { return s.head<3>().norm() + s.tail<3>().norm(); }
};

// The body whose centre is the twists' origin and whose size is their length scale: the smaller
// of the two (by bounding-box half-diagonal; A on a tie). Both are physical choices, the same
// point and length whichever object is called A, so the least-norm motions, the step grid and
// the events met on it do not depend on the naming: the graph of the swapped scene (B moved
// relative to A) is the mirror of the scene's, motion for motion (metamorphic_test.cc). In
// every scene of scenes/ A is the smaller object.
struct ReferenceBody {
  bool is_a = true;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // in its own solid's frame
  double size = 1.0;  // half its bounding-box diagonal, at least 1e-3 of the scene's scale

  explicit ReferenceBody(const SceneGeometry& scene) {
    const double floor = scene.tol.length_scale * 1e-3;
    const double size_a = std::max(scene.A.bbox.diagonal().norm() / 2, floor);
    const double size_b = std::max(scene.B.bbox.diagonal().norm() / 2, floor);
    is_a = size_a <= size_b;
    centre = is_a ? scene.A.bbox.center() : scene.B.bbox.center();
    size = is_a ? size_a : size_b;
  }
  // Its centre in B's frame when A is at X.
  Eigen::Vector3d centre_B(const Pose& X) const { return is_a ? X.apply(centre) : centre; }
  TwistFrame frame_at(const Pose& X) const { return {centre_B(X), size}; }
};

}  // namespace pcsg
