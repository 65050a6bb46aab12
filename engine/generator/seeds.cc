#include "engine/generator/seeds.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>

#include <Eigen/Eigenvalues>

#include "engine/contact/contact_context.h"
#include "engine/contact/convex_support.h"
#include "engine/core/error.h"
#include "engine/generator/motion_drive.h"

namespace pcsg {
namespace {

enum class Contactness { Apart, Touching, Penetrating };

// `nearby` (optional): the triangle pairs that may overlap near X (a bisection bracket).
Contactness classify(const SceneGeometry& scene, const Pose& X, MotionCounters& counters,
                     ContactReport* out = nullptr, const NearbyTriangles* nearby = nullptr) {
  ++counters.detections;
  DetectOptions options;
  options.nearby = nearby;
  ContactReport rep = detect_contacts(*cached_contact_context(scene), X, options);
  const Contactness c = rep.penetrating()        ? Contactness::Penetrating
                        : rep.contacts.empty() ? Contactness::Apart
                                               : Contactness::Touching;
  if (out) *out = std::move(rep);
  return c;
}

// Bisection between an apart pose (t = lo) and a penetrating one (t = hi) along `at(t)` to the
// first touching pose. Returns false when none is found to the solve tolerance.
template <class PoseAt>
bool first_touch(const SceneGeometry& scene, PoseAt at, double lo, double hi,
                 MotionCounters& counters, Pose& touch, ContactReport& rep) {
  // 60 halvings take any bracket of size <= 1e3 L below 1e-15 L.
  constexpr int kMaxBisections = 60;
  // The bracket is a straight motion: its middle's neighbourhood of half its length covers it.
  constexpr double kStraightBracket = 1.0;
  const auto context = cached_contact_context(scene);
  BracketTriangles bracket(*context, kStraightBracket);
  for (int k = 0; k < kMaxBisections; ++k) {
    const NearbyTriangles* nearby = bracket.update(at(lo), at(hi));
    const double mid = 0.5 * (lo + hi);
    const Contactness c = classify(scene, at(mid), counters, &rep, nearby);
    if (c == Contactness::Touching) {
      touch = at(mid);
      return true;
    }
    (c == Contactness::Apart ? lo : hi) = mid;
  }
  return false;
}

// Settles A from its first contact by a compliant motion along -d, keeping the contacts it
// makes and releasing those the push pulls away from. `max_creeps` (< 0: no limit) ends the
// push after that many steps whose located touch adds no contact to the ones kept: the
// bisection then finds the kept contact itself a fraction of the step on (a creep, not a rest).
std::optional<SeedCandidate> settle(const SceneGeometry& scene, Pose X, ContactReport rep,
                                    const Eigen::Vector3d& d, MotionCounters& counters,
                                    int max_creeps) {
  int creeps = 0;
  const double h = scene.tol.motion_step;
  const double size = std::max(scene.A.bbox.diagonal().norm() / 2, 1e-3 * scene.tol.length_scale);
  // Resting takes at most a few sizes of travel.
  const int max_steps = static_cast<int>(6 * size / h);
  std::vector<PointContact> active = rep.contacts;
  for (int step = 0; step < max_steps; ++step) {
    // A lone contact (convex_support.h: its elements lie on convex sets, one strictly convex)
    // is the only contact the objects can have while it lasts, so pushing on only slides it
    // around B and the single contact is the candidate. Measured on Example 1: no push came to
    // rest within its 142 steps, 38 of 42 ended on such a contact; stopping there took the run
    // from 14,592 to 9,988 collision queries with the graph unchanged.
    if (active.size() == 1 && lone_contact(scene, active[0].a, active[0].b)) break;
    const TwistFrame F{X.apply(scene.A.bbox.center()), size};
    // The push: translate along -d, rotation free.
    auto solve_with = [&](const std::vector<PointContact>& keep) {
      DriveSystem sys;
      for (const PointContact& c : keep) sys.add_hard(F.from_origin_jacobian(c.jacobian));
      Eigen::MatrixXd trans = Eigen::MatrixXd::Zero(3, 6);
      trans.leftCols<3>().setIdentity();
      sys.add_drive(trans, -d, 1.0);
      return sys.solve();
    };
    auto s = solve_with(active);
    // Release a contact when the push, without it, would lift it off (a negative multiplier).
    for (size_t k = 0; k < active.size() && active.size() > 1; ++k) {
      std::vector<PointContact> rest = active;
      rest.erase(rest.begin() + k);
      auto s2 = solve_with(rest);
      if (!s2) continue;
      const double lift = (F.from_origin_jacobian(active[k].jacobian) * *s2)(0);
      const double gain_with = s ? -d.dot(s->head<3>()) : 0.0;
      const double gain_without = -d.dot(s2->head<3>());
      if (lift > 0 && gain_without > gain_with + 1e-9) {
        active = rest;
        s = s2;
        break;
      }
    }
    // At rest: the push has no component left along the contacts' free motions.
    constexpr double kRestRelative = 1e-3;  // progress per unit drive below this: resting
    if (!s || -d.dot(s->head<3>()) < kRestRelative * TwistFrame::displacement(*s)) break;
    *s *= h / TwistFrame::displacement(*s);
    // Step with re-projection onto the active contacts.
    Pose Y = F.apply(X, *s);
    bool ok = true;
    for (int it = 0; it < 30; ++it) {
      Eigen::VectorXd r(active.size());
      Eigen::MatrixXd J(active.size(), 6);
      const TwistFrame FY{Y.apply(scene.A.bbox.center()), size};
      for (size_t i = 0; i < active.size(); ++i) {
        ++counters.pair_solves;
        auto c = solve_pair(scene, Y, active[i].a, active[i].b, active[i].type, active[i].p_A,
                            active[i].p_B);
        if (!c) {
          ok = false;
          break;
        }
        active[i] = *c;
        r[i] = c->residual(0);
        J.row(i) = FY.from_origin_jacobian(c->jacobian).row(0);
      }
      if (!ok || r.cwiseAbs().maxCoeff() <= scene.tol.keep_residual) break;
      Y = FY.apply(Y, minimum_norm_step(J, r));
    }
    if (!ok) break;
    ContactReport now;
    const Contactness c = classify(scene, Y, counters, &now);
    ++counters.steps;
    if (c == Contactness::Penetrating || now.contacts.size() > active.size()) {
      // A new contact: find where it starts and keep it from then on.
      const Pose X0 = X;
      const Twist s0 = *s;
      auto at = [&](double t) { return F.apply(X0, s0 * t); };
      Pose touch;
      ContactReport trep;
      if (!first_touch(scene, at, 0.0, 1.0, counters, touch, trep)) break;
      if (trep.contacts.size() <= active.size() && max_creeps >= 0 && ++creeps > max_creeps) break;
      X = touch;
      active = trep.contacts;
      continue;
    }
    X = Y;
    active = now.contacts;
    if (active.empty()) break;  // slid off: no resting state this way
  }
  ContactReport fin;
  if (classify(scene, X, counters, &fin) != Contactness::Touching) return std::nullopt;
  SeedCandidate out{ContactFormation::of(fin.contacts), X, fin.contacts};
  const ProjectionResult proj = project_onto_cf(scene, X, out.cf);
  if (proj.ok) {
    ContactReport pr;
    if (classify(scene, proj.pose, counters, &pr) == Contactness::Touching &&
        ContactFormation::of(pr.contacts) == out.cf) {
      out.pose = proj.pose;
      out.contacts = pr.contacts;
    }
  }
  return out;
}

// A solid's principal frame (columns: axes of its mesh vertices' second moments about the
// bounding-box centre, largest spread first, right-handed), so that the seed search moves with
// the objects when the scene is moved or rotated (the graph must not depend on B's frame).
Eigen::Matrix3d principal_frame(const SolidMesh& mesh, const Eigen::Vector3d& centre) {
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : mesh.positions) C += (p - centre) * (p - centre).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
  Eigen::Matrix3d R;
  // Eigen sorts eigenvalues increasingly: the largest spread first.
  for (int k = 0; k < 3; ++k) R.col(k) = eig.eigenvectors().col(2 - k);
  // Fix each axis' sign by the mesh's third moment along it (deterministic for a given
  // shape), then make the frame right-handed.
  for (int k = 0; k < 2; ++k) {
    double m3 = 0;
    for (const Eigen::Vector3d& p : mesh.positions) m3 += std::pow(R.col(k).dot(p - centre), 3);
    if (m3 < 0) R.col(k) *= -1;
  }
  R.col(2) = R.col(0).cross(R.col(1));
  return R;
}

// The mesh's extent along each column of R (its principal frame about `centre`).
Eigen::Vector3d principal_extent(const SolidMesh& mesh, const Eigen::Vector3d& centre,
                                 const Eigen::Matrix3d& R) {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : mesh.positions) {
    const Eigen::Vector3d q = R.transpose() * (p - centre);
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  return hi - lo;
}

}  // namespace

std::vector<SeedCandidate> find_seed_candidates(const SceneGeometry& scene,
                                                MotionCounters& counters, int threads) {
  // Push directions: the six axes and the eight diagonals; orientations: A as given and turned
  // a quarter about x and about y, so each of A's principal directions meets B at least once
  // (in B's and A's principal frames). Then the off-centre pushes below.
  std::vector<Eigen::Vector3d> dirs;
  for (int a = 0; a < 3; ++a)
    for (double sgn : {-1.0, 1.0}) {
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      d[a] = sgn;
      dirs.push_back(d);
    }
  for (double x : {-1.0, 1.0})
    for (double y : {-1.0, 1.0})
      for (double z : {-1.0, 1.0}) dirs.push_back(Eigen::Vector3d(x, y, z).normalized());
  const std::vector<Eigen::Quaterniond> turns = {
      Eigen::Quaterniond::Identity(),
      Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX())),
      Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()))};

  const Eigen::Vector3d cB = scene.B.bbox.center();
  const Eigen::Matrix3d R_B = principal_frame(scene.mesh_B, cB);
  const Eigen::Matrix3d R_A = principal_frame(scene.mesh_A, scene.A.bbox.center());
  // Pushes (direction, aim, turn) in B's principal frame: each direction at B's centre in each
  // turn; and for the six axes also at points off the centre across the push, kOffAxis of B's
  // half-extent along each other axis, with A's longest axis along the third (across the
  // push and the offset), so that a long A comes down across B's edges away from the centre
  // (a needle across a dish's rim, which no push at the centre lands on). 0.6: inside the
  // paper's dish rim (radius 0.79 of B's half-extent), where its chords (4.2 long) are
  // shorter than Example 1's ellipsoid and the needle (5).
  constexpr double kOffAxis = 0.6;
  // The off-centre pushes look for a rest across an edge, a few located touches away; one
  // that creeps (a bisection gaining no contact) more than kOffAxisCreeps times is not
  // coming to such a rest. Measured: without a limit two of Example 1's 24 off-centre pushes
  // crept for 5,326 and 2,840 queries to a single contact (Example 1 19,423 -> 29,185
  // queries); the needle's four that rest across the rim take 84 to 114 queries and more
  // than 3 creeps (with 3, three of them stopped at a single contact); 6 keeps all four
  // (Example 1's seed search: 3,126 queries before the off-centre pushes, 4,902 with them).
  constexpr int kOffAxisCreeps = 6;
  struct Push {
    Eigen::Vector3d d, aim;
    Eigen::Matrix3d turn;
    int max_creeps = -1;
  };
  std::vector<Push> pushes;
  for (const Eigen::Vector3d& d : dirs)
    for (const Eigen::Quaterniond& q : turns)
      pushes.push_back({d, Eigen::Vector3d::Zero(), q.toRotationMatrix()});
  const Eigen::Vector3d half = 0.5 * principal_extent(scene.mesh_B, cB, R_B);
  for (int a = 0; a < 3; ++a)
    for (double sgn : {-1.0, 1.0})
      for (int o = 1; o < 3; ++o)
        for (double side : {-1.0, 1.0}) {
          Push p{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero(),
                 kOffAxisCreeps};
          p.d[a] = sgn;
          const int k = (a + o) % 3, m = (a + 3 - o) % 3;
          p.aim[k] = side * kOffAxis * half[k];
          p.turn.col(0) = Eigen::Vector3d::Unit(m);
          p.turn.col(1) = Eigen::Vector3d::Unit(k);
          p.turn.col(2) = p.turn.col(0).cross(p.turn.col(1));
          pushes.push_back(p);
        }
  const size_t centre_jobs = dirs.size() * turns.size();
  const double reach = scene.B.bbox.diagonal().norm() / 2 + scene.A.bbox.diagonal().norm() / 2;
  // One job per push, each a pure function of the scene: run on `threads` threads and
  // gathered in job order, so the candidates do not depend on the thread count.
  const size_t jobs = pushes.size();
  std::vector<std::optional<SeedCandidate>> found(jobs);
  std::vector<MotionCounters> job_counters(jobs);
  auto run_job = [&](size_t job) {
    const Eigen::Vector3d d = R_B * pushes[job].d;
    const Eigen::Vector3d target = cB + R_B * pushes[job].aim;
    const Eigen::Matrix3d& turn = pushes[job].turn;
    MotionCounters& counters = job_counters[job];
    {
      // A starts outside B along d and moves toward the aim until it first touches.
      auto at = [&](double t) {
        Pose X;
        // A's principal frame aligned with B's, then turned.
        X.quaternion = Eigen::Quaterniond(R_B * turn * R_A.transpose()).normalized();
        X.position = target + d * (reach * (1.0 - t)) - (X.quaternion * scene.A.bbox.center());
        return X;
      };
      ContactReport rep;
      if (classify(scene, at(0.0), counters) != Contactness::Apart) return;
      // March in steps of the motion step (relative to the reach) until not apart.
      const double dt = scene.tol.motion_step / reach;
      double t = 0;
      Contactness c = Contactness::Apart;
      while (t < 1.0 && c == Contactness::Apart) {
        t = std::min(1.0, t + dt);
        c = classify(scene, at(t), counters, &rep);
      }
      Pose touch = at(t);
      if (c == Contactness::Penetrating &&
          !first_touch(scene, at, t - dt, t, counters, touch, rep))
        return;
      if (c == Contactness::Apart) return;
      found[job] = settle(scene, touch, rep, d, counters, pushes[job].max_creeps);
    }
  };
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t job; (job = next.fetch_add(1)) < jobs;) run_job(job);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min<int>(threads, static_cast<int>(jobs)); ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  // The centre pushes' candidates first, then the off-centre ones, each group by cardinality
  // (highest first) and CF (the generator holds the second group back: generator.cc).
  auto by_cardinality = [](const SeedCandidate& a, const SeedCandidate& b) {
    if (a.cf.cardinality() != b.cf.cardinality()) return a.cf.cardinality() > b.cf.cardinality();
    return a.cf < b.cf;
  };
  std::vector<SeedCandidate> out, off_centre;
  for (size_t job = 0; job < jobs; ++job) {
    counters.merge(job_counters[job]);
    if (!found[job]) continue;
    found[job]->off_centre = job >= centre_jobs;
    (job < centre_jobs ? out : off_centre).push_back(std::move(*found[job]));
  }
  std::stable_sort(out.begin(), out.end(), by_cardinality);
  std::stable_sort(off_centre.begin(), off_centre.end(), by_cardinality);
  out.insert(out.end(), std::make_move_iterator(off_centre.begin()),
             std::make_move_iterator(off_centre.end()));
  return out;
}

SeedCandidate seed_from_pose(const SceneGeometry& scene, const SeedSpec& seed,
                             MotionCounters& counters) {
  ContactReport rep;
  const Contactness c = classify(scene, seed.pose, counters, &rep);
  if (c == Contactness::Penetrating) {
    const Penetration& p = rep.penetrations.front();
    char buf[160];
    std::snprintf(buf, sizeof buf, "penetration depth %.3g at (%.4g, %.4g, %.4g)", p.depth,
                  p.point_B.x(), p.point_B.y(), p.point_B.z());
    throw SceneError(seed.where, "seed pose \"" + seed.pose.str() + "\" penetrates: " +
                                     scene.A.element_name(p.a) + " inside " +
                                     scene.B.element_name(p.b) + ", " + buf);
  }
  if (c == Contactness::Apart) {
    // A pose written by hand touches only to its digits, while touching means a gap below
    // tol.contact_gap (1e-9 L). Poses within the detection band of a contact are snapped onto
    // the CF of the distance minima in that band: 1e-3 L is four significant digits of a pose
    // in B's size, and beyond the band detection reports no minima to snap onto.
    const ContactContext& context = *cached_contact_context(scene);
    DetectOptions options;
    options.near_margin = context.guaranteed_band();
    options.recall = false;
    rep = detect_contacts(context, seed.pose, options);
    ++counters.detections;
    if (rep.near.empty()) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%.3g", options.near_margin);
      throw SceneError(seed.where, "seed pose \"" + seed.pose.str() +
                                       "\" touches nothing, and no element pair is within " + buf +
                                       " (the snapping band): a seed must be a contact state");
    }
    rep.contacts = rep.near;
  }
  SeedCandidate out{ContactFormation::of(rep.contacts), seed.pose, rep.contacts};
  ProjectionOptions projection;
  projection.seeds = rep.contacts;
  const ProjectionResult proj = project_onto_cf(scene, seed.pose, out.cf, projection);
  if (!proj.ok)
    throw SceneError(seed.where, "seed pose cannot be projected onto " + out.cf.str(scene) +
                                     ": " + proj.reason);
  out.pose = proj.pose;
  classify(scene, out.pose, counters, &rep);
  out.contacts = rep.contacts;
  return out;
}

}  // namespace pcsg
