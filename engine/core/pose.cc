#include "engine/core/pose.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <vector>

#include "engine/core/error.h"

namespace pcsg {

Eigen::Isometry3d Pose::isometry() const {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = rotation();
  X.translation() = position;
  return X;
}

Pose Pose::displaced(const Eigen::Vector3d& v_B, const Eigen::Vector3d& w_B,
                     const Eigen::Vector3d& about_B) const {
  Pose out;
  const double angle = w_B.norm();
  Eigen::Quaterniond dq = Eigen::Quaterniond::Identity();
  if (angle > 0) dq = Eigen::Quaterniond(Eigen::AngleAxisd(angle, w_B / angle));
  out.quaternion = (dq * quaternion).normalized();
  out.position = dq * (position - about_B) + about_B + v_B;
  return out;
}

Pose Pose::canonical() const {
  Pose out = *this;
  out.quaternion.normalize();
  if (out.quaternion.w() < 0) out.quaternion.coeffs() *= -1.0;
  return out;
}

std::string Pose::str() const {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g", position.x(),
                position.y(), position.z(), quaternion.w(), quaternion.x(), quaternion.y(),
                quaternion.z());
  return buf;
}

std::array<std::uint64_t, 7> pose_bits(const Pose& X) {
  const double coordinates[7] = {X.position.x(),   X.position.y(),   X.position.z(),
                                 X.quaternion.w(), X.quaternion.x(), X.quaternion.y(),
                                 X.quaternion.z()};
  std::array<std::uint64_t, 7> bits;
  static_assert(sizeof coordinates == sizeof bits, "seven 64-bit words");
  std::memcpy(bits.data(), coordinates, sizeof bits);
  return bits;
}

Pose between(const Pose& a, const Pose& b, double f) {
  Pose m;
  m.position = (1 - f) * a.position + f * b.position;
  // Eigen's slerp takes the shorter arc (it flips the sign of a negative dot product).
  m.quaternion = a.quaternion.slerp(f, b.quaternion).normalized();
  return m;
}

Pose parse_pose(const std::string& text) {
  std::string cleaned = text;
  for (char& c : cleaned)
    if (c == ',') c = ' ';
  std::istringstream in(cleaned);
  std::vector<double> v;
  std::string tok;
  while (in >> tok) {
    try {
      size_t used = 0;
      v.push_back(std::stod(tok, &used));
      if (used != tok.size()) throw std::invalid_argument(tok);
    } catch (const std::exception&) {
      throw UsageError("pose \"" + text + "\": \"" + tok + "\" is not a number");
    }
  }
  if (v.size() != 7)
    throw UsageError("pose \"" + text + "\": expected 7 numbers \"x y z qw qx qy qz\", got " +
                     std::to_string(v.size()));
  for (double x : v)
    if (!std::isfinite(x)) throw UsageError("pose \"" + text + "\": non-finite value");
  Pose p;
  p.position = {v[0], v[1], v[2]};
  Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
  if (q.norm() < 1e-12) throw UsageError("pose \"" + text + "\": the quaternion is zero");
  p.quaternion = q.normalized();
  return p.canonical();
}

}  // namespace pcsg
