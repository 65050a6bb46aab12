// project_onto_cf: Gauss-Newton on the pose with the stacked contact conditions of a contact
// formation (paper Section II-C: a CF's geometric representation is the set of
// configurations satisfying all its PtCs' contact conditions at once).
#include <Eigen/Dense>
#include <algorithm>

#include "engine/contact/contact_classification.h"
#include "engine/contact/contact_context.h"
#include "engine/contact/contact_formation.h"
#include "engine/contact/pair_seeds.h"

namespace pcsg {
namespace {

// Halvings of a Gauss-Newton step before the projection gives up on progress: 2^-10 of the
// first step is below the solve tolerance's reach from any start a motion step away.
constexpr int kMaxHalvings = 10;

struct Tracked {
  ElementId a, b;
  PtcType type;
  PointContact c;  // current solution (points are the next solve's start)
};

// Rows of r in units of length: the e-e-touch misalignment row is dimensionless.
double row_scale(PtcType type, int row, double L) {
  return type == PtcType::EETouch && row == 2 ? L : 1.0;
}

struct Iterate {
  Pose X;
  std::vector<Tracked> tracked;
  Eigen::VectorXd r;  // stacked, in lengths
  Eigen::MatrixXd J;  // rows x 6, twist about B's origin, rows in lengths
  double merit = 0;
};

// Re-solves every tracked contact at X from its previous points and stacks r and J.
bool evaluate(const SceneGeometry& scene, const Pose& X, std::vector<Tracked> tracked,
              Iterate& out, std::string* why) {
  const double L = scene.tol.length_scale;
  int rows = 0;
  for (Tracked& t : tracked) {
    const PairSolution s = solve_pair_problem(scene, X, t.a, t.b, t.type, t.c.p_A, t.c.p_B);
    if (!s.converged || (t.type == PtcType::FF && s.k <= 0)) {
      if (why)
        *why = "the " + std::string(ptc_type_name(t.type)) + " problem of " +
               element_pair_name(scene, t.a, t.b) + " has no solution near pose " + X.str();
      return false;
    }
    t.c = s.contact;
    rows += static_cast<int>(t.c.residual.size());
  }
  out.X = X;
  out.r.resize(rows);
  out.J.resize(rows, 6);
  int row = 0;
  for (const Tracked& t : tracked)
    for (int k = 0; k < t.c.residual.size(); ++k, ++row) {
      const double s = row_scale(t.type, k, L);
      out.r[row] = t.c.residual[k] * s;
      out.J.row(row) = t.c.jacobian.row(k) * s;
    }
  out.merit = out.r.squaredNorm();
  out.tracked = std::move(tracked);
  return true;
}

}  // namespace

ProjectionResult project_onto_cf(const ContactContext& context, const Pose& start,
                                 const ContactFormation& cf, const ProjectionOptions& options) {
  const SceneGeometry& scene = context.scene();
  const Tolerances& tol = scene.tol;
  const double L = tol.length_scale;
  ProjectionResult result;
  result.pose = start;

  // Starting points: the given seeds, then detection at the start pose, then sampling.
  std::vector<PointContact> pool = options.seeds;
  DetectOptions near;
  near.near_margin = context.guaranteed_band();
  const ContactReport at_start = detect_contacts(context, start, near);
  pool.insert(pool.end(), at_start.contacts.begin(), at_start.contacts.end());
  pool.insert(pool.end(), at_start.near.begin(), at_start.near.end());
  std::vector<Tracked> tracked;
  for (const PtcCount& e : cf.entries()) {
    std::vector<PointContact> mine;
    auto take = [&](const std::vector<PointContact>& from) {
      for (const PointContact& c : from) {
        if (static_cast<int>(mine.size()) >= e.count) return;
        if (!(c.a == e.a && c.b == e.b)) continue;
        bool dup = false;
        for (const PointContact& m : mine)
          dup = dup || (m.point_B - c.point_B).norm() <= tol.distinct_points;
        if (!dup) mine.push_back(c);
      }
    };
    take(pool);
    if (static_cast<int>(mine.size()) < e.count)
      take(options.minima ? options.minima->get(context, start, e.a, e.b, e.type)
                          : pair_local_minima(context, start, e.a, e.b, e.type));
    if (static_cast<int>(mine.size()) < e.count) {
      result.reason = "found " + std::to_string(mine.size()) + " of the " +
                      std::to_string(e.count) + " local distance minima of " +
                      element_pair_name(scene, e.a, e.b) + " needed at pose " + start.str();
      return result;
    }
    for (const PointContact& c : mine) tracked.push_back({e.a, e.b, e.type, c});
  }

  // Gauss-Newton with minimum-norm steps in the scaled twist about the contacts' centroid
  // (invariant under moving B's frame and under scaling), halved while they do not reduce |r|.
  Iterate cur;
  if (!evaluate(scene, start, tracked, cur, &result.reason)) return result;
  for (int it = 0;; ++it) {
    result.iterations = it;
    // the residuals are evaluated at the contacts' coordinates in B's frame
    double coordinates = 0;
    for (const Tracked& t : cur.tracked) coordinates = std::max(coordinates, t.c.point_B.norm());
    if (cur.r.size() == 0 || cur.r.cwiseAbs().maxCoeff() <= tol.residual_at(coordinates)) break;
    if (it >= tol.projection_max_iterations) {
      result.reason = "no convergence in " + std::to_string(it) + " iterations (residual " +
                      std::to_string(cur.r.cwiseAbs().maxCoeff()) + ")";
      return result;
    }
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const Tracked& t : cur.tracked) c += t.c.point_B;
    c /= static_cast<double>(cur.tracked.size());
    Eigen::MatrixXd Js(cur.J.rows(), 6);
    Js.leftCols<3>() = cur.J.leftCols<3>();
    Js.rightCols<3>() = (cur.J.leftCols<3>() * skew(c) + cur.J.rightCols<3>()) / L;
    // (Eigen's pivoting decompositions read out of bounds on non-finite input: pair_touch.cc)
    if (!Js.allFinite() || !cur.r.allFinite()) {
      result.reason = "the contacts' rows are not finite";
      return result;
    }
    Eigen::Matrix<double, 6, 1> step = -Js.completeOrthogonalDecomposition().solve(cur.r);
    const double size = std::max(step.head<3>().norm(), step.tail<3>().norm());
    if (size > tol.projection_step) step *= tol.projection_step / size;
    bool accepted = false;
    for (int h = 0; h <= kMaxHalvings && !accepted; ++h, step /= 2) {
      const Pose Y = cur.X.displaced(step.head<3>(), step.tail<3>() / L, c);
      Iterate next;
      if (evaluate(scene, Y, cur.tracked, next, nullptr) && next.merit < cur.merit) {
        cur = std::move(next);
        accepted = true;
      }
    }
    if (!accepted) {
      result.reason = "Gauss-Newton makes no progress at pose " + cur.X.str() +
                      " (residual " + std::to_string(cur.r.cwiseAbs().maxCoeff()) + ")";
      return result;
    }
  }
  result.pose = cur.X.canonical();
  result.max_residual = cur.r.size() ? cur.r.cwiseAbs().maxCoeff() : 0.0;

  // Detection decides: the CF's contacts in their elements, and nothing else touching.
  const ContactReport rep = detect_contacts(context, result.pose);
  result.contacts = rep.contacts;
  if (rep.penetrating()) {
    const Penetration& p = rep.penetrations.front();
    result.reason = "the projected pose penetrates at " + element_pair_name(scene, p.a, p.b) +
                    " (depth " + std::to_string(p.depth / L) + " L)";
    return result;
  }
  const ContactFormation got = ContactFormation::of(rep.contacts);
  if (got != cf) {
    result.reason = "detection at the projected pose gives " + got.str(scene) + " instead of " +
                    cf.str(scene);
    return result;
  }
  result.ok = true;
  return result;
}

ProjectionResult project_onto_cf(const SceneGeometry& scene, const Pose& start,
                                 const ContactFormation& cf, const ProjectionOptions& options) {
  return project_onto_cf(*cached_contact_context(scene), start, cf, options);
}

}  // namespace pcsg
