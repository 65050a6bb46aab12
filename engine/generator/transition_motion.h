#pragma once
// A neighbouring transition motion (paper Sections III-B, III-C): from a state's witness, move
// A in small steps that keep the kept contacts exact (Newton projection after every step),
// drive the changing contacts toward their new elements and the removed ones apart, locate
// every event (a contact reaching an element boundary, a contact separating, a collision) by
// bisection rather than at the step grid, and stop at a configuration of the target CF or at
// the first infeasibility, saying why.
#include <algorithm>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "engine/contact/contact_formation.h"
#include "engine/generator/hypothesis.h"
#include "engine/generator/twist_frame.h"

namespace pcsg {

// How a changing contact is driven (the paper's motion types, Section III-B/C).
struct MotionVariant {
  // slidingA / slidingB: the contact point on the unchanged side stays fixed while the other
  // slides; when false the motion is combined (both contact points may move).
  bool fix_unchanged_side = true;
  // The drive direction on the contact plane is turned by this angle (radians) about the
  // normal: where a face offers infinitely many paths, these are enumerated (Section III-C).
  double turn = 0;
  // Removal by rotation about the kept contacts (true) or by the least-norm motion (false).
  bool remove_by_rotation = false;
  // A contact leaving an edge for a face, or settling from a face onto an edge, also turns its
  // normal straight toward the goal's normal cone beside the rotation about the edge (false:
  // the rotation about the edge alone). Neither always arrives: the straight turn lifts the
  // lens off Example 2's dish rim where the rotation alone slides it along (both kept). Only
  // with general_settling (GeneratorOptions::complete_search).
  bool normal_drive = false;
  // Where settling stops within a step (settle_within_step): false, only where the settling
  // contact itself turns; true, wherever the new region ends within the step (another contact
  // changing, two contacts of one pair merging, a new contact met), and a contact being removed
  // is released there once it has separated. The general rule reaches Example 2's
  // {(fA1-e1, 2), (fA1-f1, 1)} in every frame; it also stops motions that the narrow rule
  // completes (GeneratorOptions::complete_search tries the narrow rule first).
  bool general_settling = false;
  std::string name() const;
};

class ConnectionMemo;

// Counters shared by every motion of one generator run.
struct MotionCounters {
  long detections = 0;
  long pair_solves = 0;
  long steps = 0;
  // Discretisation measurements (only when `measure` is set): see GraphStats.
  bool measure = false;
  double max_keep_drift = 0;
  double max_step_penetration = 0;
  // The run's remembered connected_within_cf answers (none: every answer is computed).
  ConnectionMemo* memo = nullptr;
  // Zero counts for a task of the same run (its measure flag and memo).
  MotionCounters fresh() const {
    MotionCounters c;
    c.measure = measure;
    c.memo = memo;
    return c;
  }
  void merge(const MotionCounters& o) {
    detections += o.detections;
    pair_solves += o.pair_solves;
    steps += o.steps;
    max_keep_drift = std::max(max_keep_drift, o.max_keep_drift);
    max_step_penetration = std::max(max_step_penetration, o.max_step_penetration);
  }
};

// One accepted step, for observers (animations, frame-by-frame debugging).
struct MotionFrame {
  int step = 0;
  Pose pose;
  std::vector<PointContact> contacts;             // all exact contacts at `pose`
  std::string phase;                              // "drive", "event", "settle", "collision", "done"
  std::vector<ElementId> collided_a, collided_b;  // at a collision frame
};
using MotionObserver = std::function<void(const MotionFrame&)>;

// A configuration of a higher-cardinality CF met on the way: a motion that ends because a new
// contact appears (touching, not penetrating) has reached a neighbouring state from below
// (its GN direction). Its witness is exact (projected onto the CF and re-detected).
struct Discovery {
  ContactFormation cf;
  Pose pose;
  std::vector<PointContact> contacts;
};

struct MotionOutcome {
  std::optional<Discovery> discovered;
  bool feasible = false;
  Pose end;                            // the witness of the target CF when feasible
  std::vector<PointContact> contacts;  // exact contacts at `end`
  std::string motion;                  // e.g. "slidingA", "slidingB+rotation", "combined"
  std::string reason;                  // why it failed
  int steps = 0;
  // With MotionVariant::general_settling: settling stopped where the narrow rule would not
  // have. Without it: the general rule's conditions held at some step, so it might have
  // stopped there (when false, the general rule's motion is this one, step for step).
  bool general_stop = false;
};

// Tries one motion variant for one plan of a hypothesis from `start` (whose exact contacts are
// `contacts`, in the order of `plan`).
MotionOutcome run_transition_motion(const SceneGeometry& scene, const Pose& start,
                                    const std::vector<PointContact>& contacts,
                                    const std::vector<ContactPlan>& plan,
                                    const ContactFormation& target, const MotionVariant& variant,
                                    MotionCounters& counters,
                                    const MotionObserver& observer = nullptr);

// An upward probe: from `start`, keeping every contact, A's centre is pushed toward
// `goal_B`; the first new contact met gives a state of higher cardinality (nullopt when the
// push is blocked, a kept contact changes, or A slides off).
std::optional<Discovery> probe_for_contact(const SceneGeometry& scene, const Pose& start,
                                           const std::vector<PointContact>& contacts,
                                           const Eigen::Vector3d& goal_B, MotionCounters& counters);
// A tipping probe: from `start`, keeping every contact, A turns about the axis `axis_B`
// through the point of contact `pivot` (an index into `contacts`), by at most a half turn; the
// first new contact met gives a state of higher cardinality.
std::optional<Discovery> probe_by_rotation(const SceneGeometry& scene, const Pose& start,
                                           const std::vector<PointContact>& contacts, int pivot,
                                           const Eigen::Vector3d& axis_B, MotionCounters& counters);

// A CF-compliant motion from `from` toward `to` keeping every contact of `cf`: true when it
// arrives, i.e. both witnesses lie in one CF-connected region (paper Section II-C).
bool connected_within_cf(const SceneGeometry& scene, const Pose& from, const Pose& to,
                         const ContactFormation& cf, MotionCounters& counters);

// The answers of connected_within_cf in one generator run, by their exact inputs (the poses'
// bits, the CF, the measure flag; the scene is the run's). The joins ask for the same motion
// again, mostly the walks in contact parameters (cf_parameter_path.h): those led by each
// contact between one pair of witnesses all end with the same direct travel when no waypoint
// of theirs is on the CF (Example 1: 176 of 595 motions repeated, session 31). An answer found
// here adds the counters its computation took, so the statistics are those of computing it
// again and, like the answers, do not depend on which thread asked first. Thread-safe.
class ConnectionMemo {
 public:
  struct Answer {
    bool connected = false;
    MotionCounters counters;  // what computing it took (memo unset)
  };
  std::optional<Answer> find(const std::string& key) const;
  void store(const std::string& key, const Answer& answer);
  // The key of connected_within_cf's inputs.
  static std::string key(const Pose& from, const Pose& to, const ContactFormation& cf,
                         bool measure);

 private:
  mutable std::mutex mutex_;
  std::map<std::string, Answer> answers_;
};

}  // namespace pcsg
