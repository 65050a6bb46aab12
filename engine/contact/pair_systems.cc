// The pair systems' set-up, dispatch and interpretation, and the curve and point pairs: e-e
// (common perpendicular), v-e and e-v (point-to-curve feet). pair_systems.h lists the
// equations; pair_systems_faces.cc holds the face pairs.
#include "engine/contact/pair_systems.h"

#include <Eigen/Dense>
#include <stdexcept>

namespace pcsg {
namespace {

int unknowns_of(PtcType type) {
  switch (type) {
    case PtcType::FF: return 8;
    case PtcType::FE: case PtcType::EF: return 7;
    case PtcType::EECross: return 6;
    case PtcType::FV: case PtcType::VF: return 4;
    case PtcType::VE: case PtcType::EV: return 3;
    case PtcType::VV: return 0;
    case PtcType::EETouch: break;
  }
  throw std::invalid_argument("PairSystem: e-e-touch is solved by pair_touch.h");
}

double signed_length(const Eigen::Vector3d& D, const Eigen::Vector3d& n) {
  return D.dot(n) < 0 ? -D.norm() : D.norm();
}

}  // namespace

PairSetup PairSetup::make(const SceneGeometry& scene, const Pose& X_BA, ElementId a,
                          ElementId b) {
  PairSetup s;
  s.A = &scene.A;
  s.B = &scene.B;
  s.a = a;
  s.b = b;
  s.R = X_BA.rotation();
  s.t = X_BA.position;
  s.length_scale = scene.tol.length_scale;
  return s;
}

PairSystem::PairSystem(const PairSetup& setup, PtcType type)
    : s_(setup), type_(type), size_(unknowns_of(type)) {
  if (ptc_kind_a(type) != setup.a.kind || ptc_kind_b(type) != setup.b.kind)
    throw std::invalid_argument(std::string("PairSystem: type ") + ptc_type_name(type) +
                                " does not join the given elements' kinds");
  sa_ = element_surfaces(*s_.A, s_.a);
  sb_ = element_surfaces(*s_.B, s_.b);
  if (s_.a.kind == ElementKind::Vertex) vertex_A_ = s_.A->vertices[s_.a.index].point;
  if (s_.b.kind == ElementKind::Vertex) vertex_B_ = s_.B->vertices[s_.b.index].point;
}

void PairSystem::evaluate(const SmallVector& z, SmallVector& F, SmallMatrix& J,
                          SmallVector& rs) const {
  J.setZero(size_, size_);
  evaluate_rows(z, F, &J, rs);
}

void PairSystem::evaluate_residual(const SmallVector& z, SmallVector& F,
                                   SmallVector& rs) const {
  evaluate_rows(z, F, nullptr, rs);
}

void PairSystem::evaluate_rows(const SmallVector& z, SmallVector& F, SmallMatrix* J,
                               SmallVector& rs) const {
  F.setZero(size_);
  rs.setOnes(size_);
  switch (type_) {
    case PtcType::FF: evaluate_ff(z, F, J, rs); break;
    case PtcType::FE: evaluate_fe(z, F, J, rs); break;
    case PtcType::EF: evaluate_ef(z, F, J, rs); break;
    case PtcType::FV: evaluate_fv(z, F, J, rs); break;
    case PtcType::VF: evaluate_vf(z, F, J, rs); break;
    case PtcType::EECross: evaluate_ee(z, F, J, rs); break;
    case PtcType::VE: evaluate_ve(z, F, J, rs); break;
    case PtcType::EV: evaluate_ev(z, F, J, rs); break;
    case PtcType::VV: case PtcType::EETouch: break;
  }
}

void PairSystem::unknown_scales(SmallVector& scale) const {
  scale.setConstant(size_, s_.length_scale);
  if (type_ == PtcType::FF) scale[7] = 1;  // k is dimensionless
}

void PairSystem::evaluate_ee(const SmallVector& z, SmallVector& F, SmallMatrix* J,
                             SmallVector& rs) const {
  const Eigen::Vector3d p_A = z.segment<3>(0), p_B = z.segment<3>(3);
  const bool jacobian = J != nullptr;
  const SurfaceJet ja1 = SurfaceJet::at(ga(0), p_A, jacobian);
  const SurfaceJet ja2 = SurfaceJet::at(ga(1), p_A, jacobian);
  const SurfaceJet jb1 = SurfaceJet::at(gb(0), p_B, jacobian);
  const SurfaceJet jb2 = SurfaceJet::at(gb(1), p_B, jacobian);
  const CurveJet ca = CurveJet::of(ja1, ja2, jacobian), cb = CurveJet::of(jb1, jb2, jacobian);
  const Eigen::Matrix3d& R = s_.R;
  const SurfaceJet* curves[4] = {&ja1, &ja2, &jb1, &jb2};
  for (int k = 0; k < 4; ++k) {
    F[k] = curves[k]->value;
    rs[k] = 1 / curves[k]->gradient_norm;
  }
  const Eigen::Vector3d D = R * p_A + s_.t - p_B;
  // D . R c_a = 0: d/dp_A = c_a + dc_a^T R^T D, d/dp_B = -R c_a.
  F[4] = D.dot(R * ca.c);
  rs[4] = 1 / ca.c.norm();
  // D . c_b = 0: d/dp_A = R^T c_b, d/dp_B = -c_b + dc_b^T D.
  F[5] = D.dot(cb.c);
  rs[5] = 1 / cb.c.norm();
  if (!J) return;
  for (int k = 0; k < 4; ++k) J->row(k).segment<3>(k < 2 ? 0 : 3) = curves[k]->gradient;
  J->row(4).segment<3>(0) = ca.c + ca.dc.transpose() * (R.transpose() * D);
  J->row(4).segment<3>(3) = -(R * ca.c);
  J->row(5).segment<3>(0) = R.transpose() * cb.c;
  J->row(5).segment<3>(3) = -cb.c + cb.dc.transpose() * D;
}

void PairSystem::evaluate_ve(const SmallVector& z, SmallVector& F, SmallMatrix* J,
                             SmallVector& rs) const {
  const Eigen::Vector3d p_B = z.segment<3>(0);
  const bool jacobian = J != nullptr;
  const SurfaceJet j1 = SurfaceJet::at(gb(0), p_B, jacobian);
  const SurfaceJet j2 = SurfaceJet::at(gb(1), p_B, jacobian);
  const CurveJet cb = CurveJet::of(j1, j2, jacobian);
  F[0] = j1.value;
  rs[0] = 1 / j1.gradient_norm;
  F[1] = j2.value;
  rs[1] = 1 / j2.gradient_norm;
  // (x_A - p_B) . c_b = 0: p_B is the foot of A's vertex on B's edge curve.
  const Eigen::Vector3d D = s_.R * vertex_A_ + s_.t - p_B;
  F[2] = D.dot(cb.c);
  rs[2] = 1 / cb.c.norm();
  if (!J) return;
  J->row(0) = j1.gradient.transpose();
  J->row(1) = j2.gradient.transpose();
  J->row(2) = (-cb.c + cb.dc.transpose() * D).transpose();
}

void PairSystem::evaluate_ev(const SmallVector& z, SmallVector& F, SmallMatrix* J,
                             SmallVector& rs) const {
  const Eigen::Vector3d p_A = z.segment<3>(0);
  const bool jacobian = J != nullptr;
  const SurfaceJet j1 = SurfaceJet::at(ga(0), p_A, jacobian);
  const SurfaceJet j2 = SurfaceJet::at(ga(1), p_A, jacobian);
  const CurveJet ca = CurveJet::of(j1, j2, jacobian);
  F[0] = j1.value;
  rs[0] = 1 / j1.gradient_norm;
  F[1] = j2.value;
  rs[1] = 1 / j2.gradient_norm;
  // (p_A - v_A) . c_a = 0 in A's frame, v_A = B's vertex seen from A.
  const Eigen::Vector3d D = p_A - s_.R.transpose() * (vertex_B_ - s_.t);
  F[2] = D.dot(ca.c);
  rs[2] = 1 / ca.c.norm();
  if (!J) return;
  J->row(0) = j1.gradient.transpose();
  J->row(1) = j2.gradient.transpose();
  J->row(2) = (ca.c + ca.dc.transpose() * D).transpose();
}

SmallVector PairSystem::initial(const Eigen::Vector3d& start_A,
                                const Eigen::Vector3d& start_B) const {
  SmallVector z(size_);
  const Eigen::Matrix3d& R = s_.R;
  const Eigen::Vector3d x_A = R * start_A + s_.t;
  switch (type_) {
    case PtcType::FF:
      z << start_A, start_B, unit_normal_B(start_B).dot(x_A - start_B), 1.0;
      break;
    case PtcType::FE:
      z << start_A, start_B, -(R * unit_normal_A(start_A)).dot(x_A - start_B);
      break;
    case PtcType::EF:
      z << start_A, start_B, unit_normal_B(start_B).dot(x_A - start_B);
      break;
    case PtcType::FV:
      z << start_A, -(R * unit_normal_A(start_A)).dot(x_A - vertex_B_);
      break;
    case PtcType::VF: {
      const Eigen::Vector3d x = R * vertex_A_ + s_.t;
      z << start_B, unit_normal_B(start_B).dot(x - start_B);
      break;
    }
    case PtcType::EECross: z << start_A, start_B; break;
    case PtcType::VE: z << start_B; break;
    case PtcType::EV: z << start_A; break;
    case PtcType::VV: case PtcType::EETouch: break;
  }
  return z;
}

Eigen::Vector3d PairSystem::unit_normal_A(const Eigen::Vector3d& p_A) const {
  return ga(0).gradient(p_A).normalized();
}

Eigen::Vector3d PairSystem::unit_normal_B(const Eigen::Vector3d& p_B) const {
  return gb(0).gradient(p_B).normalized();
}

PairPoints PairSystem::points(const SmallVector& z) const {
  PairPoints out;
  const Eigen::Matrix3d& R = s_.R;
  out.p_A = ptc_kind_a(type_) == ElementKind::Vertex ? vertex_A_ : Eigen::Vector3d(z.head<3>());
  out.p_B = ptc_kind_b(type_) == ElementKind::Vertex ? vertex_B_
            : ptc_kind_a(type_) == ElementKind::Vertex ? Eigen::Vector3d(z.head<3>())
                                                        : Eigen::Vector3d(z.segment<3>(3));
  const Eigen::Vector3d D = R * out.p_A + s_.t - out.p_B;
  switch (type_) {
    case PtcType::FF:
      out.gap = z[6];
      out.k = z[7];
      out.normal_B = unit_normal_B(out.p_B);
      break;
    case PtcType::FE: case PtcType::FV:
      out.gap = z[size_ - 1];
      out.normal_B = -(R * unit_normal_A(out.p_A));
      break;
    case PtcType::EF: case PtcType::VF:
      out.gap = z[size_ - 1];
      out.normal_B = unit_normal_B(out.p_B);
      break;
    case PtcType::EECross: {
      const Eigen::Vector3d t_b = edge_jet(*s_.B, s_.b.index, out.p_B).tangent;
      const Eigen::Vector3d t_a = R * edge_jet(*s_.A, s_.a.index, out.p_A).tangent;
      const Eigen::Vector3d out_of_B = outward_bisector(*s_.B, sb_, out.p_B, t_b);
      Eigen::Vector3d m = t_a.cross(t_b);
      // The common perpendicular, oriented out of B; the bisector when the tangents are
      // exactly parallel (then e-e-touch decides, pair_touch.h).
      if (m.norm() > 0) {
        m.normalize();
        if (m.dot(out_of_B) < 0) m = -m;
        out.normal_B = m;
        out.gap = m.dot(D);
      } else {
        out.normal_B = out_of_B;
        out.gap = signed_length(D, out_of_B);
      }
      break;
    }
    case PtcType::VE: {
      const Eigen::Vector3d t_b = edge_jet(*s_.B, s_.b.index, out.p_B).tangent;
      out.normal_B = outward_bisector(*s_.B, sb_, out.p_B, t_b);
      out.gap = signed_length(D, out.normal_B);
      break;
    }
    case PtcType::EV: {
      const Eigen::Vector3d t_a = edge_jet(*s_.A, s_.a.index, out.p_A).tangent;
      out.normal_B = -(R * outward_bisector(*s_.A, sa_, out.p_A, t_a));
      out.gap = signed_length(D, out.normal_B);
      break;
    }
    case PtcType::VV:
      // No normal (Section II-B); the gap's sign is the side of B's vertex bisector.
      out.gap = signed_length(D, outward_bisector(*s_.B, sb_, out.p_B, Eigen::Vector3d::Zero()));
      break;
    case PtcType::EETouch: break;
  }
  return out;
}

}  // namespace pcsg
