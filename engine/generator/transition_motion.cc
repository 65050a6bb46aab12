#include "engine/generator/transition_motion.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "engine/contact/contact_context.h"
#include "engine/contact/contact_formation.h"
#include "engine/contact/element_geometry.h"
#include "engine/generator/motion_drive.h"

namespace pcsg {
namespace {

enum class Phase { Drive, Settle, Done };

// One contact of the starting state, followed through the motion.
struct Track {
  PointContact c;
  ContactPlan plan;
  Phase phase = Phase::Drive;
  int settle_left = 0;
  ElementId left;  // after an event: the element the contact left on the changing side
  // Drive progress: the best distance to the goal so far (a length, or an angle times the
  // reference size for rotations) and the steps since it last improved.
  double best_to_goal = std::numeric_limits<double>::infinity();
  int stalled = 0;
};

// After an event, this many steps carry the changed contact into the interior of its new
// region, so that the witness is classified with a margin of ~a step, not at the boundary.
constexpr int kSettleSteps = 3;
// Events are located to 2^-30 of a step (~1e-11 L for the default step).
constexpr int kBisections = 30;
constexpr int kCorrectionIterations = 30;
// A step that cannot be corrected is halved at most this many times before giving up.
constexpr int kMaxHalvings = 6;
// Motions longer than this many times the reference body's size (twist_frame.h) are
// abandoned (none of the paper's transitions travels more than ~2 sizes).
constexpr double kMaxTravelSizes = 12.0;
// A detected contact is matched to a tracked one of the same pair within this many steps.
constexpr double kMatchSteps = 3.0;
// The last hop of a motion toward a given pose (travel_to) is split into at most this many
// pieces: h / 8 ~ 1e-3 L, the meshes' chordal error, under the thinnest solid of the stress
// scenes (the needle's radius, 1.9e-3 L).
constexpr int kMaxLastHopPieces = 8;
// A changing contact whose distance to its goal has not shrunk by kMinProgress steps within
// kMaxStalledSteps steps is not going to arrive this way (a drive circling or blocked).
constexpr double kMinProgress = 0.01;
constexpr int kMaxStalledSteps = 20;
// The triangle pairs gathered for an event's bracket cover poses this many times farther from
// its middle than the bracket's ends: the corrected poses tried by bisection stray from the
// straight step by second-order amounts only (a pose outside is queried in full).
constexpr double kBracketMargin = 1.25;

bool maintained(const Track& t) { return t.plan.action != ContactAction::Remove; }

// The contact normal that a change on one side turns toward the new element's normal: the
// outward normal of that side's solid, in its frame (normal_in_A for A, normal_B for B). An
// e-e-touch has no normal of its own: normal_B is B's rim bisector by convention, which no
// motion of A turns, so for a change on B's side it is A's rim bisector, reversed (the drive
// then turns A's rim cone about the tangent until the new face's normal lies in it).
Eigen::Vector3d changing_side_normal(const SceneGeometry& scene, const Pose& X,
                                     const PointContact& c, bool on_a) {
  if (on_a) return normal_in_A(X, c);
  if (c.type != PtcType::EETouch) return c.normal_B;
  const Eigen::Vector3d t_a = edge_jet(scene.A, c.a.index, c.p_A).tangent;
  return -(X.rotation() * outward_bisector(scene.A, element_surfaces(scene.A, c.a), c.p_A, t_a));
}

// Tracks that keep every given contact (connectivity motions and upward probes).
std::vector<Track> keep_all(const std::vector<PointContact>& contacts) {
  std::vector<Track> tracks;
  for (const PointContact& c : contacts)
    tracks.push_back(Track{c, ContactPlan{}, Phase::Drive, 0, ElementId{},
                           std::numeric_limits<double>::infinity(), 0});
  return tracks;
}

std::string fmt_point(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return buf;
}

struct Observation {
  enum Kind { Same, Event, Missing, Collision, KeptChanged } kind = Same;
  bool new_contact = false;  // a Collision that is a new touching contact, not penetration
  int track = -1;            // for Event / KeptChanged
  PointContact detected;     // the contact that differs
  std::string what;          // for Collision / KeptChanged
  std::vector<PointContact> contacts;
};

class Motion {
 public:
  Motion(const SceneGeometry& scene, const Pose& start, std::vector<Track> tracks,
         const ContactFormation& target, const MotionVariant& variant, MotionCounters& counters,
         const MotionObserver& observer)
      : scene_(scene),
        tracks_(std::move(tracks)),
        target_(target),
        variant_(variant),
        counters_(counters),
        observer_(observer),
        X_(start),
        context_(cached_contact_context(scene)),
        reference_(scene) {
    h_ = scene.tol.motion_step;
    max_steps_ = static_cast<int>(kMaxTravelSizes * reference_.size / h_) + 10 * kSettleSteps;
  }

  MotionOutcome run();
  const Pose& pose() const { return X_; }
  const PointContact& contact(int i) const { return tracks_[i].c; }
  double size() const { return reference_.size; }
  // CF-compliant travel toward `to` keeping every tracked contact (all Keep). With
  // `by_contacts` the drive moves each contact's points on A and on B toward the target's
  // (sliding and rolling over the elements); otherwise it moves the pose straight toward it.
  bool travel_to(const Pose& to, bool by_contacts);
  // Pushes A with the drive twist `drive` (recomputed every step) until a new contact is met;
  // `progress` must keep decreasing (to zero at the end of the push).
  std::optional<Discovery> probe(const std::function<Twist(const TwistFrame&)>& drive,
                                 const std::function<double()>& progress);

 private:
  TwistFrame frame_at(const Pose& X) const { return reference_.frame_at(X); }
  bool resolve(const Pose& Y, std::vector<Track>& tracks, int* lost) const;
  // Re-projects Y onto the maintained contacts. On failure, `lost` names the contact whose
  // pair solve failed (its point left its element), or is -1 when Newton did not converge.
  std::optional<Pose> correct(Pose Y, std::vector<Track>& tracks, int* lost = nullptr) const;

  // `nearby` (optional) holds the triangle pairs that may overlap near Y (bisection brackets).
  Observation classify(const Pose& Y, const std::vector<Track>& tracks,
                       const NearbyTriangles* nearby = nullptr) const;

  bool add_drive(const Track& t, const TwistFrame& F, DriveSystem& sys);
  void add_edge_rotation(const Track& t, const TwistFrame& F,
                         const Eigen::Matrix<double, 3, 6>& dn, const Eigen::Vector3d& dir,
                         DriveSystem& sys) const;
  void emit(const char* phase, const std::vector<PointContact>& contacts,
            const Observation* collision = nullptr) const;
  // After a step X_ -> F.apply(X_, s) whose observation `obs` was located by bisection at
  // the step fraction `lo` (the last pose like X_): when a settling contact leaves its new
  // region across the far side, settles it in the middle of the region along the step.
  bool settle_within_step(const Observation& obs, const TwistFrame& F, const Twist& s,
                          double lo);
  // Changing e-e-touch contacts bound for a face continue as the new pair as soon as that
  // pair is a contact at the touch point.
  void leave_touches();
  MotionOutcome fail(const std::string& why) const {
    MotionOutcome o;
    o.reason = why;
    o.motion = name();
    o.steps = step_;
    o.end = X_;
    o.general_stop = general_stop_;
    o.discovered = met_;
    return o;
  }
  std::string name() const;
  // The exact state of the contacts met at X_ (a new contact appeared), when it is one.
  std::optional<Discovery> discover(const std::vector<PointContact>& contacts) const;
  // How far a changing contact still is from its goal: the distance of its point to the goal
  // element when approaching one, the reference size times the angle between the contact
  // normal and the goal's when leaving an edge or vertex by rotation.
  double distance_to_goal(const Track& t) const;
  // The unit tangent, in its solid's frame, of the edge on A's side (on_a) or B's side of a
  // contact (zero when that side is not an edge).
  Eigen::Vector3d edge_tangent(const Track& t, bool on_a) const;
  // Drift of the kept contacts and penetration at the midpoint of the step X -> Y, where the
  // motion is not re-projected: the discretisation error of the step grid.
  void measure_midpoint(const Pose& X, const Pose& Y);

  const SceneGeometry& scene_;
  std::vector<Track> tracks_;
  const ContactFormation& target_;
  MotionVariant variant_;
  bool general_stop_ = false;     // MotionOutcome::general_stop
  std::optional<Discovery> met_;  // a state above, met where settling stopped before it
  MotionCounters& counters_;
  const MotionObserver& observer_;
  Pose X_;
  std::shared_ptr<const ContactContext> context_;
  ReferenceBody reference_;  // the twists' origin and length scale
  double h_ = 0;
  int max_steps_ = 0, step_ = 0;
  bool used_rotation_drive_ = false;
};

std::string Motion::name() const {
  bool a_changes = false, b_changes = false, removes = false;
  for (const Track& t : tracks_) {
    if (t.plan.action == ContactAction::Change) (t.plan.changes_a ? a_changes : b_changes) = true;
    if (t.plan.action == ContactAction::Remove) removes = true;
  }
  std::string n;
  auto add = [&](const char* part) { n += n.empty() ? part : std::string("+") + part; };
  if (!variant_.fix_unchanged_side && (a_changes || b_changes)) {
    add("combined");
  } else {
    if (b_changes) add("slidingA");
    if (a_changes) add("slidingB");
  }
  if (used_rotation_drive_ || (removes && variant_.remove_by_rotation)) add("rotation");
  if (removes && !variant_.remove_by_rotation) add("separation");
  if (variant_.turn != 0) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "@%+.0fdeg", variant_.turn * 180 / M_PI);
    n += buf;
  }
  if (variant_.normal_drive)
    n += "@normal";
  else if (variant_.general_settling)
    n += "@general";
  return n;
}

std::optional<Discovery> Motion::discover(const std::vector<PointContact>& contacts) const {
  Discovery d;
  d.cf = ContactFormation::of(contacts);
  const ProjectionResult proj = project_onto_cf(scene_, X_, d.cf);
  if (!proj.ok) return std::nullopt;
  ++counters_.detections;
  const ContactReport rep = detect_contacts(scene_, proj.pose);
  if (rep.penetrating() || !(ContactFormation::of(rep.contacts) == d.cf)) return std::nullopt;
  d.pose = proj.pose;
  d.contacts = rep.contacts;
  return d;
}

Eigen::Vector3d Motion::edge_tangent(const Track& t, bool on_a) const {
  const Eigen::Vector3d tangent = on_a
                                      ? Eigen::Vector3d(X_.rotation().transpose() * t.c.tangent_a_B)
                                      : Eigen::Vector3d(t.c.tangent_b_B);
  return tangent.norm() > 0 ? tangent.normalized() : Eigen::Vector3d::Zero();
}

double Motion::distance_to_goal(const Track& t) const {
  const bool on_a = t.plan.changes_a;
  const Solid& S = on_a ? scene_.A : scene_.B;
  const ElementId current = on_a ? t.c.a : t.c.b;
  const ElementId goal = on_a ? t.plan.new_a : t.plan.new_b;
  const Eigen::Vector3d x = on_a ? t.c.p_A : t.c.p_B;
  if (element_dimension(goal) < element_dimension(current)) {
    if (goal.kind == ElementKind::Vertex) return (S.vertices[goal.index].point - x).norm();
    const std::optional<Eigen::Vector3d> foot = nearest_point_on_edge(S, goal.index, x, scene_.tol);
    return foot ? (*foot - x).norm() : std::numeric_limits<double>::infinity();
  }
  const Eigen::Vector3d n = changing_side_normal(scene_, X_, t.c, on_a);
  const double cosine = std::clamp(n.dot(cone_middle(S, goal, x)), -1.0, 1.0);
  return reference_.size * std::acos(cosine);
}

void Motion::measure_midpoint(const Pose& X, const Pose& Y) {
  Pose mid;
  mid.position = 0.5 * (X.position + Y.position);
  mid.quaternion = X.quaternion.slerp(0.5, Y.quaternion);
  for (const Track& t : tracks_) {
    if (!maintained(t)) continue;
    ++counters_.pair_solves;
    auto c = track_pair(scene_, mid, t.c.a, t.c.b, t.c.type, t.c.p_A, t.c.p_B);
    if (c)
      counters_.max_keep_drift = std::max(counters_.max_keep_drift, c->residual.cwiseAbs().maxCoeff());
  }
  ++counters_.detections;
  const ContactReport rep = detect_contacts(scene_, mid);
  for (const Penetration& p : rep.penetrations)
    counters_.max_step_penetration = std::max(counters_.max_step_penetration, p.depth);
}

bool Motion::resolve(const Pose& Y, std::vector<Track>& tracks, int* lost) const {
  for (size_t i = 0; i < tracks.size(); ++i) {
    Track& t = tracks[i];
    if (!maintained(t)) continue;
    ++counters_.pair_solves;
    auto s = track_pair(scene_, Y, t.c.a, t.c.b, t.c.type, t.c.p_A, t.c.p_B);
    // An e-e-cross contact whose crossing sign flipped has passed through e-e-touch (another
    // CF) within the step: the sign is the region's invariant (region_signature). Lost, so
    // the step is shortened or the motion ends. The lens tip in the dish (stress scene): a
    // travel between two rim crossings {(eA-e1, 1)} of opposite signs arrived, joining them.
    if (!s || (t.c.type == PtcType::EECross && s->type == PtcType::EECross &&
               crossing_sign(*s) != crossing_sign(t.c))) {
      if (lost) *lost = static_cast<int>(i);
      return false;
    }
    t.c = *s;
  }
  return true;
}

std::optional<Pose> Motion::correct(Pose Y, std::vector<Track>& tracks, int* lost) const {
  if (lost) *lost = -1;
  for (int it = 0; it < kCorrectionIterations; ++it) {
    if (!resolve(Y, tracks, lost)) return std::nullopt;
    int rows = 0;
    for (const Track& t : tracks)
      if (maintained(t)) rows += static_cast<int>(t.c.residual.size());
    if (rows == 0) return Y;
    Eigen::VectorXd r(rows);
    Eigen::MatrixXd J(rows, 6);
    const TwistFrame F = frame_at(Y);
    int k = 0;
    for (const Track& t : tracks) {
      if (!maintained(t)) continue;
      const int m = static_cast<int>(t.c.residual.size());
      r.segment(k, m) = t.c.residual;
      J.middleRows(k, m) = F.from_origin_jacobian(t.c.jacobian);
      k += m;
    }
    if (r.cwiseAbs().maxCoeff() <= scene_.tol.keep_residual) return Y;
    Y = F.apply(Y, minimum_norm_step(J, r));
  }
  return std::nullopt;
}

Observation Motion::classify(const Pose& Y, const std::vector<Track>& tracks,
                             const NearbyTriangles* nearby) const {
  Observation obs;
  ++counters_.detections;
  DetectOptions options;
  options.nearby = nearby;
  // A penetration ends the observation with its first penetration alone; a motion watched
  // frame by frame (an observer) gets every contact at its collision frame too.
  options.stop_at_penetration = !observer_;
  const ContactReport rep = detect_contacts(*context_, Y, options);
  obs.contacts = rep.contacts;
  if (rep.penetrating()) {
    const Penetration& p = rep.penetrations.front();
    obs.kind = Observation::Collision;
    obs.detected.a = p.a;
    obs.detected.b = p.b;
    obs.detected.point_B = p.point_B;
    obs.what = "collision: " + element_pair_name(scene_, p.a, p.b) + " penetrate at " +
               fmt_point(p.point_B);
    return obs;
  }
  const double radius = kMatchSteps * h_;
  std::vector<bool> matched(tracks.size(), false);
  // First every detected contact that continues a tracked one (the same pair, the nearest
  // tracked point), then the others: a new contact met within `radius` of a kept contact of
  // another pair is new, not that contact changed, whichever order the detector lists them in
  // (until session 20 it was read by that order).
  std::vector<bool> continues(rep.contacts.size(), false), reached(tracks.size(), false);
  std::vector<int> continued_by(tracks.size(), -1);  // the detection continuing each track
  for (size_t k = 0; k < rep.contacts.size(); ++k) {
    const PointContact& d = rep.contacts[k];
    int best = -1;
    double best_dist = radius;
    for (size_t i = 0; i < tracks.size(); ++i) {
      const Track& t = tracks[i];
      if (matched[i] || !(t.c.a == d.a && t.c.b == d.b)) continue;
      const double dist = (t.c.point_B - d.point_B).norm();
      if (dist < best_dist) best = static_cast<int>(i), best_dist = dist;
    }
    if (best >= 0) {
      matched[best] = continues[k] = true;
      continued_by[best] = static_cast<int>(k);
    }
  }
  for (size_t k = 0; k < rep.contacts.size(); ++k) {
    if (continues[k]) continue;
    const PointContact& d = rep.contacts[k];
    int best = -1;
    double best_dist = radius;
    // A changing contact that has reached its new elements: the event. Its old pair is gone,
    // or seen at the same point (the boundary between the elements); seen elsewhere, it is
    // still there and the new pair's contact is a new one (a state above: Example 1's
    // {(fA-e1, 2), (fA-f1, 1)}, the wall contact 0.24 from a rim contact).
    for (size_t i = 0; i < tracks.size(); ++i) {
      const Track& t = tracks[i];
      if (reached[i] || t.plan.action != ContactAction::Change || t.phase != Phase::Drive) continue;
      if (continued_by[i] >= 0 &&
          (rep.contacts[continued_by[i]].point_B - d.point_B).norm() > scene_.tol.distinct_points)
        continue;
      if (!(t.plan.new_a == d.a && t.plan.new_b == d.b)) continue;
      const double dist = (t.c.point_B - d.point_B).norm();
      if (dist < best_dist) best = static_cast<int>(i), best_dist = dist;
    }
    if (best >= 0) {
      matched[best] = reached[best] = true;
      obs.kind = Observation::Event;
      obs.track = best;
      obs.detected = d;
      continue;
    }
    // A kept contact that turned into another pair, or a new contact: both end the motion.
    for (size_t i = 0; i < tracks.size(); ++i)
      if (!matched[i] && maintained(tracks[i]) &&
          (tracks[i].c.point_B - d.point_B).norm() < radius) {
        obs.kind = Observation::KeptChanged;
        obs.track = static_cast<int>(i);
        obs.detected = d;
        obs.what = "contact " + element_pair_name(scene_, tracks[i].c.a, tracks[i].c.b) + " became " +
                   element_pair_name(scene_, d.a, d.b) + " (" + ptc_type_name(d.type) + ") at " +
                   fmt_point(d.point_B);
        return obs;
      }
    obs.kind = Observation::Collision;
    obs.new_contact = true;
    obs.detected = d;
    obs.what = "collision: new contact " + element_pair_name(scene_, d.a, d.b) + " (" +
               ptc_type_name(d.type) + ") at " + fmt_point(d.point_B);
    return obs;
  }
  if (obs.kind == Observation::Event) return obs;
  // A maintained contact the detector no longer sees has left its elements' region.
  for (size_t i = 0; i < tracks.size(); ++i)
    if (!matched[i] && maintained(tracks[i])) {
      obs.kind = Observation::Missing;
      obs.track = static_cast<int>(i);
      obs.what = "contact " + element_pair_name(scene_, tracks[i].c.a, tracks[i].c.b) +
                 " leaves its elements at " + fmt_point(tracks[i].c.point_B);
      return obs;
    }
  return obs;
}

void Motion::add_edge_rotation(const Track& t, const TwistFrame& F,
                               const Eigen::Matrix<double, 3, 6>& dn, const Eigen::Vector3d& dir,
                               DriveSystem& sys) const {
  // The paper's pure rotation about the tangent line of the edge at the contact point
  // (Section III-C): the one motion that turns the contact normal across the edge's normal
  // cone while the edge stays in contact. Turned the way that moves the normal toward `dir`.
  const Eigen::Vector3d axis = t.plan.changes_a ? t.c.tangent_a_B : t.c.tangent_b_B;
  if (axis.norm() == 0 || dir.norm() == 0) return;
  Twist rot;
  rot.head<3>() = axis.cross(F.origin_B - t.c.point_B);
  rot.tail<3>() = axis * F.length;
  if ((dn * rot).dot(dir) < 0) rot = -rot;
  sys.add_drive(Eigen::MatrixXd::Identity(6, 6), rot / TwistFrame::displacement(rot), 1.0);
}

bool Motion::add_drive(const Track& t, const TwistFrame& F, DriveSystem& sys) {
  if (t.plan.action == ContactAction::Remove) {
    if (t.phase == Phase::Done) return true;
    const Eigen::MatrixXd row = F.from_origin_jacobian(t.c.jacobian).topRows(1);
    sys.add_drive(row, Eigen::VectorXd::Ones(1), 1.0);
    if (variant_.remove_by_rotation) {
      Eigen::MatrixXd trans = Eigen::MatrixXd::Zero(3, 6);
      trans.leftCols<3>().setIdentity();
      // Weak: prefers turning about the kept contacts over translating A's centre.
      constexpr double kRotationPreference = 0.3;
      sys.add_drive(trans, Eigen::VectorXd::Zero(3), kRotationPreference);
    }
    return true;
  }
  sys.add_hard(F.from_origin_jacobian(t.c.jacobian));
  if (t.plan.action != ContactAction::Change || t.phase == Phase::Done) return true;

  const auto rates = contact_rates(scene_, X_, F, t.c, counters_.pair_solves);
  if (!rates) return false;
  const bool on_a = t.plan.changes_a;
  const Solid& S = on_a ? scene_.A : scene_.B;
  const ElementId current = on_a ? t.c.a : t.c.b;
  const ElementId goal = on_a ? t.plan.new_a : t.plan.new_b;
  const Eigen::Vector3d x = on_a ? t.c.p_A : t.c.p_B;
  const Eigen::Vector3d n = changing_side_normal(scene_, X_, t.c, on_a);
  const Eigen::Matrix<double, 3, 6>& dx = on_a ? rates->point_A : rates->point_B;
  const Eigen::Matrix<double, 3, 6>& dx_other = on_a ? rates->point_B : rates->point_A;
  Eigen::Matrix<double, 3, 6> dn = (on_a ? rates->normal_A : rates->normal_B) * reference_.size;
  if (!on_a && t.c.type == PtcType::EETouch) {
    // A's rim bisector turns with A (the touch's normal_B, B's own bisector, does not)
    const double eps = scene_.tol.rate_step;
    for (int i = 0; i < 6; ++i) {
      Twist e = Twist::Zero();
      e[i] = eps;
      dn.col(i) =
          (changing_side_normal(scene_, F.apply(X_, e), t.c, false) - n) / eps * reference_.size;
    }
  }
  // Toward a lower-dimensional element (face to edge, edge to vertex) or away from one: in
  // the drive phase from the current element to the goal; when settling, from the element the
  // contact left to the one it is on now.
  const ElementId from = t.phase == Phase::Drive ? current : t.left;
  const ElementId to = t.phase == Phase::Drive ? goal : current;
  const bool approaching = element_dimension(to) < element_dimension(from);

  if (t.phase == Phase::Drive) {
    if (approaching) {
      // Slide the contact point toward the new, lower-dimensional element.
      auto u = direction_toward(S, goal, x, n, scene_.tol);
      if (!u) return false;
      if (variant_.turn != 0) *u = Eigen::AngleAxisd(variant_.turn, n) * *u;
      if (current.kind == ElementKind::Edge) {
        // A point on an edge moves along the edge only: toward the vertex along its tangent.
        // (The straight direction on the tangent plane has a part across the edge that no
        // motion gives, and the least-squares drive then spent the whole step on it.)
        const Eigen::Vector3d tangent = edge_tangent(t, on_a);
        if (!(tangent.norm() > 0)) return false;
        *u = tangent.dot(*u) >= 0 ? tangent : Eigen::Vector3d(-tangent);
      }
      sys.add_drive(dx, *u, 1.0);
      if (variant_.fix_unchanged_side) sys.add_drive(dx_other, Eigen::Vector3d::Zero(), 1.0);
    } else {
      // Leaving an edge or vertex for a face (or a vertex for an edge): turn the contact
      // normal toward the new element's normal (a rotation, Section III-C), and for a vertex
      // also slide into the new element.
      used_rotation_drive_ = true;
      Eigen::Vector3d goal_n = cone_middle(S, goal, x);
      Eigen::Vector3d dir = goal_n - n;
      if (current.kind == ElementKind::Edge) add_edge_rotation(t, F, dn, dir, sys);
      if (dir.norm() > 0 && (current.kind != ElementKind::Edge || variant_.normal_drive))
        sys.add_drive(dn, dir.normalized(), 1.0);
      if (current.kind == ElementKind::Vertex) {
        auto u = direction_toward(S, goal, x, n, scene_.tol);
        if (u) sys.add_drive(dx, *u, 1.0);
      }
    }
    return true;
  }
  // Settling: into the interior of the new element's region.
  if (approaching) {
    used_rotation_drive_ = true;
    const Eigen::Vector3d dir = cone_middle(S, current, x) - n;
    if (current.kind == ElementKind::Edge) add_edge_rotation(t, F, dn, dir, sys);
    if (dir.norm() > 0 && (current.kind != ElementKind::Edge || variant_.normal_drive))
      sys.add_drive(dn, dir.normalized(), 1.0);
    if (variant_.fix_unchanged_side) sys.add_drive(dx_other, Eigen::Vector3d::Zero(), 0.3);
  } else if (current.kind == ElementKind::Face) {
    // `current` is the new face now: slide away from the edge or vertex it was reached from.
    sys.add_drive(dx, into_face(S, current.index, t.left, x), 1.0);
  } else if (current.kind == ElementKind::Edge && t.left.kind == ElementKind::Vertex) {
    // `current` is the new edge: slide along it away from the vertex it was reached from.
    Eigen::Vector3d tangent = edge_tangent(t, on_a);
    if (!(tangent.norm() > 0)) return false;
    const Eigen::Vector3d away = x - S.vertices[t.left.index].point;
    sys.add_drive(dx, tangent.dot(away) >= 0 ? tangent : Eigen::Vector3d(-tangent), 1.0);
  } else {
    auto u = direction_toward(S, current, x, n, scene_.tol);
    if (u) sys.add_drive(dx, *u, 1.0);
  }
  return true;
}

bool Motion::settle_within_step(const Observation& obs, const TwistFrame& F, const Twist& s,
                                double lo) {
  // A region thinner than a step: the edge of weak_edge.yaml (faces 0.57 degrees apart) is
  // crossed by one settling rotation, which reported "contact eA-fB became fC-fB". Settling
  // only seeks a witness away from the region's boundaries; when the region along the step is
  // [X_, lo], its middle is the one farthest from both. Whatever ends the region within the
  // step (the settling contact turning, another contact changing, two contacts of one pair
  // merging into a penetration), except the event a driving contact is headed for. A contact
  // being removed is released there too when it has separated: lifting off may slide two
  // contacts of one pair together within the step (Example 2's {(fA1-e1, 2), (fA1-f1, 1)}).
  if (obs.kind == Observation::Same || obs.kind == Observation::Event || lo <= 0) return false;
  const auto settling_on_new_pair = [](const Track& t) {
    return t.plan.action == ContactAction::Change && t.phase == Phase::Settle &&
           t.c.a == t.plan.new_a && t.c.b == t.plan.new_b;
  };
  const bool turned = obs.kind == Observation::KeptChanged && obs.track >= 0 &&
                      settling_on_new_pair(tracks_[obs.track]);
  // The general rule's conditions. Not before an e-e-cross contact is lost (on the two lenses
  // of collinear_edges.yaml, at the rims' touch): the crossing region's sliver there is as thin
  // as the step's part before the loss, and a witness in it is ill-conditioned near a touch
  // (the crossing's gap is good to the solve's residual over the rims' sine: 8e-10 L at 5.6e-6
  // from the touch, measured); the motion fails there and another variant arrives farther in.
  // Not before the event a driving contact is headed for. Only while a contact settles or is
  // being removed.
  bool settling = false, removing = false;
  for (const Track& t : tracks_) {
    settling = settling || settling_on_new_pair(t);
    removing = removing || (t.plan.action == ContactAction::Remove && t.phase != Phase::Done);
  }
  const bool general =
      !(obs.kind == Observation::Missing && obs.track >= 0 &&
        tracks_[obs.track].c.type == PtcType::EECross) &&
      !(obs.track >= 0 && tracks_[obs.track].plan.action == ContactAction::Change &&
        tracks_[obs.track].phase == Phase::Drive) &&
      (settling || removing);
  // The narrow rule stops only where the settling contact turns; there the general rule would
  // also release and end every settling contact, so either may move differently from here.
  if (!variant_.general_settling) {
    general_stop_ = general_stop_ || general || turned;
    if (!turned) return false;
  } else if (!general) {
    return false;
  }
  std::vector<Track> tm = tracks_;
  const std::optional<Pose> Ym = correct(F.apply(X_, s * (0.5 * lo)), tm);
  if (!Ym) return false;
  const Observation om = classify(*Ym, tm);
  if (om.kind != Observation::Same) return false;
  if (!variant_.general_settling) {
    X_ = *Ym;
    tracks_ = tm;
    tracks_[obs.track].phase = Phase::Done;
    emit("settle", om.contacts);
    return true;
  }
  std::vector<bool> released(tm.size(), false);
  bool any_released = false;
  for (size_t i = 0; i < tm.size(); ++i) {
    const Track& t = tm[i];
    if (t.plan.action != ContactAction::Remove || t.phase == Phase::Done) continue;
    bool touching = false;
    for (const PointContact& d : om.contacts)
      if (d.a == t.c.a && d.b == t.c.b && (d.point_B - t.c.point_B).norm() < kMatchSteps * h_)
        touching = true;
    released[i] = !touching;
    any_released = any_released || released[i];
  }
  if (!settling && !any_released) return false;
  if (!turned) general_stop_ = true;
  X_ = *Ym;
  tracks_ = tm;
  for (size_t i = 0; i < tracks_.size(); ++i)
    if (settling_on_new_pair(tracks_[i]) || released[i]) tracks_[i].phase = Phase::Done;
  emit("settle", om.contacts);
  return true;
}

void Motion::leave_touches() {
  // Two rims touching with collinear tangents: the touch point is also a stationary point, on
  // the face's boundary, of each pair of one rim and a face of the other rim (the normal
  // plane of the common tangent holds every such face normal), so each neighbouring f-e or
  // e-f contact starts right there. Keeping the touch instead cannot reach them: its normal is
  // not fixed by the geometry, and turning A about the tangent keeps the rims touching
  // (collinear_edges.yaml: "contact eA-eB makes no progress toward fA1-eB"). The contact
  // continues as the new pair as soon as that pair is a contact (the face's normal in the
  // other rim's cone), and settling slides it into the face.
  for (Track& t : tracks_) {
    if (t.plan.action != ContactAction::Change || t.phase != Phase::Drive ||
        t.c.type != PtcType::EETouch)
      continue;
    const ElementId current = t.plan.changes_a ? t.c.a : t.c.b;
    const ElementId goal = t.plan.changes_a ? t.plan.new_a : t.plan.new_b;
    if (element_dimension(goal) <= element_dimension(current)) continue;
    ++counters_.pair_solves;
    auto next = track_pair(scene_, X_, t.plan.new_a, t.plan.new_b, t.plan.new_type, t.c.p_A,
                           t.c.p_B);
    if (!next || std::abs(next->gap) > scene_.tol.contact_gap ||
        (next->point_B - t.c.point_B).norm() > scene_.tol.distinct_points)
      continue;
    // the new face's normal must lie in the other rim's normal cone; until it does, the drive
    // turns that cone toward it about the tangent (changing_side_normal)
    const bool other_is_b = t.plan.changes_a;
    const Solid& other = other_is_b ? scene_.B : scene_.A;
    const ElementId other_el = other_is_b ? next->b : next->a;
    // (outward normals: normal_B out of B, normal_in_A out of A)
    const Eigen::Vector3d dir =
        other_is_b ? Eigen::Vector3d(next->normal_B) : normal_in_A(X_, *next);
    const ConeFit fit = fit_normal_cone(other, element_surfaces(other, other_el),
                                        other_is_b ? next->p_B : next->p_A, dir);
    if (fit.distance > scene_.tol.normal_cone) continue;
    t.left = current;
    t.c = *next;
    t.phase = Phase::Settle;
    t.settle_left = kSettleSteps;
  }
}

void Motion::emit(const char* phase, const std::vector<PointContact>& contacts,
                  const Observation* collision) const {
  if (!observer_) return;
  MotionFrame f;
  f.step = step_;
  f.pose = X_;
  f.contacts = contacts;
  f.phase = phase;
  if (collision) {
    f.collided_a.push_back(collision->detected.a);
    f.collided_b.push_back(collision->detected.b);
  }
  observer_(f);
}

MotionOutcome Motion::run() {
  emit("drive", {});
  while (step_ < max_steps_) {
    leave_touches();
    bool all_done = true;
    for (const Track& t : tracks_)
      if (t.plan.action != ContactAction::Keep && t.phase != Phase::Done) all_done = false;
    if (all_done) break;

    const TwistFrame F = frame_at(X_);
    DriveSystem sys;
    for (const Track& t : tracks_)
      if (!add_drive(t, F, sys))
        return fail("contact " + element_pair_name(scene_, t.c.a, t.c.b) +
                    " has no rates at step " + std::to_string(step_));
    auto s = sys.solve();
    if (!s)
      return fail("no motion keeps the kept contacts and drives the others (step " +
                  std::to_string(step_) + ")");
    *s *= h_ / TwistFrame::displacement(*s);

    // A step whose kept contacts cannot be corrected is shortened.
    double frac = 1.0;
    std::optional<Pose> Y;
    std::vector<Track> moved;
    for (int k = 0; k <= kMaxHalvings; ++k, frac *= 0.5) {
      moved = tracks_;
      Y = correct(F.apply(X_, *s * frac), moved);
      if (Y) break;
    }
    if (!Y)
      return fail("kept contacts cannot be maintained beyond step " + std::to_string(step_));
    Observation obs = classify(*Y, moved);

    if (obs.kind != Observation::Same) {
      // Locate the event between the last good pose and this one.
      double lo = 0, hi = frac;
      Pose Y_hi = *Y, Y_lo = X_;
      std::vector<Track> tracks_hi = moved, tracks_lo = tracks_;
      BracketTriangles bracket(*context_, kBracketMargin);
      for (int k = 0; k < kBisections; ++k) {
        const NearbyTriangles* nearby = bracket.update(Y_lo, Y_hi);
        const double mid = 0.5 * (lo + hi);
        std::vector<Track> tm = tracks_;
        auto Ym = correct(F.apply(X_, *s * mid), tm);
        if (!Ym) {
          hi = mid;
          continue;
        }
        Observation om = classify(*Ym, tm, nearby);
        if (om.kind == Observation::Same) {
          lo = mid;
          Y_lo = *Ym;
          tracks_lo = tm;
        } else {
          hi = mid;
          Y_hi = *Ym;
          tracks_hi = tm;
          obs = om;
        }
      }
      ++step_;
      ++counters_.steps;
      if (settle_within_step(obs, F, *s, lo)) {
        // Settled before a new contact: the motion no longer fails there, but what it met is
        // still a state above (as when a failed motion meets one), found at the contact.
        if (obs.kind == Observation::Collision && obs.new_contact && !met_) {
          const Pose settled = X_;
          X_ = Y_hi;
          met_ = discover(obs.contacts);
          X_ = settled;
        }
        continue;
      }
      if (obs.kind == Observation::Missing &&
          tracks_[obs.track].plan.action == ContactAction::Change &&
          tracks_[obs.track].phase == Phase::Drive) {
        // The changing contact is at its element's boundary (to 2^-30 of a step): follow it on
        // the new elements from here; settling carries it into their region.
        Track& t = tracks_lo[obs.track];
        ++counters_.pair_solves;
        auto next = track_pair(scene_, Y_lo, t.plan.new_a, t.plan.new_b, t.plan.new_type,
                               t.c.p_A, t.c.p_B);
        // The new pair must touch where the old one left its elements: a solve that found
        // its nearest points farther apart than a contact is matched over (kMatchSteps) has
        // followed another branch, and the next correction would leap to close that gap
        // (measured: a 0.16 L gap closed by one 0.19 L step at a 0.04 L motion step, the
        // sweep's 8e-2 L drift).
        if (!next || std::abs(next->gap) > kMatchSteps * h_)
          return fail(obs.what + " but does not continue as " +
                      element_pair_name(scene_, t.plan.new_a, t.plan.new_b) + " (step " +
                      std::to_string(step_) + ")");
        t.left = t.plan.changes_a ? t.c.a : t.c.b;
        t.c = *next;
        t.phase = Phase::Settle;
        t.settle_left = kSettleSteps;
        X_ = Y_lo;
        tracks_ = tracks_lo;
        emit("event", obs.contacts);
        continue;
      }
      if (obs.kind != Observation::Event) {
        X_ = Y_hi;
        emit("collision", obs.contacts, &obs);
        MotionOutcome o = fail(obs.what + " at step " + std::to_string(step_));
        if (obs.new_contact)
          if (std::optional<Discovery> d = discover(obs.contacts)) o.discovered = std::move(d);
        return o;
      }
      // The changing contact now lies on its new elements: follow that pair from here on.
      X_ = Y_hi;
      tracks_ = tracks_hi;
      Track& t = tracks_[obs.track];
      t.left = t.plan.changes_a ? t.c.a : t.c.b;
      t.c = obs.detected;
      t.phase = Phase::Settle;
      t.settle_left = kSettleSteps;
      emit("event", obs.contacts);
      continue;
    }

    if (counters_.measure) measure_midpoint(X_, *Y);
    X_ = *Y;
    tracks_ = moved;
    ++step_;
    ++counters_.steps;
    for (Track& t : tracks_) {
      if (t.plan.action == ContactAction::Change && t.phase == Phase::Drive) {
        const double d = distance_to_goal(t);
        if (d < t.best_to_goal - kMinProgress * h_) {
          t.best_to_goal = d;
          t.stalled = 0;
        } else if (++t.stalled > kMaxStalledSteps) {
          return fail("contact " + element_pair_name(scene_, t.c.a, t.c.b) +
                      " makes no progress toward " +
                      element_pair_name(scene_, t.plan.new_a, t.plan.new_b) + " (step " +
                      std::to_string(step_) + ")");
        }
      }
      if (t.plan.action == ContactAction::Change && t.phase == Phase::Settle &&
          --t.settle_left <= 0)
        t.phase = Phase::Done;
      if (t.plan.action == ContactAction::Remove && t.phase != Phase::Done) {
        ++counters_.pair_solves;
        auto sep = track_pair(scene_, X_, t.c.a, t.c.b, t.c.type, t.c.p_A, t.c.p_B);
        // Separated by half a step: clearly apart, yet the witness stays near the boundary
        // it was reached through.
        if (!sep || sep->gap >= 0.5 * h_)
          t.phase = Phase::Done;
        else
          t.c = *sep;
      }
    }
    emit("drive", obs.contacts);
  }
  if (step_ >= max_steps_)
    return fail("did not reach the target within " + std::to_string(max_steps_) + " steps");

  // The end pose must carry exactly the target CF; project it there exactly.
  ++counters_.detections;
  const ContactReport rep = detect_contacts(scene_, X_);
  const ContactFormation reached = ContactFormation::of(rep.contacts);
  if (rep.penetrating() || !(reached == target_))
    return fail("ended in " + reached.str(scene_) + " instead of " + target_.str(scene_));
  const ProjectionResult proj = project_onto_cf(scene_, X_, target_);
  if (!proj.ok) return fail("projection onto the target failed: " + proj.reason);
  ++counters_.detections;
  const ContactReport fin = detect_contacts(scene_, proj.pose);
  if (fin.penetrating() || !(ContactFormation::of(fin.contacts) == target_))
    return fail("the projected witness is classified as " +
                ContactFormation::of(fin.contacts).str(scene_));
  X_ = proj.pose;
  emit("done", fin.contacts);
  MotionOutcome o;
  o.feasible = true;
  o.end = proj.pose;
  o.contacts = fin.contacts;
  o.motion = name();
  o.steps = step_;
  o.general_stop = general_stop_;
  o.discovered = met_;
  return o;
}

bool Motion::travel_to(const Pose& to, bool by_contacts) {
  // Remaining motion as a scaled twist about the reference body's centre.
  auto remaining = [&](const Pose& X) {
    Twist s;
    // the displacement of A's point at the reference centre
    s.head<3>() =
        reference_.is_a
            ? Eigen::Vector3d(to.apply(reference_.centre) - X.apply(reference_.centre))
            : Eigen::Vector3d(to.apply(X.apply_inverse(reference_.centre)) - reference_.centre);
    const Eigen::AngleAxisd aa(to.quaternion * X.quaternion.conjugate());
    s.tail<3>() = aa.axis() * aa.angle() * reference_.size;
    return s;
  };
  // The target's contacts, matched to the tracked ones by pair (nearest point).
  std::vector<PointContact> goal;
  if (by_contacts) {
    ++counters_.detections;
    const ContactReport rep = detect_contacts(scene_, to);
    if (rep.contacts.size() != tracks_.size()) return false;
    std::vector<bool> used(rep.contacts.size(), false);
    for (const Track& t : tracks_) {
      int best = -1;
      double best_d = std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < rep.contacts.size(); ++j) {
        const PointContact& g = rep.contacts[j];
        if (used[j] || !(g.a == t.c.a && g.b == t.c.b)) continue;
        const double d = (g.p_B - t.c.p_B).norm() + (g.p_A - t.c.p_A).norm();
        if (d < best_d) best = static_cast<int>(j), best_d = d;
      }
      if (best < 0) return false;
      used[best] = true;
      goal.push_back(rep.contacts[best]);
    }
  }
  auto distance = [&](const Pose& X) {
    double d = TwistFrame::displacement(remaining(X));
    for (size_t i = 0; i < goal.size(); ++i)
      d = std::max({d, (goal[i].p_B - tracks_[i].c.p_B).norm(),
                    (goal[i].p_A - tracks_[i].c.p_A).norm()});
    return d;
  };
  double best = distance(X_);
  int stalled = 0;
  // No progress for this many steps means the drive is blocked (a region boundary or a
  // collision lies between): the witnesses are then not shown to be connected this way.
  constexpr int kMaxStalled = 8;
  // Weight of the straight pose drive when the contacts lead: enough to settle the spin about
  // the normal once the contact points have arrived.
  constexpr double kPoseWeightByContacts = 0.2;
  while (step_ < max_steps_) {
    const Twist rem = remaining(X_);
    const double dist = distance(X_);
    if (TwistFrame::displacement(rem) <= h_) {
      // Last hop onto the target itself; when that fails, in 2, 4, ... straight pieces. A
      // whole step taken at once can carry a pair solve onto another branch of a thin solid
      // (the needle's two witnesses across the rim, far and rotated: 0.04 rad apart about
      // its centre, one hop of 5 needle radii, met the rim penetrating the needle's side).
      for (int pieces = 1; pieces <= kMaxLastHopPieces; pieces *= 2) {
        std::vector<Track> moved = tracks_;
        bool arrived = true;
        for (int k = 1; k <= pieces && arrived; ++k) {
          const auto Y =
              correct(k == pieces ? to : between(X_, to, static_cast<double>(k) / pieces), moved);
          arrived = Y && classify(*Y, moved).kind == Observation::Same;
        }
        if (arrived) return true;
      }
      return false;
    }
    if (dist < best - 1e-3 * h_) {
      best = dist;
      stalled = 0;
    } else if (++stalled > kMaxStalled) {
      return false;
    }
    const TwistFrame F = frame_at(X_);
    std::vector<ContactRates> rates;
    for (const Track& t : tracks_) {
      auto r = contact_rates(scene_, X_, F, t.c, counters_.pair_solves);
      if (!r) return false;
      rates.push_back(*r);
    }
    // Contacts that the last attempt carried out of their elements get a drive back into them:
    // the motion then slides along the region's boundary instead of crossing it.
    std::vector<bool> keep_inside(tracks_.size(), false);
    bool stepped = false;
    for (int attempt = 0; attempt <= static_cast<int>(tracks_.size()) && !stepped; ++attempt) {
      DriveSystem sys;
      for (const Track& t : tracks_) sys.add_hard(F.from_origin_jacobian(t.c.jacobian));
      const double rem_norm = TwistFrame::displacement(rem);
      sys.add_drive(Eigen::MatrixXd::Identity(6, 6), rem / rem_norm,
                    by_contacts ? kPoseWeightByContacts : 1.0);
      for (size_t i = 0; i < goal.size(); ++i) {
        const PointContact& c = tracks_[i].c;
        const Eigen::Vector3d dB =
            step_toward_on_element(scene_.B, c.b, c.p_B, goal[i].p_B, c.normal_B);
        const Eigen::Vector3d dA =
            step_toward_on_element(scene_.A, c.a, c.p_A, goal[i].p_A, normal_in_A(X_, c));
        const double scale = std::max({dB.norm(), dA.norm(), h_});
        sys.add_drive(rates[i].point_B, dB / scale, 1.0);
        sys.add_drive(rates[i].point_A, dA / scale, 1.0);
      }
      for (size_t i = 0; i < tracks_.size(); ++i) {
        if (!keep_inside[i]) continue;
        const PointContact& c = tracks_[i].c;
        if (c.b.kind == ElementKind::Face)
          sys.add_drive(rates[i].point_B,
                        into_face(scene_.B, c.b.index, nearest_boundary(scene_.B, c.b, c.p_B), c.p_B),
                        1.0);
        if (c.a.kind == ElementKind::Face)
          sys.add_drive(rates[i].point_A,
                        into_face(scene_.A, c.a.index, nearest_boundary(scene_.A, c.a, c.p_A), c.p_A),
                        1.0);
      }
      auto s = sys.solve();
      if (!s) return false;
      *s *= std::min(h_, dist) / TwistFrame::displacement(*s);
      std::vector<Track> moved = tracks_;
      auto Y = correct(F.apply(X_, *s), moved);
      if (!Y) return false;
      const Observation ob = classify(*Y, moved);
      if (ob.kind == Observation::Missing && !keep_inside[ob.track]) {
        keep_inside[ob.track] = true;
        continue;
      }
      if (ob.kind != Observation::Same) return false;
      X_ = *Y;
      tracks_ = moved;
      stepped = true;
    }
    if (!stepped) return false;
    ++step_;
    ++counters_.steps;
  }
  return false;
}

std::optional<Discovery> Motion::probe(const std::function<Twist(const TwistFrame&)>& drive,
                                      const std::function<double()>& progress) {
  double best = std::numeric_limits<double>::infinity();
  int stalled = 0;
  constexpr int kMaxStalled = 8;  // as for connectivity: a blocked push
  while (step_ < max_steps_) {
    const double dist = progress();
    if (dist <= 0) return std::nullopt;
    if (dist < best - 1e-3 * h_) {
      best = dist;
      stalled = 0;
    } else if (++stalled > kMaxStalled) {
      return std::nullopt;
    }
    const TwistFrame F = frame_at(X_);
    DriveSystem sys;
    for (const Track& t : tracks_) sys.add_hard(F.from_origin_jacobian(t.c.jacobian));
    const Twist want = drive(F);
    sys.add_drive(Eigen::MatrixXd::Identity(6, 6), want / TwistFrame::displacement(want), 1.0);
    auto s = sys.solve();
    if (!s) return std::nullopt;
    *s *= h_ / TwistFrame::displacement(*s);
    std::vector<Track> moved = tracks_;
    auto Y = correct(F.apply(X_, *s), moved);
    if (!Y) return std::nullopt;
    Observation obs = classify(*Y, moved);
    if (obs.kind == Observation::Same) {
      X_ = *Y;
      tracks_ = moved;
      ++step_;
      ++counters_.steps;
      continue;
    }
    if (obs.kind != Observation::Collision) return std::nullopt;
    // Locate the first touch of the new contact between X_ and Y.
    double lo = 0, hi = 1;
    Pose Y_hi = *Y, Y_lo = X_;
    BracketTriangles bracket(*context_, kBracketMargin);
    for (int k = 0; k < kBisections; ++k) {
      const NearbyTriangles* nearby = bracket.update(Y_lo, Y_hi);
      const double mid = 0.5 * (lo + hi);
      std::vector<Track> tm = tracks_;
      auto Ym = correct(F.apply(X_, *s * mid), tm);
      if (!Ym) {
        hi = mid;
        continue;
      }
      Observation om = classify(*Ym, tm, nearby);
      if (om.kind == Observation::Same) {
        lo = mid;
        Y_lo = *Ym;
      } else {
        hi = mid;
        Y_hi = *Ym;
        obs = om;
      }
    }
    if (!obs.new_contact) return std::nullopt;
    X_ = Y_hi;
    return discover(obs.contacts);
  }
  return std::nullopt;
}

}  // namespace

std::optional<Discovery> probe_for_contact(const SceneGeometry& scene, const Pose& start,
                                           const std::vector<PointContact>& contacts,
                                           const Eigen::Vector3d& goal_B,
                                           MotionCounters& counters) {
  std::vector<Track> tracks = keep_all(contacts);
  const ContactFormation cf = ContactFormation::of(contacts);
  Motion m(scene, start, std::move(tracks), cf, MotionVariant{}, counters, nullptr);
  const Eigen::Vector3d centre_A = scene.A.bbox.center();
  // Translate A's centre toward the goal.
  return m.probe(
      [&](const TwistFrame&) {  // a translation: every point of A moves alike
        Twist t = Twist::Zero();
        t.head<3>() = goal_B - m.pose().apply(centre_A);
        return t;
      },
      [&] { return (goal_B - m.pose().apply(centre_A)).norm(); });
}

std::optional<Discovery> probe_by_rotation(const SceneGeometry& scene, const Pose& start,
                                           const std::vector<PointContact>& contacts, int pivot,
                                           const Eigen::Vector3d& axis_B,
                                           MotionCounters& counters) {
  std::vector<Track> tracks = keep_all(contacts);
  const ContactFormation cf = ContactFormation::of(contacts);
  Motion m(scene, start, std::move(tracks), cf, MotionVariant{}, counters, nullptr);
  const Eigen::Vector3d axis = axis_B.normalized();
  // Turn about the pivot contact's current point; progress is the turn still to go, as a
  // length at the reference size (at most half a turn).
  const Eigen::Quaterniond q0 = start.quaternion;
  return m.probe(
      [&](const TwistFrame& F) {
        Twist t;
        t.head<3>() = axis.cross(F.origin_B - m.contact(pivot).point_B);
        t.tail<3>() = axis * F.length;
        return t;
      },
      [&] {
        const double turned = Eigen::AngleAxisd(m.pose().quaternion * q0.conjugate()).angle();
        return m.size() * (M_PI - turned);
      });
}

std::optional<ConnectionMemo::Answer> ConnectionMemo::find(const std::string& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = answers_.find(key);
  if (it == answers_.end()) return std::nullopt;
  return it->second;
}

void ConnectionMemo::store(const std::string& key, const Answer& answer) {
  std::lock_guard<std::mutex> lock(mutex_);
  answers_.emplace(key, answer);
}

std::string ConnectionMemo::key(const Pose& from, const Pose& to, const ContactFormation& cf,
                                bool measure) {
  std::string key;
  auto add = [&](const void* data, size_t bytes) {
    key.append(static_cast<const char*>(data), bytes);
  };
  for (const Pose* X : {&from, &to}) {
    const std::array<std::uint64_t, 7> bits = pose_bits(*X);
    add(bits.data(), sizeof bits);
  }
  for (const PtcCount& e : cf.entries()) {
    const int fields[] = {static_cast<int>(e.a.kind), e.a.index,
                          static_cast<int>(e.b.kind), e.b.index,
                          static_cast<int>(e.type),   e.count};
    add(fields, sizeof fields);
  }
  key.push_back(measure ? 1 : 0);
  return key;
}

namespace {

bool compute_connected_within_cf(const SceneGeometry& scene, const Pose& from, const Pose& to,
                                 const ContactFormation& cf, MotionCounters& counters) {
  ++counters.detections;
  const ContactReport rep = detect_contacts(scene, from);
  if (!(ContactFormation::of(rep.contacts) == cf)) return false;
  const std::vector<Track> tracks = keep_all(rep.contacts);
  // First straight toward the target pose, then, if that is blocked, by sliding and rolling
  // the contact points toward the target's.
  for (bool by_contacts : {false, true}) {
    Motion m(scene, from, tracks, cf, MotionVariant{}, counters, nullptr);
    if (m.travel_to(to, by_contacts)) return true;
  }
  return false;
}

}  // namespace

bool connected_within_cf(const SceneGeometry& scene, const Pose& from, const Pose& to,
                         const ContactFormation& cf, MotionCounters& counters) {
  if (!counters.memo) return compute_connected_within_cf(scene, from, to, cf, counters);
  const std::string key = ConnectionMemo::key(from, to, cf, counters.measure);
  std::optional<ConnectionMemo::Answer> answer = counters.memo->find(key);
  if (!answer) {
    answer.emplace();
    answer->counters.measure = counters.measure;
    answer->connected = compute_connected_within_cf(scene, from, to, cf, answer->counters);
    counters.memo->store(key, *answer);
  }
  counters.merge(answer->counters);
  return answer->connected;
}

std::string MotionVariant::name() const {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s%s turn %+.0f deg", fix_unchanged_side ? "sliding" : "combined",
                remove_by_rotation ? "/rotation" : "", turn * 180 / M_PI);
  if (general_settling && !normal_drive)
    std::snprintf(buf + std::strlen(buf), sizeof buf - std::strlen(buf), ", general settling");
  if (normal_drive)
    std::snprintf(buf + std::strlen(buf), sizeof buf - std::strlen(buf), ", normal");
  return buf;
}

MotionOutcome run_transition_motion(const SceneGeometry& scene, const Pose& start,
                                    const std::vector<PointContact>& contacts,
                                    const std::vector<ContactPlan>& plan,
                                    const ContactFormation& target, const MotionVariant& variant,
                                    MotionCounters& counters, const MotionObserver& observer) {
  std::vector<Track> tracks;
  for (size_t i = 0; i < contacts.size(); ++i)
    tracks.push_back(Track{contacts[i], plan[i], Phase::Drive, 0, ElementId{},
                           std::numeric_limits<double>::infinity(), 0});
  Motion m(scene, start, std::move(tracks), target, variant, counters, observer);
  return m.run();
}

}  // namespace pcsg
