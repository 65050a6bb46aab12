#include "engine/contact/pair_touch.h"

#include <Eigen/Dense>

#include "engine/contact/element_geometry.h"

namespace pcsg {

TouchSolution solve_touch(const PairSetup& setup, const Eigen::Vector3d& start_A,
                          const Eigen::Vector3d& start_B, const NewtonOptions& options) {
  const double L = options.length_scale;
  const Eigen::Matrix3d& R = setup.R;
  const SurfaceSet sa = element_surfaces(*setup.A, setup.a);
  const SurfaceSet sb = element_surfaces(*setup.B, setup.b);
  const Polynomial* g[4] = {&setup.A->surfaces[sa.index[0]], &setup.A->surfaces[sa.index[1]],
                            &setup.B->surfaces[sb.index[0]], &setup.B->surfaces[sb.index[1]]};
  TouchSolution out;
  out.p_A = start_A;
  out.p_B = start_B;
  double sigma = 0;  // orientation of A's tangent that aligns it with B's, fixed at the start
  for (int it = 0; it < options.max_iterations; ++it) {
    SurfaceJet j[4];
    for (int k = 0; k < 4; ++k) j[k] = SurfaceJet::at(*g[k], k < 2 ? out.p_A : out.p_B);
    const CurveJet ca = CurveJet::of(j[0], j[1]), cb = CurveJet::of(j[2], j[3]);
    if (sigma == 0) sigma = (R * ca.tangent).dot(cb.tangent) < 0 ? -1 : 1;
    const Eigen::Vector3d D = R * out.p_A + setup.t - out.p_B;
    // Constraints in units of L, unknowns in units of L.
    Eigen::Matrix<double, 5, 1> c;
    Eigen::Matrix<double, 5, 6> Jc = Eigen::Matrix<double, 5, 6>::Zero();
    for (int k = 0; k < 4; ++k) {
      c[k] = j[k].value / j[k].gradient_norm / L;
      Jc.row(k).segment<3>(k < 2 ? 0 : 3) = j[k].gradient / j[k].gradient_norm;
    }
    // D . c_b = 0: p_B is the foot of x_A on B's curve.
    const double cbn = cb.c.norm();
    c[4] = D.dot(cb.c) / cbn / L;
    Jc.row(4).segment<3>(0) = R.transpose() * cb.c / cbn;
    Jc.row(4).segment<3>(3) = (-cb.c + cb.dc.transpose() * D) / cbn;
    // The misalignment and its derivative (dimensionless, per unit L of motion).
    const Eigen::Vector3d misalign = sigma * (R * ca.tangent) - cb.tangent;
    Eigen::Matrix<double, 3, 6> Jm;
    Jm.leftCols<3>() = sigma * R * ca.tangent_derivative() * L;
    Jm.rightCols<3>() = -cb.tangent_derivative() * L;
    // A point where an edge's two faces are tangent has no tangent line (Example 2's f2 and
    // f3 at B's bottom pole, a mesh vertex of f3, so a detection start): the rows are not
    // finite, and Eigen's JacobiSVD reads out of bounds on them. No touch is found from there.
    if (!c.allFinite() || !Jc.allFinite() || !Jm.allFinite()) return out;
    // Minimum-norm restoration of the constraints, then the best step along their null space.
    const Eigen::JacobiSVD<Eigen::Matrix<double, 5, 6>> svd(Jc, Eigen::ComputeFullV |
                                                                    Eigen::ComputeFullU);
    const Eigen::Matrix<double, 6, 1> step_c = -svd.solve(c);
    const Eigen::Matrix<double, 6, 1> null = svd.matrixV().col(5);
    const Eigen::Vector3d Jz = Jm * null;
    const double alpha =
        Jz.squaredNorm() > 0 ? -Jz.dot(misalign + Jm * step_c) / Jz.squaredNorm() : 0.0;
    Eigen::Matrix<double, 6, 1> step = step_c + alpha * null;
    if (!step.allFinite()) return out;
    const double big = step.cwiseAbs().maxCoeff();
    if (big > options.max_step) step *= options.max_step / big;
    out.p_A += step.head<3>() * L;
    out.p_B += step.tail<3>() * L;
    if (c.cwiseAbs().maxCoeff() * L <= options.residual && big * L <= options.residual) {
      out.converged = true;
      break;
    }
  }
  const Eigen::Vector3d ta = R * edge_jet(*setup.A, setup.a.index, out.p_A).tangent;
  const Eigen::Vector3d tb = edge_jet(*setup.B, setup.b.index, out.p_B).tangent;
  out.misalignment = ta.cross(tb).norm();  // the sine of the tangents' angle
  return out;
}

}  // namespace pcsg
