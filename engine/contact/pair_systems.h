#pragma once
// The stationarity systems of the local distance problem between one element of A and one of
// B (paper Section II-B types), as square systems F(z) = 0 with analytic Jacobians.
//
// Where a face is involved the systems are "common normal" formulations: the gap s is an
// unknown and the points are joined along a face normal, x_A - p_B = s n. Unlike the
// Lagrange conditions of min |x_A - p_B|^2 they stay regular at touching (s = 0), where the
// distance's Hessian loses the curvature terms; their Jacobian is singular only where the
// relative curvature is (a non-isolated contact). Points and tangents of A are in A's frame,
// of B in B's frame; x_A = R p_A + t is A's point seen from B.
//
//   f-f  z = (p_A, p_B, s, k): g_a = 0, g_b = 0, x_A - p_B - s n_b = 0, R n_a + k n_b = 0
//   f-e  z = (p_A, p_B, s):    g_a = 0, g_b1 = g_b2 = 0, x_A - p_B + s R n_a = 0,
//                              n_a . R^T t_b = 0 (the face normal is normal to the edge)
//   e-f  z = (p_A, p_B, s):    g_a1 = g_a2 = 0, g_b = 0, x_A - p_B - s n_b = 0, n_b . R t_a = 0
//   f-v  z = (p_A, s):         g_a = 0, x_A - v_B + s R n_a = 0
//   v-f  z = (p_B, s):         g_b = 0, x_A - p_B - s n_b = 0
//   e-e  z = (p_A, p_B):       curve equations, D . R t_a = 0, D . t_b = 0 (D = x_A - p_B):
//                              the common perpendicular, regular at touching while the
//                              tangents cross (e-e-touch: pair_touch.h)
//   v-e  z = (p_B):            g_b1 = g_b2 = 0, (x_A - p_B) . t_b = 0
//   e-v  z = (p_A):            g_a1 = g_a2 = 0, (p_A - v_A) . t_a = 0 (v_A: B's vertex in A)
// v-v has no unknowns.
#include <Eigen/Core>

#include "engine/contact/contact.h"
#include "engine/contact/element_geometry.h"
#include "engine/contact/newton_solver.h"

namespace pcsg {

// One element pair at one pose.
struct PairSetup {
  const Solid* A = nullptr;
  const Solid* B = nullptr;
  ElementId a, b;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // X_BA's rotation
  Eigen::Vector3d t = Eigen::Vector3d::Zero();      // X_BA's translation
  double length_scale = 1;

  static PairSetup make(const SceneGeometry& scene, const Pose& X_BA, ElementId a, ElementId b);
};

// A pair problem's solution in geometric terms.
struct PairPoints {
  Eigen::Vector3d p_A = Eigen::Vector3d::Zero();  // A's frame
  Eigen::Vector3d p_B = Eigen::Vector3d::Zero();  // B's frame
  double gap = 0;                                 // signed
  Eigen::Vector3d normal_B = Eigen::Vector3d::Zero();
  double k = 1;  // f-f: ratio of the normals, +1 when they are opposite (a contact)
};

class PairSystem final : public SquareSystem {
 public:
  // `type` must join the kinds of setup.a and setup.b; not EETouch (pair_touch.h).
  PairSystem(const PairSetup& setup, PtcType type);
  int size() const override { return size_; }
  void evaluate(const SmallVector& z, SmallVector& F, SmallMatrix& J,
                SmallVector& row_scale) const override;
  void evaluate_residual(const SmallVector& z, SmallVector& F,
                         SmallVector& row_scale) const override;
  void unknown_scales(SmallVector& scale) const override;

  // The unknowns for starting points near the elements (A's frame, B's frame).
  SmallVector initial(const Eigen::Vector3d& start_A, const Eigen::Vector3d& start_B) const;
  // Points, signed gap and normal (from B toward A) of a solution. For e-e the normal is the
  // common perpendicular oriented out of B; for v-e, e-v and v-v the gap is |D| signed by
  // the side of the edge's (vertex's) outward bisector, and the normal that bisector.
  PairPoints points(const SmallVector& z) const;
  // e-e-cross only (no-op otherwise): refines a solution z whose tangents are nearly parallel,
  // where the common slide of both points along the rims is poorly conditioned in the Newton
  // system (pair_crossing.cc). Moves the points by at most max_shift in all.
  void polish_crossing(SmallVector& z, double max_shift, int max_iterations) const;
  // e-e-cross only: minimises |x_A - p_B|^2 over the two curves from z by Newton steps in the
  // arc lengths, halved until the distance drops, until it drops no more (for starts where
  // solve_square_system fails). True when the common-perpendicular rows are then below
  // options.residual.
  bool descend_crossing(SmallVector& z, const NewtonOptions& options) const;

 private:
  // F and the row scales, and J (set to zero by the caller) unless it is null: without J the
  // jets skip the Hessians, and F and the scales are the same bits.
  void evaluate_rows(const SmallVector& z, SmallVector& F, SmallMatrix* J, SmallVector& rs) const;
  void evaluate_ff(const SmallVector& z, SmallVector& F, SmallMatrix* J, SmallVector& rs) const;
  void evaluate_fe(const SmallVector& z, SmallVector& F, SmallMatrix* J, SmallVector& rs) const;
  void evaluate_ef(const SmallVector& z, SmallVector& F, SmallMatrix* J, SmallVector& rs) const;
  void evaluate_fv(const SmallVector& z, SmallVector& F, SmallMatrix* J, SmallVector& rs) const;
  void evaluate_vf(const SmallVector& z, SmallVector& F, SmallMatrix* J, SmallVector& rs) const;
  void evaluate_ee(const SmallVector& z, SmallVector& F, SmallMatrix* J, SmallVector& rs) const;
  void evaluate_ve(const SmallVector& z, SmallVector& F, SmallMatrix* J, SmallVector& rs) const;
  void evaluate_ev(const SmallVector& z, SmallVector& F, SmallMatrix* J, SmallVector& rs) const;

  Eigen::Vector3d unit_normal_A(const Eigen::Vector3d& p_A) const;  // of A's face
  Eigen::Vector3d unit_normal_B(const Eigen::Vector3d& p_B) const;  // of B's face
  const Polynomial& ga(int k) const { return s_.A->surfaces[sa_.index[k]]; }
  const Polynomial& gb(int k) const { return s_.B->surfaces[sb_.index[k]]; }

  PairSetup s_;
  PtcType type_;
  int size_ = 0;
  SurfaceSet sa_, sb_;                                  // the elements' surfaces
  Eigen::Vector3d vertex_A_ = Eigen::Vector3d::Zero();  // A's vertex (A's frame)
  Eigen::Vector3d vertex_B_ = Eigen::Vector3d::Zero();  // B's vertex (B's frame)
};

}  // namespace pcsg
