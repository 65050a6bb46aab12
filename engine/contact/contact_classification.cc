#include "engine/contact/contact_classification.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <vector>

namespace pcsg {
namespace {

// Redirections from one candidate: a face reaches a vertex in two steps (face -> edge ->
// vertex) on each side, and a cone test may step back once; more means a cycle.
constexpr int kMaxRedirects = 8;

const std::string& name_of(const Solid& solid, ElementId id) {
  switch (id.kind) {
    case ElementKind::Face: return solid.faces[id.index].name;
    case ElementKind::Edge: return solid.edges[id.index].name;
    case ElementKind::Vertex: break;
  }
  return solid.vertices[id.index].name;
}

// Two unit vectors spanning the plane normal to n.
// A surface's name for messages (hand-built solids may leave the names out).
std::string surface_name(const Solid& solid, int s) {
  return s >= 0 && s < static_cast<int>(solid.surface_names.size())
             ? solid.surface_names[s]
             : "surface " + std::to_string(s);
}

Eigen::Matrix<double, 3, 2> tangent_basis(const Eigen::Vector3d& n) {
  Eigen::Vector3d u = n.unitOrthogonal();
  Eigen::Matrix<double, 3, 2> T;
  T << u, n.cross(u);
  return T;
}

double min_eigenvalue(const Eigen::Matrix2d& M) {
  const Eigen::Matrix2d S = 0.5 * (M + M.transpose());
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(S, Eigen::EigenvaluesOnly)
      .eigenvalues()[0];
}

// The second fundamental form of a face in the basis T (in the face's frame), positive where
// the face bends away from its outward normal.
Eigen::Matrix2d shape_form(const Polynomial& g, const Eigen::Vector3d& p,
                           const Eigen::Matrix<double, 3, 2>& T) {
  const SurfaceJet j = SurfaceJet::at(g, p);
  return T.transpose() * j.hessian * T / j.gradient_norm;
}

Classification reject(std::string why) {
  Classification c;
  c.verdict = Verdict::Rejected;
  c.reason = std::move(why);
  return c;
}

}  // namespace

bool strictly_inside(const Solid& solid, const Eigen::Vector3d& p, double depth) {
  return worst_violation(solid, SurfaceSet{}, p).distance < -depth;
}

Classification classify_solution(const SceneGeometry& scene, const Pose& X_BA,
                                 const PairSolution& solution) {
  const PointContact& c = solution.contact;
  const Tolerances& tol = scene.tol;
  const SurfaceSet sa = element_surfaces(scene.A, c.a), sb = element_surfaces(scene.B, c.b);
  Classification out;
  out.a = c.a;
  out.b = c.b;
  bool redirect = false;
  // A point outside its element's relative interior: the bounding inequality it crosses
  // names the lower-dimensional element that holds the contact instead.
  auto leave = [&](const Solid& solid, const SurfaceSet& set, const Eigen::Vector3d& p,
                   ElementId& id) -> bool {
    // On the boundary counts as outside: the relative interior is open, and a point on an
    // edge of a face belongs to the edge (the lower-dimensional element wins ties).
    const Violation v = bounding_violation(solid, set, p, tol.on_boundary, tol.tangential_sine);
    if (v.surface < 0 || v.distance < -tol.on_boundary) return true;
    SurfaceSet next = set;
    next.add(v.surface);
    const ElementId e = element_on_surfaces(solid, next, p, id);
    if (e.index < 0) return false;
    id = e;
    redirect = true;
    return true;
  };
  if (!leave(scene.A, sa, c.p_A, out.a))
    return reject("A's point leaves " + name_of(scene.A, c.a) + " across " +
                  surface_name(scene.A, worst_violation(scene.A, sa, c.p_A).surface) +
                  " where no element of A continues it");
  if (!leave(scene.B, sb, c.p_B, out.b))
    return reject("B's point leaves " + name_of(scene.B, c.b) + " across " +
                  surface_name(scene.B, worst_violation(scene.B, sb, c.p_B).surface) +
                  " where no element of B continues it");
  if (redirect) {
    out.verdict = Verdict::Redirect;
    return out;
  }
  if (c.type == PtcType::FF && solution.k <= 0)
    return reject("the faces' normals are not opposite at the stationary point");
  // The contact direction must lie in B's normal cone at p_B and its opposite in A's: an edge
  // or vertex touches only if no adjacent face (edge) is closer (Section II-B: f-e is an edge
  // tangential contact that is not face tangential).
  Eigen::Vector3d d = c.normal_B;
  if (c.type == PtcType::VE || c.type == PtcType::EV || c.type == PtcType::VV ||
      c.type == PtcType::EETouch) {
    // Contact lines have no normal: the separation's direction, when there is one.
    const Eigen::Vector3d D = X_BA.apply(c.p_A) - c.p_B;
    d = D.norm() > tol.contact_gap ? Eigen::Vector3d(D.normalized()) : Eigen::Vector3d::Zero();
  }
  auto cone = [&](const Solid& solid, const SurfaceSet& set, const Eigen::Vector3d& p,
                  const Eigen::Vector3d& dir, ElementId& id) -> bool {
    if (id.kind == ElementKind::Face || dir.isZero()) return true;
    const ConeFit fit = fit_normal_cone(solid, set, p, dir);
    if (fit.distance <= tol.normal_cone) return true;
    if (fit.support.size == 0) return false;
    const ElementId e = element_on_surfaces(solid, fit.support, p, id);
    if (e.index < 0) return false;
    id = e;
    redirect = true;
    return true;
  };
  if (!cone(scene.B, sb, c.p_B, d, out.b))
    return reject("the contact direction leaves the normal cone of B's " +
                  name_of(scene.B, c.b));
  if (!cone(scene.A, sa, c.p_A, -(X_BA.rotation().transpose() * d), out.a))
    return reject("the contact direction leaves the normal cone of A's " +
                  name_of(scene.A, c.a));
  if (redirect) {
    out.verdict = Verdict::Redirect;
    return out;
  }
  out.verdict = is_local_minimum(scene, X_BA, c) ? Verdict::Contact : Verdict::NotMinimum;
  return out;
}

double sliding_curvature(const SceneGeometry& scene, const Pose& X_BA, const PointContact& c) {
  const Eigen::Matrix3d R = X_BA.rotation();
  const Eigen::Vector3d& n = c.normal_B;
  const double s = c.gap;
  auto face_a = [&] { return scene.A.surfaces[scene.A.faces[c.a.index].surface]; };
  auto face_b = [&] { return scene.B.surfaces[scene.B.faces[c.b.index].surface]; };
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  switch (c.type) {
    case PtcType::FF: {
      // The gap over the common tangent plane: s + u^T (K_A + K_B') u / 2, where B's form is
      // that of its surface offset by s (the parallel surface A touches).
      const Eigen::Matrix<double, 3, 2> T = tangent_basis(n);
      const Eigen::Matrix2d KA = shape_form(face_a(), c.p_A, R.transpose() * T);
      const Eigen::Matrix2d KB = shape_form(face_b(), c.p_B, T);
      return min_eigenvalue(KA + KB * (I + s * KB).inverse());
    }
    case PtcType::FE: {
      // Along B's edge: A's normal curvature minus the edge's curvature toward A.
      const Eigen::Vector3d t_A = R.transpose() * c.tangent_b_B;
      const double ka = SurfaceJet::at(face_a(), c.p_A).normal_curvature(t_A);
      return ka - edge_jet(scene.B, c.b.index, c.p_B).curvature.dot(n);
    }
    case PtcType::EF: {
      const double kb = SurfaceJet::at(face_b(), c.p_B).normal_curvature(c.tangent_a_B);
      return (R * edge_jet(scene.A, c.a.index, c.p_A).curvature).dot(n) + kb;
    }
    default:
      return std::numeric_limits<double>::infinity();
  }
}

bool is_ring_contact(const SceneGeometry& scene, const Pose& X_BA, const PointContact& c) {
  return std::abs(sliding_curvature(scene, X_BA, c)) < scene.tol.ring_curvature;
}

bool is_local_minimum(const SceneGeometry& scene, const Pose& X_BA, const PointContact& c) {
  const double L = scene.tol.length_scale;
  const double flat = scene.tol.curvature;  // 1/length
  const Eigen::Matrix3d R = X_BA.rotation();
  const Eigen::Vector3d D = X_BA.apply(c.p_A) - c.p_B;
  const Eigen::Vector3d& n = c.normal_B;
  const double s = c.gap;
  auto face_a = [&] { return scene.A.surfaces[scene.A.faces[c.a.index].surface]; };
  auto face_b = [&] { return scene.B.surfaces[scene.B.faces[c.b.index].surface]; };
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  switch (c.type) {
    case PtcType::FF: case PtcType::FE: case PtcType::EF:
      return sliding_curvature(scene, X_BA, c) >= -flat;
    case PtcType::EECross: {
      // Hessian of |D|^2 / 2 in the two arc lengths.
      const double cross = -c.tangent_a_B.dot(c.tangent_b_B);
      Eigen::Matrix2d H;
      H << 1 + D.dot(R * edge_jet(scene.A, c.a.index, c.p_A).curvature), cross, cross,
          1 - D.dot(edge_jet(scene.B, c.b.index, c.p_B).curvature);
      return min_eigenvalue(H) >= -flat * L;
    }
    case PtcType::FV: {
      const Eigen::Matrix<double, 3, 2> T = tangent_basis(R.transpose() * n);
      return min_eigenvalue(I + s * shape_form(face_a(), c.p_A, T)) >= -flat * L;
    }
    case PtcType::VF:
      return min_eigenvalue(I + s * shape_form(face_b(), c.p_B, tangent_basis(n))) >= -flat * L;
    case PtcType::VE:
      return 1 - D.dot(edge_jet(scene.B, c.b.index, c.p_B).curvature) >= -flat * L;
    case PtcType::EV:
      return 1 + D.dot(R * edge_jet(scene.A, c.a.index, c.p_A).curvature) >= -flat * L;
    case PtcType::VV: case PtcType::EETouch:
      return true;  // a point pair, or pinned by the tangents: no sliding direction to test
  }
  return true;
}

ResolvedContact resolve_contact(const SceneGeometry& scene, const Pose& X_BA, ElementId a,
                                ElementId b, const Eigen::Vector3d& start_A,
                                const Eigen::Vector3d& start_B) {
  ResolvedContact out;
  const int max_iterations = scene.tol.detection_solve_max_iterations;
  Eigen::Vector3d sA = start_A, sB = start_B;
  // The pairs visited and their solutions. A cycle happens only at a tie of the boundary and
  // cone tests (a contact on an element's boundary, within the tolerances): the
  // lower-dimensional pair of the cycle is then the contact.
  std::vector<std::pair<ElementId, ElementId>> visited;
  std::vector<PairSolution> solutions;
  auto dimension = [](ElementId x, ElementId y) {
    return (x.kind == ElementKind::Face ? 2 : x.kind == ElementKind::Edge ? 1 : 0) +
           (y.kind == ElementKind::Face ? 2 : y.kind == ElementKind::Edge ? 1 : 0);
  };
  for (int step = 0; step < kMaxRedirects; ++step) {
    for (size_t k = 0; k < visited.size(); ++k) {
      if (!(visited[k].first == a && visited[k].second == b)) continue;
      size_t best = k;
      for (size_t j = k; j < visited.size(); ++j)
        if (dimension(visited[j].first, visited[j].second) <
            dimension(visited[best].first, visited[best].second))
          best = j;
      out.found = true;
      out.contact = solutions[best].contact;
      out.minimum = is_local_minimum(scene, X_BA, out.contact);
      return out;
    }
    visited.push_back({a, b});
    const PtcType type = ptc_type_between(a.kind, b.kind);
    PairSolution sol = solve_pair_problem(scene, X_BA, a, b, type, sA, sB, max_iterations);
    if (type == PtcType::EECross) {
      // Nearly parallel tangents: the common perpendicular is poorly determined; the touch
      // formulation decides whether they are parallel (pair_touch.h).
      const bool near_parallel =
          !sol.converged || sol.contact.tangent_a_B.cross(sol.contact.tangent_b_B).norm() <
                                scene.tol.near_collinear_sine;
      if (near_parallel) {
        const Eigen::Vector3d tA = sol.converged ? sol.contact.p_A : sA;
        const Eigen::Vector3d tB = sol.converged ? sol.contact.p_B : sB;
        PairSolution touch =
            solve_pair_problem(scene, X_BA, a, b, PtcType::EETouch, tA, tB, max_iterations);
        if (touch.converged &&
            touch.contact.tangent_a_B.cross(touch.contact.tangent_b_B).norm() <
                scene.tol.collinear_sine)
          sol = std::move(touch);
      }
    }
    if (!sol.converged) {
      out.diverged = true;
      out.reason = "the " + std::string(ptc_type_name(type)) + " solve of " +
                   name_of(scene.A, a) + "-" + name_of(scene.B, b) + " does not converge";
      return out;
    }
    const Classification cls = classify_solution(scene, X_BA, sol);
    switch (cls.verdict) {
      case Verdict::Contact: case Verdict::NotMinimum:
        out.found = true;
        out.minimum = cls.verdict == Verdict::Contact;
        out.contact = std::move(sol.contact);
        return out;
      case Verdict::Redirect:
        a = cls.a;
        b = cls.b;
        sA = a.kind == ElementKind::Vertex ? scene.A.vertices[a.index].point : sol.contact.p_A;
        sB = b.kind == ElementKind::Vertex ? scene.B.vertices[b.index].point : sol.contact.p_B;
        solutions.push_back(std::move(sol));
        break;
      case Verdict::Rejected:
        out.reason = cls.reason;
        return out;
    }
  }
  out.reason = "too many reclassifications from " + name_of(scene.A, a) + "-" +
               name_of(scene.B, b);
  return out;
}

}  // namespace pcsg
