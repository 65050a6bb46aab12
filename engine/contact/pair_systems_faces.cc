// The common-normal systems of the pairs that involve a face: f-f, f-e, e-f, f-v, v-f
// (pair_systems.h lists the equations). Each evaluator forms the rows F and their scales,
// then, when J is asked for, the Jacobian, whose comments give each block's origin.
#include <Eigen/Dense>

#include "engine/contact/pair_systems.h"

namespace pcsg {

void PairSystem::evaluate_ff(const SmallVector& z, SmallVector& F, SmallMatrix* J,
                             SmallVector& rs) const {
  const Eigen::Vector3d p_A = z.segment<3>(0), p_B = z.segment<3>(3);
  const double s = z[6], k = z[7];
  const bool jacobian = J != nullptr;
  const SurfaceJet ja = SurfaceJet::at(ga(0), p_A, jacobian);
  const SurfaceJet jb = SurfaceJet::at(gb(0), p_B, jacobian);
  const Eigen::Matrix3d& R = s_.R;
  // g_a(p_A) = 0, g_b(p_B) = 0.
  F[0] = ja.value;
  rs[0] = 1 / ja.gradient_norm;
  F[1] = jb.value;
  rs[1] = 1 / jb.gradient_norm;
  // x_A - p_B - s n_b = 0: the points are joined along B's normal.
  F.segment<3>(2) = R * p_A + s_.t - p_B - s * jb.normal;
  rs.segment<3>(2).setOnes();
  // R n_a + k n_b = 0: the normals are parallel (k = 1 when opposite, as in a contact).
  F.segment<3>(5) = R * ja.normal + k * jb.normal;
  rs.segment<3>(5).setConstant(s_.length_scale);
  if (!J) return;
  const Eigen::Matrix3d dn_b = jb.normal_derivative();
  J->row(0).segment<3>(0) = ja.gradient;
  J->row(1).segment<3>(3) = jb.gradient;
  J->block<3, 3>(2, 0) = R;
  J->block<3, 3>(2, 3) = -Eigen::Matrix3d::Identity() - s * dn_b;
  J->block<3, 1>(2, 6) = -jb.normal;
  J->block<3, 3>(5, 0) = R * ja.normal_derivative();
  J->block<3, 3>(5, 3) = k * dn_b;
  J->block<3, 1>(5, 7) = jb.normal;
}

void PairSystem::evaluate_fe(const SmallVector& z, SmallVector& F, SmallMatrix* J,
                             SmallVector& rs) const {
  const Eigen::Vector3d p_A = z.segment<3>(0), p_B = z.segment<3>(3);
  const double s = z[6];
  const bool jacobian = J != nullptr;
  const SurfaceJet ja = SurfaceJet::at(ga(0), p_A, jacobian);
  const SurfaceJet jb1 = SurfaceJet::at(gb(0), p_B, jacobian);
  const SurfaceJet jb2 = SurfaceJet::at(gb(1), p_B, jacobian);
  const CurveJet cb = CurveJet::of(jb1, jb2, jacobian);
  const Eigen::Matrix3d& R = s_.R;
  F[0] = ja.value;
  rs[0] = 1 / ja.gradient_norm;
  F[1] = jb1.value;
  rs[1] = 1 / jb1.gradient_norm;
  F[2] = jb2.value;
  rs[2] = 1 / jb2.gradient_norm;
  // x_A - p_B + s R n_a = 0: joined along A's normal (n = -R n_a points from B toward A).
  F.segment<3>(3) = R * p_A + s_.t - p_B + s * (R * ja.normal);
  rs.segment<3>(3).setOnes();
  // n_a . R^T c_b = 0: A's normal is normal to B's edge tangent c_b = grad g_b1 x grad g_b2.
  const Eigen::Vector3d c_in_A = R.transpose() * cb.c;
  F[6] = ja.normal.dot(c_in_A);
  rs[6] = s_.length_scale / cb.c.norm();
  if (!J) return;
  const Eigen::Matrix3d dn_a = ja.normal_derivative();
  J->row(0).segment<3>(0) = ja.gradient;
  J->row(1).segment<3>(3) = jb1.gradient;
  J->row(2).segment<3>(3) = jb2.gradient;
  J->block<3, 3>(3, 0) = R + s * R * dn_a;
  J->block<3, 3>(3, 3) = -Eigen::Matrix3d::Identity();
  J->block<3, 1>(3, 6) = R * ja.normal;
  J->row(6).segment<3>(0) = dn_a.transpose() * c_in_A;
  J->row(6).segment<3>(3) = cb.dc.transpose() * (R * ja.normal);
}

void PairSystem::evaluate_ef(const SmallVector& z, SmallVector& F, SmallMatrix* J,
                             SmallVector& rs) const {
  const Eigen::Vector3d p_A = z.segment<3>(0), p_B = z.segment<3>(3);
  const double s = z[6];
  const bool jacobian = J != nullptr;
  const SurfaceJet ja1 = SurfaceJet::at(ga(0), p_A, jacobian);
  const SurfaceJet ja2 = SurfaceJet::at(ga(1), p_A, jacobian);
  const SurfaceJet jb = SurfaceJet::at(gb(0), p_B, jacobian);
  const CurveJet ca = CurveJet::of(ja1, ja2, jacobian);
  const Eigen::Matrix3d& R = s_.R;
  F[0] = ja1.value;
  rs[0] = 1 / ja1.gradient_norm;
  F[1] = ja2.value;
  rs[1] = 1 / ja2.gradient_norm;
  F[2] = jb.value;
  rs[2] = 1 / jb.gradient_norm;
  // x_A - p_B - s n_b = 0.
  F.segment<3>(3) = R * p_A + s_.t - p_B - s * jb.normal;
  rs.segment<3>(3).setOnes();
  // n_b . R c_a = 0: B's normal is normal to A's edge tangent.
  const Eigen::Vector3d c_in_B = R * ca.c;
  F[6] = jb.normal.dot(c_in_B);
  rs[6] = s_.length_scale / ca.c.norm();
  if (!J) return;
  const Eigen::Matrix3d dn_b = jb.normal_derivative();
  J->row(0).segment<3>(0) = ja1.gradient;
  J->row(1).segment<3>(0) = ja2.gradient;
  J->row(2).segment<3>(3) = jb.gradient;
  J->block<3, 3>(3, 0) = R;
  J->block<3, 3>(3, 3) = -Eigen::Matrix3d::Identity() - s * dn_b;
  J->block<3, 1>(3, 6) = -jb.normal;
  J->row(6).segment<3>(0) = ca.dc.transpose() * (R.transpose() * jb.normal);
  J->row(6).segment<3>(3) = dn_b.transpose() * c_in_B;
}

void PairSystem::evaluate_fv(const SmallVector& z, SmallVector& F, SmallMatrix* J,
                             SmallVector& rs) const {
  const Eigen::Vector3d p_A = z.segment<3>(0);
  const double s = z[3];
  const bool jacobian = J != nullptr;
  const SurfaceJet ja = SurfaceJet::at(ga(0), p_A, jacobian);
  const Eigen::Matrix3d& R = s_.R;
  F[0] = ja.value;
  rs[0] = 1 / ja.gradient_norm;
  // x_A - v_B + s R n_a = 0: B's vertex projected onto A's face.
  F.segment<3>(1) = R * p_A + s_.t - vertex_B_ + s * (R * ja.normal);
  rs.segment<3>(1).setOnes();
  if (!J) return;
  J->row(0).segment<3>(0) = ja.gradient;
  J->block<3, 3>(1, 0) = R + s * R * ja.normal_derivative();
  J->block<3, 1>(1, 3) = R * ja.normal;
}

void PairSystem::evaluate_vf(const SmallVector& z, SmallVector& F, SmallMatrix* J,
                             SmallVector& rs) const {
  const Eigen::Vector3d p_B = z.segment<3>(0);
  const double s = z[3];
  const bool jacobian = J != nullptr;
  const SurfaceJet jb = SurfaceJet::at(gb(0), p_B, jacobian);
  F[0] = jb.value;
  rs[0] = 1 / jb.gradient_norm;
  // x_A - p_B - s n_b = 0: A's vertex projected onto B's face.
  F.segment<3>(1) = s_.R * vertex_A_ + s_.t - p_B - s * jb.normal;
  rs.segment<3>(1).setOnes();
  if (!J) return;
  J->row(0).segment<3>(0) = jb.gradient;
  J->block<3, 3>(1, 0) = -Eigen::Matrix3d::Identity() - s * jb.normal_derivative();
  J->block<3, 1>(1, 3) = -jb.normal;
}

}  // namespace pcsg
