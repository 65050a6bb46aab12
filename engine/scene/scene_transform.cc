// Rigid and scaling transforms of whole scenes, for the invariance tests and stress scenes: the
// generated graph must not depend on where B's frame is or on the unit of length.
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "engine/scene/scene.h"

namespace pcsg {
namespace {

// Rewrites every face of `object` as g(M x + c); the text then states the new polynomial, so
// that it never disagrees with g.
void substitute_faces(ObjectSpec& object, const Eigen::Matrix3d& M, const Eigen::Vector3d& c) {
  for (FaceSpec& f : object.faces) {
    f.g = f.g.substituted(M, c);
    f.text = f.g.str() + " <= 0";
  }
}

}  // namespace

SceneSpec scaled_scene(const SceneSpec& scene, double s) {
  if (!(s > 0) || !std::isfinite(s)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", s);
    throw std::invalid_argument(std::string("scaled_scene: scale ") + buf +
                                " must be finite and > 0");
  }
  // the scaled solid is { x : g(x / s) <= 0 }; A is scaled in its own frame likewise, so that
  // X_BA keeps its rotation and only its position scales
  SceneSpec out = scene;
  const Eigen::Matrix3d M = Eigen::Matrix3d::Identity() / s;
  substitute_faces(out.A, M, Eigen::Vector3d::Zero());
  substitute_faces(out.B, M, Eigen::Vector3d::Zero());
  for (SeedSpec& seed : out.seeds) seed.pose.position *= s;
  return out;
}

SceneSpec moved_scene(const SceneSpec& scene, const Pose& X_in) {
  const Pose X = X_in.canonical();  // a unit quaternion, so that R is a rotation
  // B moved by X holds p_new where X^-1 p_new was in B: g'(p) = g(R^T p - R^T t)
  SceneSpec out = scene;
  const Eigen::Matrix3d Rt = X.rotation().transpose();
  substitute_faces(out.B, Rt, -Rt * X.position);
  // A rides along: its pose in the new frame is X * X_BA
  for (SeedSpec& seed : out.seeds) {
    Pose moved;
    moved.position = X.apply(seed.pose.position);
    moved.quaternion = X.quaternion * seed.pose.quaternion;
    seed.pose = moved.canonical();
  }
  return out;
}

}  // namespace pcsg
