#include "engine/generator/state_identity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "engine/contact/element_geometry.h"
#include "engine/generator/parallel_for.h"

namespace pcsg {

RegionSignature region_signature(const std::vector<PointContact>& contacts) {
  RegionSignature sig;
  for (const PointContact& c : contacts) {
    if (c.type != PtcType::EECross) continue;
    sig.emplace_back(static_cast<int>(c.a.kind), c.a.index, static_cast<int>(c.b.kind), c.b.index,
                     crossing_sign(c));
  }
  std::sort(sig.begin(), sig.end());
  return sig;
}

namespace {

// The largest piece of a turn about a contact normal made by one CF-compliant travel (to the
// pose turned further, projected onto the CF): short enough that the straight pose
// interpolation of the travel stays near the turn.
constexpr double kMaxTurnPiece = M_PI / 4;

}  // namespace

TurnedWitness turned_about_normal(const SceneGeometry& scene, const Pose& pose,
                                  const std::vector<PointContact>& contacts, int pivot,
                                  double angle, MotionCounters& counters) {
  TurnedWitness out;
  const PointContact& c = contacts[pivot];
  if (c.normal_B.norm() == 0) return out;
  const ContactFormation cf = ContactFormation::of(contacts);
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(angle) / kMaxTurnPiece)));
  Pose at = pose;
  std::vector<PointContact> found;
  for (int k = 1; k <= pieces; ++k) {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(angle * k / pieces, c.normal_B));
    Pose turned;
    turned.quaternion = (q * pose.quaternion).normalized();
    turned.position = q * (pose.position - c.point_B) + c.point_B;
    const ProjectionResult proj = project_onto_cf(scene, turned, cf);
    ++counters.detections;
    if (!proj.ok || !connected_within_cf(scene, at, proj.pose, cf, counters)) return out;
    at = proj.pose;
    found = proj.contacts;
  }
  std::vector<bool> used(found.size(), false);
  for (const PointContact& want : contacts) {
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < found.size(); ++j) {
      if (used[j] || !(found[j].a == want.a && found[j].b == want.b && found[j].type == want.type))
        continue;
      const double d = (found[j].p_A - want.p_A).norm();
      if (d < best_d) best = static_cast<int>(j), best_d = d;
    }
    if (best < 0) return out;
    used[best] = true;
    out.contacts.push_back(found[best]);
  }
  out.ok = true;
  out.pose = at;
  return out;
}

namespace {

// `X` (a witness of a CF of one e-e-cross contact) turned about the contact normal until the
// edges cross at right angles, the crossing sign kept; not ok otherwise.
TurnedWitness crossing_squared(const SceneGeometry& scene, const Pose& X,
                               MotionCounters& counters) {
  ++counters.detections;
  const ContactReport rep = detect_contacts(scene, X);
  if (rep.penetrating() || rep.contacts.size() != 1 || rep.contacts[0].type != PtcType::EECross)
    return {};
  const PointContact& c = rep.contacts[0];
  // psi: the angle about n from t_A to t_B; turning A by theta turns t_A by theta.
  const double psi = std::atan2(c.normal_B.dot(c.tangent_a_B.cross(c.tangent_b_B)),
                                c.tangent_a_B.dot(c.tangent_b_B));
  const double theta = psi - std::copysign(M_PI / 2, psi);
  return turned_about_normal(scene, X, rep.contacts, 0, theta, counters);
}

bool moved_either_way(const SceneGeometry& scene, const Pose& a, const Pose& b,
                      const ContactFormation& cf, MotionCounters& counters) {
  return connected_within_cf(scene, a, b, cf, counters) ||
         connected_within_cf(scene, b, a, cf, counters);
}

}  // namespace

Pose aligned_by_symmetry(const SceneGeometry& scene, const Pose& a, const Pose& b,
                         const SceneSymmetry& sym) {
  Pose x = a;
  if (sym.B) {
    const Eigen::Vector3d& u = sym.B->direction;
    const Eigen::Vector3d cA = scene.A.bbox.center();
    auto radial = [&](const Pose& X) {
      Eigen::Vector3d r = X.apply(cA) - sym.B->point;
      return Eigen::Vector3d(r - u * u.dot(r));
    };
    const Eigen::Vector3d ra = radial(a), rb = radial(b);
    // A's centre on the axis: no turn aligns better than another.
    if (ra.norm() > scene.tol.distinct_points && rb.norm() > scene.tol.distinct_points)
      x = turned_about_B(x, *sym.B, std::atan2(u.dot(ra.cross(rb)), ra.dot(rb)));
  }
  if (sym.A) {
    // The turn about A's axis closest to the remaining relative rotation (its twist part).
    const Eigen::Quaterniond d = x.quaternion.conjugate() * b.quaternion;
    const double phi = 2 * std::atan2(d.vec().dot(sym.A->direction), d.w());
    x = turned_about_A(x, *sym.A, phi);
  }
  return x;
}

SceneSymmetry SceneSymmetry::of(const SceneGeometry& scene) {
  SceneSymmetry s;
  s.B = axis_of_revolution(scene.B, scene.tol);
  s.A = axis_of_revolution(scene.A, scene.tol);
  s.half_turns_A = half_turn_axes(scene.A, scene.tol, s.A);
  s.half_turns_B = half_turn_axes(scene.B, scene.tol, s.B);
  s.relabelling_A = relabelling_half_turns(scene.A, scene.tol, s.A);
  s.relabelling_B = relabelling_half_turns(scene.B, scene.tol, s.B);
  s.mirrors_A = mirror_planes(scene.A, scene.tol, s.A);
  s.mirrors_B = mirror_planes(scene.B, scene.tol, s.B);
  for (const SymmetryAxis& h : s.relabelling_A)
    s.relabelling_A_elements.push_back(*half_turn_elements(scene.A, scene.tol, h));
  for (const SymmetryAxis& h : s.relabelling_B)
    s.relabelling_B_elements.push_back(*half_turn_elements(scene.B, scene.tol, h));
  for (const MirrorPlane& m : s.mirrors_A)
    s.mirror_A_elements.push_back(*mirror_elements(scene.A, scene.tol, m));
  for (const MirrorPlane& m : s.mirrors_B)
    s.mirror_B_elements.push_back(*mirror_elements(scene.B, scene.tol, m));
  return s;
}

std::vector<Pose> symmetric_images(const Pose& b, const SceneSymmetry& symmetry) {
  std::vector<Pose> images = {b};
  for (const SymmetryAxis& h : symmetry.half_turns_A) images.push_back(turned_about_A(b, h, M_PI));
  for (const SymmetryAxis& h : symmetry.half_turns_B) images.push_back(turned_about_B(b, h, M_PI));
  return images;
}

bool joined_within_cf(const SceneGeometry& scene, const Pose& a, const Pose& b,
                      const ContactFormation& cf, MotionCounters& counters,
                      const SceneSymmetry& symmetry, int midpoint_levels) {
  // b and b turned about each half-turn axis of A or of B: the same configuration
  for (const Pose& target : symmetric_images(b, symmetry)) {
    if (moved_either_way(scene, a, target, cf, counters)) return true;
    if (symmetry.A || symmetry.B) {
      // The turns keep every contact: the turned pose is in a's region by construction.
      const Pose t = aligned_by_symmetry(scene, a, target, symmetry);
      if (moved_either_way(scene, t, target, cf, counters)) return true;
    }
  }
  if (cf.cardinality() == 1 && cf.entries().front().type == PtcType::EECross &&
      midpoint_levels > 0) {
    const TurnedWitness sa = crossing_squared(scene, a, counters);
    const TurnedWitness sb = sa.ok ? crossing_squared(scene, b, counters) : TurnedWitness{};
    if (sa.ok && sb.ok) {
      if (moved_either_way(scene, sa.pose, sb.pose, cf, counters)) return true;
      if (symmetry.A || symmetry.B) {
        const Pose t = aligned_by_symmetry(scene, sa.pose, sb.pose, symmetry);
        if (moved_either_way(scene, t, sb.pose, cf, counters)) return true;
      }
    }
  }
  if (midpoint_levels <= 0) return false;
  // A waypoint: the pose halfway, moved onto the CF (the projection checks it by detection:
  // exactly `cf`, no penetration).
  const ProjectionResult mid = project_onto_cf(scene, between(a, b, 0.5), cf);
  ++counters.detections;
  if (!mid.ok) return false;
  return joined_within_cf(scene, a, mid.pose, cf, counters, symmetry, midpoint_levels - 1) &&
         joined_within_cf(scene, mid.pose, b, cf, counters, symmetry, midpoint_levels - 1);
}

namespace {

// How far apart two poses are: A's centre's travel plus its turn times A's size.
double pose_distance(const Pose& x, const Pose& y, const Eigen::Vector3d& cA, double size) {
  return (x.apply(cA) - y.apply(cA)).norm() + size * x.quaternion.angularDistance(y.quaternion);
}

// Roadmap samples between the witnesses: kRoadmapFractions poses evenly spaced from a to b,
// each also turned by the kRoadmapTurns (radians) about each of A's axes through its centre;
// near each witness: moved by kRoadmapMoves of A's size along each of A's axes and turned by
// twice that (radians) about it. Sized to the failed joins measured: the duplicates of
// Example 1 swapped and of the needle (stress scene) are joined with 11 and 21 of these nodes.
constexpr int kRoadmapFractions = 7;
constexpr double kRoadmapTurns[] = {0.3, -0.3, 0.6, -0.6};
constexpr double kRoadmapMoves[] = {0.1, -0.1, 0.25, -0.25};
// Edges tried: each node toward this many nearest others.
constexpr int kRoadmapNeighbours = 8;

}  // namespace

bool joined_by_roadmap(const SceneGeometry& scene, const Pose& a, const Pose& b,
                       const ContactFormation& cf, const RegionSignature& signature,
                       MotionCounters& counters, RoadmapStats* stats, int threads) {
  const double size = scene.A.bbox.diagonal().norm() / 2;
  const Eigen::Vector3d cA = scene.A.bbox.center();
  std::vector<Pose> starts;
  for (int k = 1; k <= kRoadmapFractions; ++k) {
    const double f = static_cast<double>(k) / (kRoadmapFractions + 1);
    const Pose m = between(a, b, f);
    starts.push_back(m);
    for (int axis = 0; axis < 3; ++axis)
      for (double angle : kRoadmapTurns)
        starts.push_back(turned_about_A(m, {cA, Eigen::Vector3d::Unit(axis)}, angle));
  }
  for (const Pose* w : {&a, &b})
    for (int axis = 0; axis < 3; ++axis)
      for (double move : kRoadmapMoves) {
        starts.push_back(turned_about_A(*w, {cA, Eigen::Vector3d::Unit(axis)}, 2 * move));
        Pose m = *w;
        m.position += move * size * (w->quaternion * Eigen::Vector3d::Unit(axis));
        starts.push_back(m);
      }
  std::vector<Pose> nodes = {a, b};
  std::vector<ProjectionResult> projected(starts.size());
  parallel_for(
      starts.size(), threads, [] { return false; },
      [&](size_t k) { projected[k] = project_onto_cf(scene, starts[k], cf); });
  for (const ProjectionResult& p : projected) {
    ++counters.detections;
    if (p.ok && region_signature(p.contacts) == signature) nodes.push_back(p.pose);
  }
  const int n = static_cast<int>(nodes.size());
  // Union-find over the nodes; a and b are nodes 0 and 1.
  std::vector<int> parent(n);
  for (int i = 0; i < n; ++i) parent[i] = i;
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<std::tuple<double, int, int>> edges;
  for (int i = 0; i < n; ++i) {
    std::vector<std::pair<double, int>> near;
    for (int j = 0; j < n; ++j)
      if (j != i) near.emplace_back(pose_distance(nodes[i], nodes[j], cA, size), j);
    std::sort(near.begin(), near.end());
    for (int k = 0; k < std::min<int>(kRoadmapNeighbours, static_cast<int>(near.size())); ++k)
      edges.emplace_back(near[k].first, std::min(i, near[k].second), std::max(i, near[k].second));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  // The edges in order, each tried unless its ends are joined already; up to `threads` of
  // those still open run at once (ordered_pipeline), and a result is used (its counters
  // merged) only where the order would have tried it, so neither the answer nor the counters
  // depend on the thread count.
  int motions = 0;
  std::vector<char> moved(edges.size(), 0);
  std::vector<MotionCounters> tried(edges.size(), counters.fresh());
  ordered_pipeline(
      edges.size(), threads, jobs_ahead(threads), [] { return false; },
      [&](size_t e) { return root(std::get<1>(edges[e])) == root(std::get<2>(edges[e])); },
      [&](size_t e) {
        const auto& [d, i, j] = edges[e];
        moved[e] = moved_either_way(scene, nodes[i], nodes[j], cf, tried[e]);
      },
      [&](size_t e) {
        const auto& [d, i, j] = edges[e];  // (open: skip(e) was false just before)
        ++motions;
        counters.merge(tried[e]);
        if (moved[e]) parent[root(i)] = root(j);
        return root(0) != root(1);
      });
  if (stats) *stats = {n, motions};
  return root(0) == root(1);
}

namespace {

// The tangent walk's pieces, in A's size (half its box diagonal, as the roadmap's moves): the
// first piece is the roadmap's smaller move, and a piece grows by half after each one that
// holds up to twice that, so that the walk crosses the solids' sizes in a few tens of pieces.
constexpr double kWalkFirstPiece = 0.1;
constexpr double kWalkLongestPiece = 0.2;
// A piece that fails is halved, up to this many times (to 1/8 of it), before the walk stops.
// Measured (session 50): with 3 the needle's far duplicate is joined as with 6, and Example
// 1's two pairs of hands, which no walk joins, take 1,744 queries instead of 3,916.
constexpr int kWalkHalvings = 3;
// Pieces of one walk at most: the experiment that found the walk joined the needle's far
// witnesses in 10.
constexpr int kWalkMaxPieces = 40;
// The direct travel to the goal is tried every this many pieces, and whenever the goal is
// within two pieces.
constexpr int kWalkDirectEvery = 4;

// One walk from `x` (a witness of `cf`, `contacts` its contacts) toward `goal`; true when a
// checked motion reaches it.
bool walk_toward(const SceneGeometry& scene, Pose x, std::vector<PointContact> contacts,
                 const Pose& goal, const ContactFormation& cf, MotionCounters& counters) {
  const double size = scene.A.bbox.diagonal().norm() / 2;
  const Eigen::Vector3d cA = scene.A.bbox.center();
  double piece = kWalkFirstPiece * size;
  for (int k = 0; k < kWalkMaxPieces; ++k) {
    const double d = pose_distance(x, goal, cA, size);
    if ((k % kWalkDirectEvery == 0 || d < 2 * piece) && k > 0 &&
        moved_either_way(scene, x, goal, cf, counters))
      return true;
    // The twist toward the goal about A's centre c, in lengths (v, size * w) ...
    const Eigen::Vector3d c = x.apply(cA);
    const Eigen::AngleAxisd turn(goal.quaternion * x.quaternion.conjugate());
    const double angle = turn.angle() > M_PI ? turn.angle() - 2 * M_PI : turn.angle();
    Eigen::Matrix<double, 6, 1> u;
    u << goal.apply(cA) - c, size * angle * turn.axis();
    // ... with the part that would change the contacts' conditions (their Jacobians, about
    // B's origin: v0 = v + c x w) taken out.
    int rows = 0;
    for (const PointContact& p : contacts) rows += static_cast<int>(p.jacobian.rows());
    Eigen::MatrixXd J(rows, 6);
    int row = 0;
    for (const PointContact& p : contacts) {
      const Eigen::MatrixXd& Jp = p.jacobian;
      J.block(row, 0, Jp.rows(), 3) = Jp.leftCols(3);
      J.block(row, 3, Jp.rows(), 3) = (Jp.leftCols(3) * skew(c) + Jp.rightCols(3)) / size;
      row += static_cast<int>(Jp.rows());
    }
    if (!J.allFinite()) return false;
    const Eigen::Matrix<double, 6, 1> tangent = u - J.completeOrthogonalDecomposition().solve(J * u);
    if (!(tangent.norm() > 0)) return false;
    bool moved = false;
    for (int h = 0; h <= kWalkHalvings && !moved; ++h) {
      if (h > 0) piece /= 2;
      const Eigen::Matrix<double, 6, 1> t = tangent * std::min(1.0, piece / tangent.norm());
      ProjectionOptions seeded;
      seeded.seeds = contacts;  // the contacts just left: the next pose's start points
      const ProjectionResult p =
          project_onto_cf(scene, x.displaced(t.head<3>(), t.tail<3>() / size, c), cf, seeded);
      ++counters.detections;
      if (!p.ok || !(pose_distance(p.pose, goal, cA, size) < d) ||
          !connected_within_cf(scene, x, p.pose, cf, counters))
        continue;
      x = p.pose;
      contacts = p.contacts;
      moved = true;
      piece = std::min(1.5 * piece, kWalkLongestPiece * size);
    }
    if (!moved) return false;
  }
  return false;
}

}  // namespace

bool joined_by_tangent_walk(const SceneGeometry& scene, const Pose& a, const Pose& b,
                            const ContactFormation& cf, MotionCounters& counters,
                            const SceneSymmetry& symmetry) {
  for (const auto& [from, to] : {std::pair{&a, &b}, std::pair{&b, &a}})
    for (const Pose& goal : symmetric_images(*to, symmetry)) {
      // (the turns keep every contact: the start is in the region of `from`)
      const Pose start = aligned_by_symmetry(scene, *from, goal, symmetry);
      ++counters.detections;
      const ContactReport rep = detect_contacts(scene, start);
      if (rep.penetrating() || !(ContactFormation::of(rep.contacts) == cf)) continue;
      if (walk_toward(scene, start, rep.contacts, goal, cf, counters)) return true;
    }
  return false;
}

}  // namespace pcsg
