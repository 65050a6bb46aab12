#include "engine/generator/generator.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>

#include "engine/contact/contact_classification.h"
#include "engine/contact/convex_support.h"
#include "engine/contact/pair_seeds.h"
#include "engine/generator/cf_parameter_path.h"
#include "engine/generator/hypothesis.h"
#include "engine/generator/motion_drive.h"
#include "engine/generator/parallel_for.h"
#include "engine/generator/state_identity.h"

namespace pcsg {

namespace {
using RegionSignatures = std::vector<RegionSignature>;

// Whether A touches B along a curve somewhere at this pose (is_ring_contact): not a
// point-contact configuration, so never a witness (a seed, a motion's end, a projection).
bool touches_along_a_curve(const SceneGeometry& scene, const Pose& pose,
                           const std::vector<PointContact>& contacts) {
  return std::any_of(contacts.begin(), contacts.end(),
                     [&](const PointContact& c) { return is_ring_contact(scene, pose, c); });
}

// A feasible transition whose motion ends touching along a curve reaches no state.
void refuse_curve_contact_end(const SceneGeometry& scene, const Pose& end,
                              const std::vector<PointContact>& contacts, Candidate& c) {
  if (!c.feasible || !touches_along_a_curve(scene, end, contacts)) return;
  c.feasible = false;
  c.reason = c.motion + ": ends touching along a curve (a ring contact), not at points";
}
}  // namespace

std::vector<MotionVariant> motion_variants() {
  return {
      // The default search's, settling only where the settling contact turns:
      {true, 0.0, false},        // slidingA / slidingB, least-norm separation
      {true, 0.0, true},         // the same with separation by rotation
      {false, 0.0, false},       // combined sliding
      {false, M_PI / 4, false},  // combined, other paths on the face
      {false, -M_PI / 4, false},
      // GeneratorOptions::complete_search's too: the same settling wherever the new region ends
      // within a step (MotionVariant::general_settling); then an edge left or settled onto with
      // the normal turned straight toward the goal's cone (MotionVariant::normal_drive).
      {true, 0.0, false, false, true},
      {true, 0.0, true, false, true},
      {false, 0.0, false, false, true},
      {false, M_PI / 4, false, false, true},
      {false, -M_PI / 4, false, false, true},
      {true, 0.0, false, true, true},
      {false, 0.0, false, true, true},
  };
}

namespace {

// The plans of a hypothesis the default search tries, and the variants (motion_variants()
// lists them first).
constexpr size_t kFirstPlans = 2;
constexpr size_t kFirstVariants = 5;
// Whether the retries from a state's other witnesses try the complete search's further
// motions too (try_hypothesis's second pass), or the default ones only: those run from each
// state's own witness. Measured in session 44, that pass cost 146,000 of Example 2's 1.0 M
// complete-search queries and 14,000 of the torus's 218,000, and without it neither graph
// lost or gained a state or a link (Example 2 moved kept its complete signature too).
constexpr bool kRetriesTryEveryMotion = false;

// The variant that moves as v does with the other settling rule (v itself for the normal
// drive, which has the general rule only).
size_t settling_counterpart(const std::vector<MotionVariant>& variants, size_t v) {
  const MotionVariant& b = variants[v];
  if (b.normal_drive) return v;
  for (size_t j = 0; j < variants.size(); ++j) {
    const MotionVariant& a = variants[j];
    if (a.general_settling != b.general_settling && !a.normal_drive &&
        a.fix_unchanged_side == b.fix_unchanged_side && a.turn == b.turn &&
        a.remove_by_rotation == b.remove_by_rotation)
      return j;
  }
  return v;
}

// Whether `upper` is `lower` plus exactly one PtC: then `lower` is reached from `upper` by
// removing that contact, the reverse of the motion that met it (an LN transition down).
bool adds_one_contact(const ContactFormation& lower, const ContactFormation& upper) {
  if (upper.cardinality() != lower.cardinality() + 1) return false;
  for (const PtcCount& e : lower.entries()) {
    const auto& u = upper.entries();
    const bool covered = std::any_of(u.begin(), u.end(), [&](const PtcCount& x) {
      return x.a == e.a && x.b == e.b && x.type == e.type && x.count >= e.count;
    });
    if (!covered) return false;
  }
  return true;
}

// One hypothesised target: a CF and, when it has e-e-cross contacts, the crossing signs to
// arrive with (one candidate each).
struct Reached {
  Candidate candidate;
  MotionOutcome outcome;
};

struct TryResult {
  RegionSignatures wanted;       // the signatures tried (see try_hypothesis)
  std::vector<Reached> targets;  // one per signature of `wanted`, in its order
  MotionCounters counters;
  std::vector<Discovery> discovered;  // higher-cardinality states met by failed motions
};

// Whether a variant differs from an earlier one for this plan (turns only matter when a contact
// slides toward a lower-dimensional element; the separation style only with removals; the
// normal drive only when a contact changes from or onto an edge).
bool variant_matters(const MotionVariant& v, const std::vector<ContactPlan>& plan,
                     const std::vector<PointContact>& contacts) {
  bool approach = false, removes = false, edge = false;
  for (size_t i = 0; i < plan.size(); ++i) {
    const ContactPlan& p = plan[i];
    if (p.action == ContactAction::Remove) removes = true;
    if (p.action != ContactAction::Change) continue;
    approach = true;
    const ElementId from = p.changes_a ? contacts[i].a : contacts[i].b;
    const ElementId to = p.changes_a ? p.new_a : p.new_b;
    if (from.kind == ElementKind::Edge || to.kind == ElementKind::Edge) edge = true;
  }
  if (v.normal_drive && !edge) return false;
  if (v.turn != 0 && !approach) return false;
  if (v.remove_by_rotation && !removes) return false;
  if (!v.fix_unchanged_side && !approach) return false;
  return true;
}

// The region signatures a plan may arrive with: a kept e-e-cross contact keeps its crossing
// sign (no CF-compliant motion changes it, state_identity.h); a contact changed into an
// e-e-cross may arrive with either, and each is a region of its own.
RegionSignatures plan_signatures(const std::vector<PointContact>& contacts,
                                 const std::vector<ContactPlan>& plan) {
  RegionSignature fixed;
  std::vector<std::tuple<int, int, int, int>> open;
  for (size_t i = 0; i < contacts.size(); ++i) {
    const ContactPlan& p = plan[i];
    if (p.action == ContactAction::Keep) {
      const RegionSignature own = region_signature({contacts[i]});
      fixed.insert(fixed.end(), own.begin(), own.end());
    } else if (p.action == ContactAction::Change && p.new_type == PtcType::EECross) {
      open.emplace_back(static_cast<int>(p.new_a.kind), p.new_a.index,
                        static_cast<int>(p.new_b.kind), p.new_b.index);
    }
  }
  RegionSignatures out;
  for (size_t bits = 0; bits < (size_t{1} << open.size()); ++bits) {
    RegionSignature sig = fixed;
    for (size_t k = 0; k < open.size(); ++k) {
      const auto& [ak, ai, bk, bi] = open[k];
      sig.emplace_back(ak, ai, bk, bi, (bits >> k & 1) ? 1 : -1);
    }
    std::sort(sig.begin(), sig.end());
    out.push_back(std::move(sig));
  }
  return out;
}

// The signatures of every plan tried for `h` from `contacts`, sorted and without repeats.
RegionSignatures target_signatures(const std::vector<PointContact>& contacts, const Hypothesis& h) {
  RegionSignatures out;
  const size_t plans = h.plan_options.size();
  for (size_t p = 0; p < plans; ++p)
    for (RegionSignature& sig : plan_signatures(contacts, h.plan_options[p]))
      out.push_back(std::move(sig));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string signature_text(const SceneGeometry& scene, const RegionSignature& sig) {
  std::string out;
  for (const auto& [ak, ai, bk, bi, sign] : sig) {
    if (!out.empty()) out += ", ";
    out += element_pair_name(scene, {static_cast<ElementKind>(ak), ai},
                             {static_cast<ElementKind>(bk), bi});
    out += sign > 0 ? " +" : " -";
  }
  return out;
}

// Where a transition's motions start: the state's witness, or that witness with A turned
// about the contact normal of a contact that becomes an e-e-cross. The turn keeps the contact
// point and the normal and turns A's tangents there: the slide toward the new edge then
// arrives with the edges crossing the other way (state_identity.h: a half turn reverses t_A,
// so the crossing sign).
struct MotionStart {
  bool ok = false;
  Pose pose;
  std::vector<PointContact> contacts;  // in the order of the state's contacts
  std::string prefix;                  // prepended to the motion's name
};

// The starts of a hypothesis's motions: the witness itself, then, for each contact that may
// become an e-e-cross by sliding onto a new edge, the witness turned about its normal so that
// the slide runs along the other edge's tangent, one way and the other: the slide then meets
// the new edge across the other (far from e-e-touch, where either sign is near), each way
// with one crossing sign. (Where the slide has no direction, e.g. leaving a vertex, a half
// turn.) Turned starts are computed on first use.
class MotionStarts {
 public:
  MotionStarts(const SceneGeometry& scene, const State& s, const Hypothesis& h)
      : scene_(scene), s_(s) {
    turns_.push_back({-1, 0, ""});
    // The first two plans' turns first, then (GeneratorOptions::complete_search) the other
    // plans' for the contacts those left without: a start keeps its index whichever plans the
    // search tries (replay_candidate).
    const size_t plans = h.plan_options.size();
    std::vector<bool> turned(s.contacts.size(), false);
    for (const auto& [first, last] :
         {std::pair{size_t{0}, std::min(plans, kFirstPlans)}, std::pair{kFirstPlans, plans}})
      for (size_t i = 0; i < s.contacts.size(); ++i)
        for (size_t p = first; p < last && !turned[i]; ++p) {
          const ContactPlan& cp = h.plan_options[p][i];
          if (cp.action != ContactAction::Change || cp.new_type != PtcType::EECross) continue;
          add_turns(static_cast<int>(i), cp);
          turned[i] = true;
        }
    starts_.resize(turns_.size());
  }
  size_t size() const { return turns_.size(); }
  const MotionStart& at(size_t k, MotionCounters& counters) {
    if (!starts_[k]) {
      const Turn& t = turns_[k];
      if (t.pivot < 0) {
        starts_[k] = MotionStart{true, s_.pose, s_.contacts, ""};
      } else {
        const TurnedWitness w =
            turned_about_normal(scene_, s_.pose, s_.contacts, t.pivot, t.angle, counters);
        starts_[k] = MotionStart{w.ok, w.pose, w.contacts, t.name + "+"};
      }
    }
    return *starts_[k];
  }

 private:
  struct Turn {
    int pivot;
    double angle;
    std::string name;
  };
  void add_turns(int pivot, const ContactPlan& cp) {
    const PointContact& c = s_.contacts[pivot];
    const Eigen::Vector3d& n = c.normal_B;
    if (n.norm() == 0) return;
    const bool on_a = cp.changes_a;
    const ElementId current = on_a ? c.a : c.b;
    const ElementId goal = on_a ? cp.new_a : cp.new_b;
    const Eigen::Vector3d other_tangent = on_a ? c.tangent_b_B : c.tangent_a_B;
    std::optional<Eigen::Vector3d> d;
    if (element_dimension(goal) < element_dimension(current) && other_tangent.norm() > 0)
      d = on_a ? direction_toward(scene_.A, goal, c.p_A, normal_in_A(s_.pose, c), scene_.tol)
               : direction_toward(scene_.B, goal, c.p_B, n, scene_.tol);
    if (!d) {
      turns_.push_back({pivot, M_PI, "halfturn"});
      return;
    }
    // In B's frame; the angle about n from the slide to the other edge's tangent.
    const Eigen::Vector3d slide = on_a ? Eigen::Vector3d(s_.pose.rotate(*d)) : *d;
    const double phi = std::atan2(n.dot(slide.cross(other_tangent)), slide.dot(other_tangent));
    // Turning A by theta turns A's slide by theta (change on A), or A's tangent (change on B).
    const std::string other = on_a ? scene_.B.element_name(c.b) : scene_.A.element_name(c.a);
    for (int way : {1, -1}) {
      double theta = on_a ? phi : -phi;
      if (way < 0) theta += M_PI;
      theta = std::remainder(theta, 2 * M_PI);
      turns_.push_back({pivot, theta, std::string("spin(") + (way > 0 ? "+" : "-") + other + ")"});
    }
  }

  const SceneGeometry& scene_;
  const State& s_;
  std::vector<Turn> turns_;
  std::vector<std::optional<MotionStart>> starts_;
};

// Tries the motions toward `h` for each wanted region signature (all of the hypothesis's when
// `wanted` is null): from each start (MotionStarts), each plan that may arrive with the
// signature, each variant, until one arrives with exactly that signature. A motion is run at
// most once and its outcome shared by the signatures; within one start, once a motion has
// arrived with another signature, that start's remaining variants are left for the next start
// (they slide the same way and would arrive alike).
TryResult try_hypothesis(const SceneGeometry& scene, const State& s, const Hypothesis& h,
                         bool measure, bool complete, const RegionSignatures* wanted = nullptr) {
  TryResult r;
  r.counters.measure = measure;
  r.wanted = wanted ? *wanted : target_signatures(s.contacts, h);
  const size_t plans = h.plan_options.size();
  std::vector<RegionSignatures> plan_sigs;
  for (size_t p = 0; p < plans; ++p)
    plan_sigs.push_back(plan_signatures(s.contacts, h.plan_options[p]));
  const std::vector<MotionVariant> variants = motion_variants();
  MotionStarts starts(scene, s, h);
  std::map<std::tuple<size_t, size_t, size_t>, MotionOutcome> runs;
  const bool signed_target = r.wanted.size() > 1 || !r.wanted.front().empty();
  // No configuration has this CF (convex_support.h): its default motions still run, for what
  // they meet on the way (a failed motion that meets a new contact discovers a state above),
  // and the candidate says why it cannot succeed.
  const std::optional<PtcCount> lone = lone_contact_pair(scene, h.cf);
  for (const RegionSignature& sig : r.wanted) {
    Reached out;
    Candidate& c = out.candidate;
    c.from = s.id;
    c.cf = h.cf;
    if (signed_target) c.crossing = signature_text(scene, sig);
    std::string reasons;
    auto note = [&](const std::string& why) {
      if (!reasons.empty()) reasons += "; ";
      reasons += why;
    };
    bool done = false;
    // The default search: the first two plans with the first five variants, whose settling
    // stops only where the settling contact turns. With `complete`, where that reaches no
    // target: every plan with the general settling rule and the normal drive, and the other
    // plans with the narrow rule again where their general run stopped where it would not
    // have (MotionOutcome::general_stop). A first-pass arrival keeps the witness the default
    // search gives, which other states' motions depend on (the torus's {(fA-e2, 2),
    // (fA-f2, 1)} is met only from the {(fA-e2, 2)} witness it gives, and Example 1 with B
    // moved joins only its arrivals); the second pass adds what it misses (Example 2's
    // {(fA1-e1, 2), (fA1-f1, 1)} in every frame, and three more CFs).
    // No second pass toward a CF no configuration has (`lone`): it cannot be reached, and the
    // first pass's motions toward it already run for what they meet on the way. Without it,
    // Example 1's and Example 2's complete graphs are unchanged, states and links bit for bit
    // (session 44: 5,595 of 49,652 and 48,724 of 1,048,270 queries fewer).
    const int passes = complete && !lone ? 2 : 1;
    for (int pass = 0; pass < passes && !done; ++pass)
      for (size_t k = 0; k < starts.size() && !done; ++k) {
        const MotionStart& start = starts.at(k, r.counters);
        if (!start.ok) {
          if (pass == 0) note("turn about the normal: not CF-compliant from this witness");
          continue;
        }
        bool other_side = false;
        for (size_t p = 0; p < plans && !done && !other_side; ++p) {
          if (std::find(plan_sigs[p].begin(), plan_sigs[p].end(), sig) == plan_sigs[p].end())
            continue;
          if (pass == 0 && p >= kFirstPlans) break;
          for (size_t i = 0; i < variants.size() && !done && !other_side; ++i) {
            // pass 0: the first variants; pass 1: the general-settling ones, then the first
            // ones again (other plans)
            const size_t n = variants.size();
            const size_t v = pass == 0 ? i : (kFirstVariants + i) % n;
            if (pass == 0 && v >= kFirstVariants) break;
            if (!variant_matters(variants[v], h.plan_options[p], start.contacts)) continue;
            // the same motion as one run already, where the other settling rule changes nothing
            const auto same = runs.find({k, p, settling_counterpart(variants, v)});
            if (pass == 1 && same != runs.end() && !same->second.general_stop) continue;
            if (pass == 1 && v < kFirstVariants) {
              if (p < kFirstPlans) continue;  // tried in pass 0
              // after its general run stopped where this one would not, and failed
              if (same == runs.end() || same->second.feasible) continue;
            }
            ++c.attempts;
            auto it = runs.find({k, p, v});
            if (it == runs.end()) {
              MotionOutcome o =
                  run_transition_motion(scene, start.pose, start.contacts, h.plan_options[p], h.cf,
                                        variants[v], r.counters);
              o.motion = start.prefix + o.motion;
              if (o.discovered) r.discovered.push_back(*o.discovered);
              it = runs.emplace(std::make_tuple(k, p, v), std::move(o)).first;
            }
            const MotionOutcome& o = it->second;
            c.motion = o.motion;
            c.steps = o.steps;
            c.run = {static_cast<int>(k), static_cast<int>(p), static_cast<int>(v)};
            if (reaches_target(scene, c, o)) {  // c.crossing is sig's text
              c.feasible = true;
              out.outcome = o;
              done = true;
            } else if (o.feasible) {
              note(o.motion + ": arrives with the crossing " +
                   signature_text(scene, region_signature(o.contacts)));
              other_side = true;
            } else {
              note(o.motion + ": " + o.reason);
              out.outcome = o;
            }
          }
        }
      }
    if (!c.feasible) c.reason = reasons;
    if (lone)
      c.reason = "no configuration has this CF: " + element_pair_name(scene, lone->a, lone->b) +
                 " join convex sets, one strictly convex, so where they touch the objects "
                 "touch nowhere else; " +
                 c.reason;
    r.targets.push_back(std::move(out));
  }
  return r;
}

// An upward probe of a state: a push toward a point (pivot < 0) or a turn about an axis
// through the point of contact `pivot`.
struct Probe {
  int state;
  int pivot;
  Eigen::Vector3d vector;
};

// The parts of a run that ask for collision queries, for GraphStats::queries_by_phase: where
// the time goes (each query attributed to the innermost part running when it was counted).
enum class Phase {
  Seeds,         // the automatic seed search or the listed seeds' projections
  Motions,       // the transition motions of the hypotheses of each BFS level
  Probes,        // the upward probes (pushes and tips) of each BFS level
  Identity,      // joins deciding whether a witness lies in a known state's region
  Retries,       // hypotheses tried again from a state's other witnesses
  MissingLinks,  // hypotheses tried again from waypoints toward a CF's states
  Relabelling,   // the states and links the solids' relabelling half turns imply
  Projections,   // the upward projections: one contact more, from turned witnesses
  Mirror,        // the states and links the solids' mirror planes imply
};
constexpr const char* kPhaseNames[] = {
    "seeds",          "transition motions",           "upward probes",
    "state identity", "retries from other witnesses", "missing-link retries",
    "relabelling",    "upward projections",           "mirror images"};
constexpr int kPhases = sizeof(kPhaseNames) / sizeof(kPhaseNames[0]);

class Builder {
 public:
  Builder(const SceneGeometry& scene, const GeneratorOptions& options,
          GeneratorListener* listener, const std::atomic<bool>* cancel)
      : scene_(scene), options_(options), listener_(listener), cancel_(cancel),
        symmetry_(SceneSymmetry::of(scene)) {
    graph_.scene = scene.spec.name;
    counters_.memo = &memo_;
  }

  StateGraph run();

 private:
  bool cancelled() const { return cancel_ && cancel_->load(); }
  // Joins run ahead of find_state: per (state, member), whether that witness of the state is
  // joined to the pose (joined_within_cf), with the join's counters.
  using JoinsAhead = std::map<std::pair<int, int>, std::pair<bool, MotionCounters>>;
  // The joins find_state(cf, pose, contacts) would try as the graph stands, run on the worker
  // threads while the graph does not change (beside the motions whose ends they place).
  // find_state later takes each from here where it would run it itself, and runs the joins
  // with states and witnesses added in between; each join is a pure function of its two
  // poses, so the graph and the counters do not depend on the thread count.
  JoinsAhead joins_ahead(const ContactFormation& cf, const Pose& pose,
                         const std::vector<PointContact>& contacts) const;
  // What find_state(cf, pose, contacts) with region signature `sig` tries: when a state of
  // that CF and signature already holds the pose as a witness (the first such), no join;
  // otherwise the witnesses of each state of that CF and signature, in id order.
  struct JoinsToTry {
    int holder = -1;
    std::vector<int> states;
  };
  JoinsToTry joins_to_try(const ContactFormation& cf, const RegionSignature& sig,
                          const Pose& pose) const;
  // The state of this CF whose region holds `pose` (whose exact contacts are `contacts`), or
  // -1. A witness joined to several states proves them one state (connectivity is
  // transitive): they are united, and merged when the run ends. `ahead` (optional): joins
  // already run (joins_ahead).
  int find_state(const ContactFormation& cf, const Pose& pose,
                 const std::vector<PointContact>& contacts, const JoinsAhead* ahead = nullptr);
  // joins_ahead of each discovery (none for a null one), on the worker threads.
  std::vector<JoinsAhead> joins_ahead_of(const std::vector<const Discovery*>& found);
  int representative(int id);
  // Whether two poses are one (positions within tol.distinct_points, orientations within
  // kSamePoseAngle): the same witness reached twice.
  bool same_pose(const Pose& a, const Pose& b) const;
  // Renumbers the states after the unions of find_state: one state per class (the lowest
  // id's witness), links and candidates redirected, duplicate links dropped.
  void merge_united_states();
  // States of one CF and region signature that no join proved one while the graph grew, joined
  // now by paths in the contact's parameters (cf_parameter_path.h) or through a roadmap of the
  // region (joined_by_roadmap, state_identity.h): united when one is found.
  // At the end, so that each duplicate's own transitions are in the graph before its links
  // are re-pointed by merge_united_states.
  void join_duplicate_states();
  int add_state(const ContactFormation& cf, const Pose& pose,
                const std::vector<PointContact>& contacts, bool seed, int depth);
  void grow(int seed_id);
  // The hypotheses of a state toward CFs the graph does not have, tried again from each of
  // its other witnesses (feasibility from one witness is incomplete: a motion that fails
  // from one point of a region may succeed from another); each new state found is grown.
  // Repeats until nothing new is found.
  void retry_from_other_witnesses();
  // Tells the listener how far a phase after the BFS levels has come: `done` of `total` units.
  void report_phase(Phase p, const char* unit, int done, int total);
  // A walk over the states [0, n) in order reports its progress through upto(i): each state
  // up to i not yet reported (the walks over ordered_pipeline's commits reach them in order).
  struct StateWalk {
    Builder& builder;
    Phase phase;
    int n;
    int reported = -1;
    void upto(int i) {
      for (; reported < i; ++reported) builder.report_phase(phase, "states", reported + 1, n);
    }
  };
  // ordered_pipeline over n jobs on this run's threads, until cancelled.
  template <typename Skip, typename Job, typename Commit>
  void in_order(size_t n, Skip&& skip, Job&& job, Commit&& commit) {
    ordered_pipeline(
        n, options_.threads, jobs_ahead(options_.threads), [&] { return cancelled(); }, skip, job,
        commit);
  }
  // The motions retry_from_other_witnesses would try as the graph stands, run on the worker
  // threads; keyed by (state, witness, CF). Empty with one thread.
  std::map<std::tuple<int, int, ContactFormation>, TryResult> try_retries_ahead();
  // The region signatures of `h`'s target (from a witness with `contacts`) that no state of
  // the graph has: what a retry still looks for (nothing for a CF no configuration has).
  RegionSignatures missing_signatures(const std::vector<PointContact>& contacts,
                                      const Hypothesis& h) const;
  void add_link(int from, int to, const std::string& motion);
  // The states that the solids' relabelling half turns imply (symmetry.h): each state's
  // witness turned so, one configuration under the other labelling, re-detected exactly. Each
  // whose CF and region signature no state has is added and grown. Returns whether any was.
  bool add_relabelled_states();
  // Each state's witness under each relabelling half turn, re-detected; nullopt where the
  // re-detection does not touch as the state does (left out rather than trusted).
  std::vector<std::optional<Discovery>> relabelled_images(int id);
  // The configuration Y, an image of state id's witness under a symmetry that maps A's
  // elements by `in_A` and B's by `in_B` (nullptr: that solid's stay), re-detected: nullopt
  // unless it touches as the state does, on the images of its elements (no penetration, the
  // state's CF mapped). A witness near its region's boundary may read otherwise there (Example 2
  // far and rotated: a {(eA-e1, 1), (fA2-e1, 1)} witness, reflected, read {(fA2-e1, 2)}, its
  // lens-rim contact on fA2 beside the rim), and the links mirrored through it joined CFs no
  // LN transition joins ({(fA2-e1, 2)} -> {(fA1-e1, 1)} and -> {(eA-f2, 1)}).
  std::optional<Discovery> image_at(int id, const Pose& Y, const ElementMap* in_A,
                                    const ElementMap* in_B);
  // Whether a state of this class (CF and region signature) is held already.
  bool class_held(const ContactFormation& cf, const RegionSignature& sig) const;
  // Each LN link's image under the relabelling half turns and the mirror (mirror_image),
  // between the states the images of its ends join (the turned or reflected motion is a proof:
  // the same motion under the other labelling, or the whole scene reflected).
  void add_relabelled_links();
  // The state holding `d`, the image of state id's witness under a symmetry, or nullopt's -1.
  // An image no state's region joins is added as a state of its own: the image of a region
  // is a region, and its links are the images of id's (session 38: in Example 2 the image of
  // a {(fA2-e1, 2)} state joined none of the three {(fA1-e1, 2)} states, and the image of its
  // link to {(eA-e1, 1), (fA2-f1, 1)} was missing).
  int image_state(int id, const std::optional<Discovery>& d);
  // The LN hypotheses of a state with these contacts, with the plans the search tries: the
  // first two of each, or every kind with GeneratorOptions::complete_search.
  std::vector<Hypothesis> hypotheses(const std::vector<PointContact>& contacts) const;
  // The mirror image of state `id`'s witness (symmetry.h, mirrored: by the first mirror plane
  // of each solid), re-detected exactly; nullopt when a solid has no mirror plane or the image
  // does not touch as the state does. A configuration and its image may lie in different
  // regions of one CF (Example 1's ellipsoid lying across the dish with its rim contact on
  // one side of its wall contact or the other): then the image is a state of its own.
  std::optional<Discovery> mirror_image(int id);
  // Each state's mirror image that no state's region holds (find_state: no join) is added
  // and grown. Returns whether any was.
  bool add_mirrored_states();
  // Where the upward probes of a state push A's centre: toward each element of B that none
  // of its contacts touches (a face's interior point, an edge's middle, a vertex).
  std::vector<Eigen::Vector3d> probe_goals(const State& s) const;
  // States one contact above each state not yet searched, found by projecting its witness,
  // turned about A's centre, onto each CF that adds one PtC and that the graph does not have
  // (paper Section IV: one seed per local maximum; a motion or probe from a witness at the
  // edge of its region can miss a state above it that lies elsewhere along the region). Each
  // new state seeds its own LN graph. Returns whether any state was added.
  bool project_upward();
  // Whether state id's region has a link to a state of CF `cf` (a later union or link makes
  // it so; nothing makes it not so).
  bool linked_to_cf(int id, const ContactFormation& cf) {
    return std::any_of(graph_.links.begin(), graph_.links.end(), [&](const Link& l) {
      return representative(l.from) == representative(id) && graph_.states[l.to].cf == cf;
    });
  }
  // True when some state of the graph has this CF (in any region).
  bool holds_cf(const ContactFormation& cf) const {
    return std::any_of(graph_.states.begin(), graph_.states.end(),
                       [&](const State& s) { return s.cf == cf; });
  }
  std::set<int> projected_upward_;
  // The first i in [0, n) for which test(i, counters) holds, or -1 (test: a join, a pure
  // function of its inputs): the answer, and the counters merged into counters_, of testing
  // them one by one in order, with up to options_.threads tests running at once, at most
  // kJobsAheadPerThread per thread ahead of the first not yet decided (ordered_pipeline).
  // The tests after the first that holds are dropped with their counters, so neither
  // depends on the thread count.
  template <typename Test>
  int first_holding(size_t n, Test&& test);

  const SceneGeometry& scene_;
  GeneratorOptions options_;
  GeneratorListener* listener_;
  const std::atomic<bool>* cancel_;
  SceneSymmetry symmetry_;
  StateGraph graph_;
  ConnectionMemo memo_;  // the run's CF-compliant motions, for the joins that repeat them
  MotionCounters counters_;
  // Collision queries per Phase so far, and the phase now running with the count at its
  // start. The queries count where their counters are merged (a join run ahead counts in
  // state identity, when find_state takes its answer).
  std::array<long, kPhases> phase_queries_{};
  Phase phase_ = Phase::Seeds;
  long phase_start_ = 0;
  // The same for this thread's wall time (GraphStats::seconds_by_phase), whose phase also
  // changes where a batch of parallel work starts (TimeScope): the batch's time is its phase's.
  std::array<double, kPhases> phase_seconds_{};
  Phase time_phase_ = Phase::Seeds;
  std::chrono::steady_clock::time_point phase_since_ = std::chrono::steady_clock::now();
  void switch_time_phase(Phase p) {
    const auto now = std::chrono::steady_clock::now();
    phase_seconds_[static_cast<int>(time_phase_)] +=
        std::chrono::duration<double>(now - phase_since_).count();
    phase_since_ = now;
    time_phase_ = p;
  }
  void switch_phase(Phase p) {
    phase_queries_[static_cast<int>(phase_)] += counters_.detections - phase_start_;
    phase_start_ = counters_.detections;
    phase_ = p;
    switch_time_phase(p);
  }
  // Attributes the queries counted and the time spent while it lives to `p`, then returns to
  // the phases before.
  class PhaseScope {
   public:
    PhaseScope(Builder& b, Phase p) : b_(b), before_(b.phase_), time_before_(b.time_phase_) {
      b_.switch_phase(p);
    }
    ~PhaseScope() {
      b_.switch_phase(before_);
      b_.switch_time_phase(time_before_);
    }
    PhaseScope(const PhaseScope&) = delete;
    PhaseScope& operator=(const PhaseScope&) = delete;

   private:
    Builder& b_;
    Phase before_, time_before_;
  };
  // Attributes the time spent while it lives (not the queries) to `p`: a batch of parallel
  // work whose counters are merged later, each in its own phase.
  class TimeScope {
   public:
    TimeScope(Builder& b, Phase p) : b_(b), before_(b.time_phase_) { b_.switch_time_phase(p); }
    ~TimeScope() { b_.switch_time_phase(before_); }
    TimeScope(const TimeScope&) = delete;
    TimeScope& operator=(const TimeScope&) = delete;

   private:
    Builder& b_;
    Phase before_;
  };
  std::map<std::pair<int, int>, bool> linked_;
  struct Witness {
    Pose pose;
    std::vector<PointContact> contacts;
  };
  // The hypotheses of a state toward a CF the graph has but the state has no link to, tried
  // again from waypoint witnesses on the way to each state of that CF (feasibility from one
  // witness is incomplete: from a witness deep in the region every motion may run into an
  // obstacle that a witness nearer the target avoids).
  void retry_missing_links();
  // A witness of state `id` the fraction `f` of the way toward state `toward`'s witness: the
  // pose there (the target turned by the solids' symmetries to the nearest equivalent)
  // projected onto the state's CF, and joined to the state's witness by CF-compliant motions.
  // Reads only what that phase does not change (the states, their first witnesses and
  // signatures), and counts into `counters`: it runs on the worker threads.
  std::optional<Witness> waypoint(int id, int toward, double f, MotionCounters& counters) const;
  // A witness of state `id` near its first one: that witness turned about or moved along one
  // of A's axes (sample `i` of kRegionSamples), projected onto the state's CF, in the same
  // region signature and joined to the witness by CF-compliant motions. The same reads and
  // counting as waypoint.
  std::optional<Witness> region_sample(int id, int i, MotionCounters& counters) const;
  // Their common end: `start` projected onto state `id`'s CF, a witness of it when the
  // projection has the state's CF and region signature, no penetration, and a CF-compliant
  // motion joins it to the state's witness.
  std::optional<Witness> witness_near(int id, const Pose& start, MotionCounters& counters) const;

  // Per state: the witnesses shown to lie in its region (its own first, then those of later
  // motions that ended there), a roadmap that later witnesses may join at any of its points;
  // its region signature; its class in the union of states proved to be one.
  std::vector<std::vector<Witness>> members_;
  // The states whose mirror images add_mirrored_states has placed: ids below this.
  size_t mirrored_upto_ = 0;
  std::vector<RegionSignature> signatures_;
  // (state, witness, CF) already retried by retry_from_other_witnesses.
  std::set<std::tuple<int, int, ContactFormation>> retried_;
  std::vector<int> united_;
  // States of higher cardinality met by motions from state `from`, in merge order.
  std::vector<std::pair<int, Discovery>> discoveries_;
};

// Roadmap points kept per state: enough to cover a region from several sides (the witnesses
// of transitions into it arrive from each neighbouring region), few enough that a failed
// join costs a bounded number of motions.
constexpr size_t kMaxMembersPerState = 4;
// Orientations closer than this (radians) are one, with positions within tol.distinct_points:
// round-off of a reflection applied twice is ~1e-15.
constexpr double kSamePoseAngle = 1e-9;

bool Builder::same_pose(const Pose& a, const Pose& b) const {
  return (a.position - b.position).norm() <= scene_.tol.distinct_points &&
         a.quaternion.angularDistance(b.quaternion) <= kSamePoseAngle;
}

int Builder::representative(int id) {
  while (united_[id] != id) id = united_[id] = united_[united_[id]];
  return id;
}

template <typename Test>
int Builder::first_holding(size_t n, Test&& test) {
  std::vector<char> holds(n, 0);
  std::vector<MotionCounters> counters(n, counters_.fresh());
  int found = -1;
  in_order(
      n, [](size_t) { return false; }, [&](size_t k) { holds[k] = test(k, counters[k]); },
      [&](size_t k) {
        counters_.merge(counters[k]);
        if (!holds[k]) return true;
        found = static_cast<int>(k);
        return false;
      });
  return found;
}

Builder::JoinsToTry Builder::joins_to_try(const ContactFormation& cf, const RegionSignature& sig,
                                          const Pose& pose) const {
  JoinsToTry out;
  for (const State& s : graph_.states) {
    if (!(s.cf == cf) || signatures_[s.id] != sig) continue;
    for (const Witness& m : members_[s.id])
      if (same_pose(m.pose, pose)) {
        out.holder = s.id;
        out.states.clear();
        return out;
      }
    out.states.push_back(s.id);
  }
  return out;
}

Builder::JoinsAhead Builder::joins_ahead(const ContactFormation& cf, const Pose& pose,
                                         const std::vector<PointContact>& contacts) const {
  JoinsAhead joins;
  for (int id : joins_to_try(cf, region_signature(contacts), pose).states)
    for (size_t m = 0; m < members_[id].size(); ++m) {
      MotionCounters c = counters_.fresh();
      const bool joined = joined_within_cf(scene_, members_[id][m].pose, pose, cf, c, symmetry_);
      joins[{id, static_cast<int>(m)}] = {joined, c};
      if (joined) break;
    }
  return joins;
}

std::vector<Builder::JoinsAhead> Builder::joins_ahead_of(
    const std::vector<const Discovery*>& found) {
  TimeScope time(*this, Phase::Identity);  // (the queries count when find_state takes them)
  // joins_ahead of each, its joins in one list for the worker threads. Each (discovery,
  // state) group tries the state's witnesses in order until one joins, and the groups do not
  // depend on each other, so the list takes every group's first witness, then every group's
  // second, and so on: the threads run other groups' joins before any join that an earlier
  // one of its group may make useless.
  struct Join {
    size_t found, group;  // group: the (discovery, state) whose witnesses are tried in order
    int state, member;
    bool joined = false;
    MotionCounters counters;
  };
  std::vector<std::vector<Join>> by_group;
  size_t joins_listed = 0;
  for (size_t k = 0; k < found.size(); ++k) {
    if (!found[k]) continue;
    const Discovery& d = *found[k];
    for (int id : joins_to_try(d.cf, region_signature(d.contacts), d.pose).states) {
      by_group.emplace_back();
      for (size_t m = 0; m < members_[id].size(); ++m)
        by_group.back().push_back(
            {k, by_group.size() - 1, id, static_cast<int>(m), false, counters_.fresh()});
      joins_listed += by_group.back().size();
    }
  }
  std::vector<Join> list;
  for (size_t m = 0; list.size() < joins_listed; ++m)
    for (const std::vector<Join>& g : by_group)
      if (m < g.size()) list.push_back(g[m]);
  std::vector<char> joined(by_group.size(), 0);
  std::vector<JoinsAhead> joins(found.size());
  in_order(
      list.size(), [&](size_t i) { return joined[list[i].group] != 0; },
      [&](size_t i) {
        Join& j = list[i];
        j.joined = joined_within_cf(scene_, members_[j.state][j.member].pose, found[j.found]->pose,
                                    found[j.found]->cf, j.counters, symmetry_);
      },
      [&](size_t i) {
        const Join& j = list[i];
        joins[j.found][{j.state, j.member}] = {j.joined, j.counters};
        joined[j.group] = j.joined;
        return true;
      });
  return joins;
}

int Builder::find_state(const ContactFormation& cf, const Pose& pose,
                        const std::vector<PointContact>& contacts, const JoinsAhead* ahead) {
  PhaseScope phase(*this, Phase::Identity);
  // A pose a state holds already (a mirror image's image is the witness itself): every join
  // from it was tried when it was placed.
  const JoinsToTry to_try = joins_to_try(cf, region_signature(contacts), pose);
  if (to_try.holder >= 0) return to_try.holder;
  int found = -1;
  for (int id : to_try.states) {
    // Already known to be the state found: nothing to prove.
    if (found >= 0 && representative(id) == representative(found)) continue;
    const std::vector<Witness>& members = members_[id];
    // The joins run ahead first, in order; the members after them (added since) are tried
    // here, a batch at a time.
    size_t m = 0;
    bool joined = false;
    for (; ahead && m < members.size() && !joined; ++m) {
      const auto known = ahead->find({id, static_cast<int>(m)});
      if (known == ahead->end()) break;
      counters_.merge(known->second.second);
      joined = known->second.first;
    }
    if (!joined)
      joined = first_holding(members.size() - m, [&](size_t k, MotionCounters& c) {
                 return joined_within_cf(scene_, members[m + k].pose, pose, cf, c, symmetry_);
               }) >= 0;
    if (!joined) continue;
    if (found < 0) {
      found = id;
      if (members_[id].size() < kMaxMembersPerState)
        members_[id].push_back({pose, contacts});
    } else {
      // `pose` joins both: one region, one state.
      const int r1 = representative(found), r2 = representative(id);
      united_[std::max(r1, r2)] = std::min(r1, r2);
    }
  }
  return found;
}

int Builder::add_state(const ContactFormation& cf, const Pose& pose,
                       const std::vector<PointContact>& contacts, bool seed, int depth) {
  State s;
  s.id = static_cast<int>(graph_.states.size());
  s.cf = cf;
  s.pose = pose.canonical();
  s.contacts = contacts;
  s.seed = seed;
  s.depth = depth;
  graph_.states.push_back(s);
  members_.push_back({{s.pose, s.contacts}});
  signatures_.push_back(region_signature(contacts));
  united_.push_back(s.id);
  if (listener_) listener_->on_state(graph_, graph_.states.back());
  return s.id;
}

void Builder::add_link(int from, int to, const std::string& motion) {
  if (from == to || linked_[{from, to}]) return;
  linked_[{from, to}] = true;
  graph_.links.push_back({from, to, LinkKind::LN, motion});
  // The reverse of an LN transition that drops cardinality is a GN link (Section II-D).
  const int card_from = graph_.states[from].cf.cardinality();
  const int card_to = graph_.states[to].cf.cardinality();
  if (card_to < card_from) {
    graph_.links.push_back({to, from, LinkKind::GN, motion});
  } else if (card_to == card_from && !linked_[{to, from}]) {
    // Between states of one cardinality the reversed motion is itself an LN transition: it
    // keeps the same contacts, crosses the same boundary the other way and ends in `from`'s
    // region. Without it a link's direction would depend on which witness the motion
    // happened to start from (a rigid motion of B's frame swapped the direction of
    // {(fA-e1, 2)} <-> {(fA-e1, 1), (fA-f1, 1)} in Example 1).
    linked_[{to, from}] = true;
    graph_.links.push_back({to, from, LinkKind::LN, "reverse of " + motion});
  }
}

std::vector<Eigen::Vector3d> Builder::probe_goals(const State& s) const {
  auto touched = [&](ElementId b) {
    return std::any_of(s.contacts.begin(), s.contacts.end(),
                       [&](const PointContact& c) { return c.b == b; });
  };
  std::vector<Eigen::Vector3d> goals;
  const Solid& B = scene_.B;
  for (size_t f = 0; f < B.faces.size(); ++f)
    if (!touched({ElementKind::Face, static_cast<int>(f)})) goals.push_back(B.faces[f].interior_point);
  for (size_t e = 0; e < B.edges.size(); ++e)
    if (!touched({ElementKind::Edge, static_cast<int>(e)}) && !B.edges[e].samples.empty())
      goals.push_back(B.edges[e].samples[B.edges[e].samples.size() / 2].point);
  for (size_t v = 0; v < B.vertices.size(); ++v)
    if (!touched({ElementKind::Vertex, static_cast<int>(v)})) goals.push_back(B.vertices[v].point);
  return goals;
}

// Turns of A about its centre from which project_upward starts: kUpwardTurns axes spread over
// the sphere (a Fibonacci lattice), angles up to kUpwardMaxTurn radians (a golden-ratio
// sequence); they move with A, so they do not depend on B's frame or the unit. Sized on
// Example 1's {(fA-e1, 2), (fA-f1, 1)} from the witnesses of the two 2-contact states below
// it: 8 of 474 such starts project onto it, 2 of 474 with B's frame moved far and rotated;
// with 100 turns none did there.
constexpr int kUpwardTurns = 200;
constexpr double kUpwardMaxTurn = 1.2;

bool Builder::project_upward() {
  PhaseScope phase(*this, Phase::Projections);
  struct Target {
    int state;
    ContactFormation cf;
  };
  auto elements = [](const Solid& S) {
    std::vector<ElementId> out;
    for (size_t i = 0; i < S.faces.size(); ++i)
      out.push_back({ElementKind::Face, static_cast<int>(i)});
    for (size_t i = 0; i < S.edges.size(); ++i)
      out.push_back({ElementKind::Edge, static_cast<int>(i)});
    for (size_t i = 0; i < S.vertices.size(); ++i)
      out.push_back({ElementKind::Vertex, static_cast<int>(i)});
    return out;
  };
  const std::vector<ElementId> EA = elements(scene_.A), EB = elements(scene_.B);
  std::vector<Target> targets;
  const int n = static_cast<int>(graph_.states.size());
  for (int id = 0; id < n; ++id) {
    if (!projected_upward_.insert(id).second) continue;
    const ContactFormation& cf = graph_.states[id].cf;
    // A contact that must be the only one has no state above it (convex_support.h).
    if (std::any_of(cf.entries().begin(), cf.entries().end(),
                    [&](const PtcCount& e) { return lone_contact(scene_, e.a, e.b); }))
      continue;
    for (const ElementId& a : EA)
      for (const ElementId& b : EB) {
        // One generic contact more (codimension 1); a lone pair cannot be added to any.
        const PtcType type = ptc_type_between(a.kind, b.kind);
        if (ptc_codimension(type) != 1 || lone_contact(scene_, a, b)) continue;
        ContactFormation t = cf;
        t.add(a, b, type, 1);
        if (!holds_cf(t)) targets.push_back({id, t});
      }
  }
  if (targets.empty()) return false;
  const Eigen::Vector3d cA = scene_.A.bbox.center();
  std::vector<SymmetryAxis> turns;
  for (int i = 0; i < kUpwardTurns; ++i) {
    const double z = 1 - (2.0 * i + 1) / (2.0 * kUpwardTurns), r = std::sqrt(1 - z * z);
    const double phi = i * 2.399963229728653;  // the golden angle
    turns.push_back({cA, Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z)});
  }
  auto angle = [](int i) {
    return kUpwardMaxTurn * std::fmod(0.5 + i * 0.6180339887498949, 1.0);  // golden ratio - 1
  };
  const size_t jobs = targets.size() * turns.size();
  std::vector<std::optional<ProjectionResult>> results(jobs);  // the converged ones
  // Projection j is turn j % turns of target j / turns. They run a state at a time, one job
  // per turn projecting that turn toward each of the state's targets in turn: the targets
  // start from the same turned pose, so they meet its detection in the context's recent
  // reports and the sampled minima of their shared pairs (the state's own) in the job's memo
  // (pair_seeds.h; the same answers, computed once: the results do not change).
  size_t done = 0;  // projections of the states before
  for (size_t first = 0; first < targets.size() && !cancelled();) {
    size_t last = first;
    while (last < targets.size() && targets[last].state == targets[first].state) ++last;
    const size_t n_targets = last - first;
    parallel_for(
        turns.size(), options_.threads, [&] { return cancelled(); },
        [&](size_t i) {
          PairMinimaMemo minima;
          ProjectionOptions options;
          options.minima = &minima;
          const Pose start =
              turned_about_A(graph_.states[targets[first].state].pose, turns[i], angle(i));
          for (size_t t = first; t < last; ++t) {
            ProjectionResult p = project_onto_cf(scene_, start, targets[t].cf, options);
            if (p.ok) results[t * turns.size() + i] = std::move(p);
          }
        },
        [&](size_t finished) {
          // about every 64 projections, as before they ran by turns
          const size_t now = done + finished * n_targets;
          if (now / 64 != (now - n_targets) / 64)
            report_phase(Phase::Projections, "projections", static_cast<int>(now),
                         static_cast<int>(jobs));
        });
    done += n_targets * turns.size();
    first = last;
  }
  if (cancelled()) return false;
  counters_.detections += static_cast<long>(jobs);  // one per projection, as elsewhere
  // In job order (whatever the thread count): the first witness of each target CF and region
  // signature that joins no state seeds one.
  bool added = false;
  std::set<std::pair<ContactFormation, RegionSignature>> seen;
  for (size_t j = 0; j < jobs; ++j) {
    if (!results[j]) continue;
    const ProjectionResult& p = *results[j];
    const ContactFormation& cf = targets[j / turns.size()].cf;
    if (!seen.insert({cf, region_signature(p.contacts)}).second) continue;
    if (touches_along_a_curve(scene_, p.pose, p.contacts)) continue;
    if (find_state(cf, p.pose, p.contacts) >= 0) continue;
    if (static_cast<int>(graph_.states.size()) >= options_.max_states) break;
    grow(add_state(cf, p.pose, p.contacts, true, 0));
    added = true;
  }
  return added;
}

void Builder::grow(int seed_id) {
  std::vector<int> frontier = {seed_id};
  int level = 0;
  while (!frontier.empty() && !cancelled()) {
    // Every hypothesis of every state on this level, in a fixed order.
    std::vector<std::pair<int, Hypothesis>> jobs;
    for (int id : frontier)
      for (Hypothesis& h : hypotheses(graph_.states[id].contacts))
        jobs.emplace_back(id, std::move(h));
    // And the upward probes of each state: toward every element of B it does not touch.
    std::vector<Probe> probes;
    if (options_.probe_upward)
      for (int id : frontier) {
        // A state with a contact that must be the only one has no state above it
        // (convex_support.h): a probe keeping that contact can meet no other.
        const auto& held = graph_.states[id].cf.entries();
        if (std::any_of(held.begin(), held.end(),
                        [&](const PtcCount& e) { return lone_contact(scene_, e.a, e.b); }))
          continue;
        for (const Eigen::Vector3d& goal : probe_goals(graph_.states[id]))
          probes.push_back({id, -1, goal});
        // Tipping about each contact: about an edge's tangent, and about the two axes of the
        // contact plane, each way.
        const State& st = graph_.states[id];
        for (size_t c = 0; c < st.contacts.size(); ++c) {
          const PointContact& pc = st.contacts[c];
          std::vector<Eigen::Vector3d> axes;
          if (pc.tangent_b_B.norm() > 0) axes.push_back(pc.tangent_b_B);
          if (pc.tangent_a_B.norm() > 0) axes.push_back(pc.tangent_a_B);
          if (axes.empty() && pc.normal_B.norm() > 0) {
            const Eigen::Vector3d u = pc.normal_B.unitOrthogonal();
            axes.push_back(u);
            axes.push_back(pc.normal_B.cross(u));
          }
          for (const Eigen::Vector3d& ax : axes)
            for (double sign : {1.0, -1.0})
              probes.push_back({id, static_cast<int>(c), sign * ax});
        }
      }
    std::vector<TryResult> results(jobs.size());
    std::vector<std::vector<JoinsAhead>> ahead(jobs.size());
    std::vector<std::optional<Discovery>> probed(probes.size());
    std::vector<MotionCounters> probe_counters(probes.size());
    {
      // (the probes and the joins of the motions' ends, run here, count their queries in
      // their own phases when merged, and their time in the motions')
      TimeScope batch(*this, Phase::Motions);
      parallel_for(
          jobs.size() + probes.size(), options_.threads, [&] { return cancelled(); },
          [&](size_t j) {
            if (j < jobs.size()) {
              results[j] =
                  try_hypothesis(scene_, graph_.states[jobs[j].first], jobs[j].second,
                                 options_.measure_discretisation, options_.complete_search);
              for (const Reached& t : results[j].targets)
                ahead[j].push_back(t.candidate.feasible
                                       ? joins_ahead(t.candidate.cf, t.outcome.end,
                                                     t.outcome.contacts)
                                       : JoinsAhead{});
              return;
            }
            const size_t k = j - jobs.size();
            const Probe& p = probes[k];
            const State& st = graph_.states[p.state];
            probed[k] = p.pivot < 0 ? probe_for_contact(scene_, st.pose, st.contacts, p.vector,
                                                        probe_counters[k])
                                    : probe_by_rotation(scene_, st.pose, st.contacts, p.pivot,
                                                        p.vector, probe_counters[k]);
          });
    }
    if (cancelled()) break;

    // Merge in job order: deterministic whatever the thread count.
    std::vector<int> next_frontier;
    for (size_t j = 0; j < jobs.size(); ++j) {
      TryResult& r = results[j];
      {
        PhaseScope phase(*this, Phase::Motions);
        counters_.merge(r.counters);
      }
      const int from = jobs[j].first;
      for (size_t k = 0; k < r.targets.size(); ++k) {
        Reached& t = r.targets[k];
        Candidate& c = t.candidate;
        refuse_curve_contact_end(scene_, t.outcome.end, t.outcome.contacts, c);
        if (c.feasible) {
          int to = find_state(c.cf, t.outcome.end, t.outcome.contacts, &ahead[j][k]);
          if (to < 0 && static_cast<int>(graph_.states.size()) < options_.max_states) {
            to = add_state(c.cf, t.outcome.end, t.outcome.contacts, false,
                           graph_.states[c.from].depth + 1);
            next_frontier.push_back(to);
          }
          c.to = to;
          if (to >= 0) add_link(c.from, to, c.motion);
        }
        graph_.candidates.push_back(c);
        if (listener_) listener_->on_candidate(graph_, graph_.candidates.back());
      }
      for (Discovery& d : r.discovered)
        if (adds_one_contact(graph_.states[from].cf, d.cf))
          discoveries_.push_back({from, std::move(d)});
      if (listener_)
        listener_->on_progress(graph_, level, static_cast<int>(j + 1),
                               static_cast<int>(jobs.size()));
    }
    for (size_t k = 0; k < probes.size(); ++k) {
      {
        PhaseScope phase(*this, Phase::Probes);
        counters_.merge(probe_counters[k]);
      }
      if (probed[k] && adds_one_contact(graph_.states[probes[k].state].cf, probed[k]->cf))
        discoveries_.push_back({probes[k].state, std::move(*probed[k])});
    }
    frontier = std::move(next_frontier);
    ++level;
  }
}

void Builder::join_duplicate_states() {
  PhaseScope phase(*this, Phase::Identity);
  const int n = static_cast<int>(graph_.states.size());
  // The walk: each pair of states of one CF and region signature, unless already one state
  // (decided when the walk reaches the pair), is tried by a tangent walk between their first
  // witnesses (the cheapest: most that fail stop at their first piece), then by parameter
  // paths between each of the first's witnesses and each of the second's, in order, until one
  // joins them, then through a roadmap between their first witnesses. Every pair not joined
  // through others gets every attempt, so the states joined do not depend on this order, only
  // the queries spent (Example 1: 24,738 for state identity with the walk first, 26,910 last). Each attempt is a pure function of the states'
  // witnesses (this phase adds none), so all of them run ahead on the worker threads
  // (ordered_pipeline), and the walk uses a result where it would have made the attempt, the
  // others dropped with their counters: neither depends on the thread count.
  struct Pair {
    int i, j;
    bool done = false;
  };
  struct Attempt {
    size_t pair;
    int path;  // witness pair i-th * (j's witnesses) + j-th; -1: the roadmap; -2: the walk
    MotionCounters counters;
    bool joined = false;
  };
  std::vector<Pair> pairs;
  std::vector<Attempt> attempts;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (!(graph_.states[i].cf == graph_.states[j].cf) || signatures_[i] != signatures_[j])
        continue;
      const size_t paths = members_[i].size() * members_[j].size();
      attempts.push_back({pairs.size(), -2, counters_.fresh()});
      for (size_t k = 0; k < paths; ++k)
        attempts.push_back({pairs.size(), static_cast<int>(k), counters_.fresh()});
      attempts.push_back({pairs.size(), -1, counters_.fresh()});
      pairs.push_back({i, j});
    }
  StateWalk walk{*this, Phase::Identity, n};
  in_order(
      attempts.size(),
      [&](size_t k) {
        // joined through others since: one state
        Pair& p = pairs[attempts[k].pair];
        if (!p.done && representative(p.i) == representative(p.j)) p.done = true;
        return p.done;
      },
      [&](size_t k) {
        Attempt& a = attempts[k];
        const Pair& p = pairs[a.pair];
        const std::vector<Witness>&mi = members_[p.i], &mj = members_[p.j];
        const ContactFormation& cf = graph_.states[p.i].cf;
        // The walk along the region's tangent space joined the needle's far frame's duplicate
        // that every other join missed; the roadmap of the region between the two states' own
        // witnesses, the duplicates of Example 1 swapped and of the needle that every path
        // missed.
        if (a.path >= 0)
          a.joined = joined_by_parameter_path(scene_, mi[a.path / mj.size()].pose,
                                              mj[a.path % mj.size()].pose, cf, a.counters,
                                              symmetry_);
        else if (a.path == -1)
          a.joined = joined_by_roadmap(scene_, mi[0].pose, mj[0].pose, cf, signatures_[p.i],
                                       a.counters, nullptr, options_.threads);
        else
          a.joined = joined_by_tangent_walk(scene_, mi[0].pose, mj[0].pose, cf, a.counters,
                                            symmetry_);
      },
      [&](size_t k) {
        const Attempt& a = attempts[k];
        Pair& p = pairs[a.pair];
        walk.upto(p.i);
        counters_.merge(a.counters);  // (not done: skip(k) was false just before)
        if (!a.joined) return true;
        p.done = true;
        const int r1 = representative(p.i), r2 = representative(p.j);
        united_[std::max(r1, r2)] = std::min(r1, r2);
        return true;
      });
  if (!cancelled()) walk.upto(n - 1);
}

std::optional<Discovery> Builder::image_at(int id, const Pose& Y, const ElementMap* in_A,
                                          const ElementMap* in_B) {
  ++counters_.detections;
  ContactReport rep = detect_contacts(scene_, Y);
  // The state's configuration moved by a symmetry: it touches as the state does, on the
  // images of its elements.
  if (rep.penetrating() || rep.contacts.size() != graph_.states[id].contacts.size())
    return std::nullopt;
  ContactFormation cf = ContactFormation::of(rep.contacts);
  if (!(cf == image_cf(graph_.states[id].cf, in_A, in_B))) return std::nullopt;
  return Discovery{std::move(cf), Y, std::move(rep.contacts)};
}

bool Builder::class_held(const ContactFormation& cf, const RegionSignature& sig) const {
  return std::any_of(graph_.states.begin(), graph_.states.end(),
                     [&](const State& s) { return s.cf == cf && signatures_[s.id] == sig; });
}

std::vector<std::optional<Discovery>> Builder::relabelled_images(int id) {
  const State& st = graph_.states[id];
  std::vector<std::optional<Discovery>> images;
  for (size_t k = 0; k < symmetry_.relabelling_A.size(); ++k)
    images.push_back(image_at(id, turned_about_A(st.pose, symmetry_.relabelling_A[k], M_PI),
                              &symmetry_.relabelling_A_elements[k], nullptr));
  for (size_t k = 0; k < symmetry_.relabelling_B.size(); ++k)
    images.push_back(image_at(id, turned_about_B(st.pose, symmetry_.relabelling_B[k], M_PI),
                              nullptr, &symmetry_.relabelling_B_elements[k]));
  return images;
}

bool Builder::add_relabelled_states() {
  PhaseScope phase(*this, Phase::Relabelling);
  if (symmetry_.relabelling_A.empty() && symmetry_.relabelling_B.empty()) return false;
  bool added = false;
  const int n = static_cast<int>(graph_.states.size());
  for (int id = 0; id < n && !cancelled(); ++id) {
    for (std::optional<Discovery>& image : relabelled_images(id)) {
      if (!image) continue;
      if (class_held(image->cf, region_signature(image->contacts)) ||
          static_cast<int>(graph_.states.size()) >= options_.max_states)
        continue;
      grow(add_state(image->cf, image->pose, image->contacts, false, graph_.states[id].depth));
      added = true;
    }
  }
  return added;
}

std::vector<Hypothesis> Builder::hypotheses(const std::vector<PointContact>& contacts) const {
  std::vector<Hypothesis> hs = hypothesise_ln(scene_, contacts, options_.complete_search);
  if (!options_.complete_search)
    for (Hypothesis& h : hs)
      if (h.plan_options.size() > kFirstPlans) h.plan_options.resize(kFirstPlans);
  return hs;
}

int Builder::image_state(int id, const std::optional<Discovery>& d) {
  if (!d) return -1;
  const int found = find_state(d->cf, d->pose, d->contacts);
  // With the complete search an image that joins no state is one (so every link's image is a
  // link); otherwise it is left out, with its links.
  if (found >= 0 || !options_.complete_search ||
      static_cast<int>(graph_.states.size()) >= options_.max_states)
    return found;
  return add_state(d->cf, d->pose, d->contacts, false, graph_.states[id].depth);
}

void Builder::add_relabelled_links() {
  const bool relabelling = !symmetry_.relabelling_A.empty() || !symmetry_.relabelling_B.empty();
  const bool mirror =
      options_.mirror_images && !symmetry_.mirrors_A.empty() && !symmetry_.mirrors_B.empty();
  if (!relabelling && !mirror) return;
  const int n = static_cast<int>(graph_.states.size());
  // image[id][k]: the state the k-th image of id's witness joins, or -1; the mirror image last.
  // First each image is joined to the states there are (find_state), and none is added yet.
  std::vector<std::vector<int>> image(n);
  std::vector<std::vector<std::optional<Discovery>>> images(n);
  auto join = [&](int id, std::optional<Discovery> d) {
    image[id].push_back(d ? find_state(d->cf, d->pose, d->contacts) : -1);
    images[id].push_back(std::move(d));
  };
  for (int id = 0; id < n && !cancelled(); ++id) {
    {
      PhaseScope phase(*this, Phase::Relabelling);
      for (std::optional<Discovery>& d : relabelled_images(id)) join(id, std::move(d));
    }
    if (mirror) {
      PhaseScope phase(*this, Phase::Mirror);
      join(id, mirror_image(id));
    }
  }
  if (cancelled()) return;
  // Each symmetry here is an involution (a half turn, a mirror): where t's image joins s, the
  // image of that join's motions joins s's image to t, so s's image is t whether or not a join
  // from s's side proves it (session 52: Example 2 with B moved held {(eA-e1, 1), (fA1-f1, 1)}
  // and its fA2 image three times each, the third an image that no join reached though its
  // state's image had joined).
  for (int t = 0; t < n; ++t)
    for (size_t k = 0; k < image[t].size(); ++k) {
      const int s = image[t][k];
      if (s >= 0 && s < n && image[s][k] < 0 && images[s][k]) image[s][k] = t;
    }
  // The images that join no state: with the complete search each is a state (image_state).
  // image_state asks find_state again: the joins of pass one added witnesses to the states,
  // and this pass adds states, either of which an image may join now.
  for (int id = 0; id < n && !cancelled(); ++id)
    for (size_t k = 0; k < image[id].size(); ++k)
      if (image[id][k] < 0 && images[id][k]) {
        PhaseScope phase(*this, mirror && k + 1 == image[id].size() ? Phase::Mirror
                                                                    : Phase::Relabelling);
        image[id][k] = image_state(id, images[id][k]);
      }
  if (cancelled()) return;
  // The images of the links added here are links too (the mirror image of a relabelled link:
  // the two symmetries composed), so the links are imaged until no new one comes. The states
  // that image_state added have no images of their own (ids from n on).
  for (size_t done = 0; done < graph_.links.size();) {
    const size_t end = graph_.links.size();
    for (size_t i = done; i < end; ++i) {
      const Link l = graph_.links[i];  // (add_link appends to graph_.links)
      if (l.kind != LinkKind::LN || l.from >= n || l.to >= n) continue;
      for (size_t k = 0; k < image[l.from].size(); ++k) {
        const int from = image[l.from][k], to = image[l.to][k];
        const bool mirrored = mirror && k + 1 == image[l.from].size();
        if (from >= 0 && to >= 0)
          add_link(from, to, l.motion + (mirrored ? ", mirrored" : ", relabelled"));
      }
    }
    done = end;
  }
}

std::optional<Discovery> Builder::mirror_image(int id) {
  if (symmetry_.mirrors_A.empty() || symmetry_.mirrors_B.empty()) return std::nullopt;
  return image_at(id,
                  mirrored(graph_.states[id].pose, symmetry_.mirrors_A[0], symmetry_.mirrors_B[0]),
                  &symmetry_.mirror_A_elements[0], &symmetry_.mirror_B_elements[0]);
}

bool Builder::add_mirrored_states() {
  PhaseScope phase(*this, Phase::Mirror);
  bool added = false;
  const int n = static_cast<int>(graph_.states.size());
  // The images first (a state's witness never changes: each is placed once), and their joins
  // on the worker threads.
  std::vector<std::optional<Discovery>> images;
  for (int id = static_cast<int>(mirrored_upto_); id < n && !cancelled(); ++id)
    images.push_back(mirror_image(id));
  std::vector<const Discovery*> placed;
  for (const std::optional<Discovery>& image : images) placed.push_back(image ? &*image : nullptr);
  const std::vector<JoinsAhead> ahead = joins_ahead_of(placed);
  const int first = static_cast<int>(mirrored_upto_);
  for (int id = first; id < first + static_cast<int>(images.size()) && !cancelled(); ++id) {
    mirrored_upto_ = id + 1;
    const std::optional<Discovery>& image = images[id - first];
    if (!image || static_cast<int>(graph_.states.size()) >= options_.max_states) continue;
    if (find_state(image->cf, image->pose, image->contacts, &ahead[id - first]) >= 0) continue;
    // The mirror reverses every crossing sign (state_identity.h), so an image with a crossing
    // contact lies in another class (CF and region signature) than its source. When the graph
    // holds a state of that class already, the image is taken to be in one of its regions,
    // unjoined or not: joins of e-e-cross witnesses near the rims' touch fail often (measured:
    // the lens tip on the dish tip's {(eA-e1, 1)} image, a third state of two signs). Only an
    // image of its source's own class (no crossing contact: Example 1's two hands) is a state
    // of its own when no join proves it one with a state.
    const RegionSignature sig = region_signature(image->contacts);
    if (!(image->cf == graph_.states[id].cf && sig == signatures_[id]) &&
        class_held(image->cf, sig))
      continue;
    grow(add_state(image->cf, image->pose, image->contacts, false, graph_.states[id].depth));
    added = true;
  }
  return added;
}

void Builder::merge_united_states() {
  const int n = static_cast<int>(graph_.states.size());
  std::vector<int> new_id(n, -1);
  std::vector<State> states;
  for (int i = 0; i < n; ++i) {
    const int r = representative(i);
    if (r == i) {
      new_id[i] = static_cast<int>(states.size());
      states.push_back(graph_.states[i]);
      states.back().id = new_id[i];
    }
  }
  if (static_cast<int>(states.size()) == n) return;
  for (int i = 0; i < n; ++i) {
    const int r = representative(i);
    new_id[i] = new_id[r];
    State& kept = states[new_id[i]];
    kept.seed = kept.seed || graph_.states[i].seed;
    kept.depth = std::min(kept.depth, graph_.states[i].depth);
  }
  std::vector<Link> links;
  std::map<std::tuple<int, int, int>, bool> seen;
  for (Link l : graph_.links) {
    l.from = new_id[l.from];
    l.to = new_id[l.to];
    if (l.from == l.to) continue;
    if (seen[{l.from, l.to, static_cast<int>(l.kind)}]) continue;
    seen[{l.from, l.to, static_cast<int>(l.kind)}] = true;
    links.push_back(l);
  }
  for (Candidate& c : graph_.candidates) {
    // A candidate tried from a state merged into another started at that state's witness,
    // which is not the merged state's own: it keeps the pose, so that a replay (pcsg figures
    // from a stored graph) starts where the motion did.
    if (!c.start && representative(c.from) != c.from) c.start = graph_.states[c.from].pose;
    c.from = new_id[c.from];
    if (c.to >= 0) c.to = new_id[c.to];
  }
  graph_.states = std::move(states);
  graph_.links = std::move(links);
}

void Builder::report_phase(Phase p, const char* unit, int done, int total) {
  if (listener_)
    listener_->on_phase_progress(
        graph_, std::string(kPhaseNames[static_cast<int>(p)]) + " (" + unit + ")", done, total);
}

void Builder::retry_from_other_witnesses() {
  PhaseScope phase(*this, Phase::Retries);
  for (bool found_new = true; found_new && !cancelled();) {
    found_new = false;
    // The motions this pass will try as things stand, run ahead on the worker threads (each
    // is a pure function of the scene, the witness and the hypothesis). The pass below then
    // walks them in its fixed order and uses a result only where it would have run the
    // motion itself; a motion made moot by a state found earlier in the walk is dropped, and
    // one the walk reaches unforeseen (a state or witness added meanwhile) runs there. So the
    // graph and the counters do not depend on the thread count.
    std::map<std::tuple<int, int, ContactFormation>, TryResult> ahead =
        try_retries_ahead();
    for (size_t id = 0; id < graph_.states.size() && !cancelled(); ++id) {
      report_phase(Phase::Retries, "states", static_cast<int>(id),
                   static_cast<int>(graph_.states.size()));
      for (size_t k = 1; k < members_[id].size(); ++k) {
        State from = graph_.states[id];
        from.pose = members_[id][k].pose;
        from.contacts = members_[id][k].contacts;
        for (const Hypothesis& h : hypotheses(from.contacts)) {
          if (!retried_.insert({static_cast<int>(id), static_cast<int>(k), h.cf}).second)
            continue;
          const RegionSignatures wanted = missing_signatures(from.contacts, h);
          if (wanted.empty()) continue;
          if (static_cast<int>(graph_.states.size()) >= options_.max_states) return;
          // A motion run ahead for other wanted signatures is not the one the walk would run.
          const auto found = ahead.find({static_cast<int>(id), static_cast<int>(k), h.cf});
          TryResult r = found != ahead.end() && found->second.wanted == wanted
                            ? std::move(found->second)
                            : try_hypothesis(scene_, from, h, options_.measure_discretisation,
                                             kRetriesTryEveryMotion, &wanted);
          counters_.merge(r.counters);
          for (Discovery& d : r.discovered)
            if (adds_one_contact(from.cf, d.cf)) discoveries_.push_back({from.id, std::move(d)});
          // Each signature reached is a region the graph does not have (`wanted`).
          std::vector<int> reached;
          for (Reached& t : r.targets) {
            refuse_curve_contact_end(scene_, t.outcome.end, t.outcome.contacts, t.candidate);
            if (!t.candidate.feasible) continue;
            const int to =
                add_state(h.cf, t.outcome.end, t.outcome.contacts, false, from.depth + 1);
            t.candidate.to = to;
            t.candidate.start = from.pose;
            graph_.candidates.push_back(t.candidate);
            if (listener_) listener_->on_candidate(graph_, graph_.candidates.back());
            add_link(from.id, to, t.candidate.motion);
            reached.push_back(to);
          }
          for (int to : reached) grow(to);
          found_new = found_new || !reached.empty();
        }
      }
    }
  }
}

std::map<std::tuple<int, int, ContactFormation>, TryResult> Builder::try_retries_ahead() {
  struct Job {
    int id, k;
    Hypothesis h;
    RegionSignatures wanted;
  };
  std::vector<Job> jobs;
  std::set<std::tuple<int, int, ContactFormation>> listed;
  for (size_t id = 0; id < graph_.states.size(); ++id)
    for (size_t k = 1; k < members_[id].size(); ++k)
      for (Hypothesis& h : hypotheses(members_[id][k].contacts)) {
        const std::tuple<int, int, ContactFormation> key{static_cast<int>(id),
                                                         static_cast<int>(k), h.cf};
        if (retried_.count(key) || !listed.insert(key).second) continue;
        RegionSignatures wanted = missing_signatures(members_[id][k].contacts, h);
        if (wanted.empty()) continue;
        jobs.push_back(
            {static_cast<int>(id), static_cast<int>(k), std::move(h), std::move(wanted)});
      }
  std::vector<TryResult> results(jobs.size());
  // One thread: nothing to run ahead, the walk runs each motion it needs (and only those).
  if (std::min<int>(options_.threads, static_cast<int>(jobs.size())) < 2) return {};
  parallel_for(
      jobs.size(), options_.threads, [&] { return cancelled(); },
      [&](size_t j) {
        State from = graph_.states[jobs[j].id];
        from.pose = members_[jobs[j].id][jobs[j].k].pose;
        from.contacts = members_[jobs[j].id][jobs[j].k].contacts;
        results[j] = try_hypothesis(scene_, from, jobs[j].h, options_.measure_discretisation,
                                    kRetriesTryEveryMotion, &jobs[j].wanted);
      },
      [&](size_t finished) {
        report_phase(Phase::Retries, "motions run ahead", static_cast<int>(finished),
                     static_cast<int>(jobs.size()));
      });
  std::map<std::tuple<int, int, ContactFormation>, TryResult> out;
  if (cancelled()) return out;
  for (size_t j = 0; j < jobs.size(); ++j)
    out.emplace(std::make_tuple(jobs[j].id, jobs[j].k, jobs[j].h.cf), std::move(results[j]));
  return out;
}

std::optional<Builder::Witness> Builder::waypoint(int id, int toward, double f,
                                                  MotionCounters& counters) const {
  const State& s = graph_.states[id];
  const Pose& to = graph_.states[toward].pose;
  // The target as near the state's witness as the solids' symmetries allow: their half turns
  // and turns about an axis of revolution relabel points without moving anything.
  Pose target = to;
  double best = std::numeric_limits<double>::infinity();
  for (const Pose& t : symmetric_images(to, symmetry_)) {
    const Pose a = aligned_by_symmetry(scene_, t, s.pose, symmetry_);
    const double angle = a.quaternion.angularDistance(s.pose.quaternion);
    if (angle < best) best = angle, target = a;
  }
  return witness_near(id, between(s.pose, target, f), counters);
}

std::optional<Builder::Witness> Builder::witness_near(int id, const Pose& start,
                                                      MotionCounters& counters) const {
  const State& s = graph_.states[id];
  ++counters.detections;
  const ProjectionResult proj = project_onto_cf(scene_, start, s.cf);
  if (!proj.ok) return std::nullopt;
  ++counters.detections;
  const ContactReport rep = detect_contacts(scene_, proj.pose);
  if (rep.penetrating() || !(ContactFormation::of(rep.contacts) == s.cf) ||
      region_signature(rep.contacts) != signatures_[id])
    return std::nullopt;
  // a witness of this very state only when a CF-compliant motion joins them
  if (!joined_within_cf(scene_, s.pose, proj.pose, s.cf, counters, symmetry_)) return std::nullopt;
  return Witness{proj.pose, rep.contacts};
}

// The region samples of retry_missing_links: the state's witness turned about each of A's
// axes through A's centre by +-kSampleTurns radians, and moved along each by +-kSampleShifts
// of A's half-diagonal. They move with A, so they do not depend on B's frame or the unit.
// Each size is two or three times the one before (on the needle the smallest shift is about
// one motion step): a narrow region keeps the small ones, a wide one lets the large ones leave
// the witness's neighbourhood (GeneratorOptions::region_samples). Sized on the needle in the dish
// (scenes/stress/needle_in_dish.yaml), whose own frame lacked {(fA-e1, 1), (fA-f1, 1)} ->
// {(fA-f2, 1)}: the hypothesis fails from the region's witness and every waypoint, and
// succeeds from a sample that, projected, lies 0.137 rad (about A's x axis, across the
// needle) and 0.58 (4.5% of L) from the witness.
constexpr std::array<double, 6> kSampleTurns = {0.15, -0.15, 0.3, -0.3, 0.6, -0.6};
constexpr std::array<double, 4> kSampleShifts = {0.05, -0.05, 0.15, -0.15};
constexpr int kRegionSamples = 3 * static_cast<int>(kSampleTurns.size() + kSampleShifts.size());

std::optional<Builder::Witness> Builder::region_sample(int id, int i,
                                                       MotionCounters& counters) const {
  const State& s = graph_.states[id];
  const int per_axis = static_cast<int>(kSampleTurns.size() + kSampleShifts.size());
  const int axis = i / per_axis, k = i % per_axis;
  const Eigen::Vector3d u = Eigen::Vector3d::Unit(axis);
  Pose start = s.pose;
  if (k < static_cast<int>(kSampleTurns.size())) {
    start = turned_about_A(s.pose, {scene_.A.bbox.center(), u}, kSampleTurns[k]);
  } else {
    const double size = scene_.A.bbox.diagonal().norm() / 2;
    start.position += s.pose.rotate(u * (kSampleShifts[k - kSampleTurns.size()] * size));
  }
  return witness_near(id, start, counters);
}

void Builder::retry_missing_links() {
  PhaseScope phase(*this, Phase::MissingLinks);
  const int n = static_cast<int>(graph_.states.size());
  // The walk: for each state and each of its hypotheses toward a CF the graph has but the
  // state has no link to (decided when the walk reaches it), attempts in order until one
  // links: the hypothesis from each of the state's other witnesses, then from waypoints
  // halfway and three quarters of the way toward each state of that CF, then from samples of
  // the state's region around its witness (region_sample). The attempts'
  // motions (and waypoints) are pure functions of what this phase does not change, so they
  // run ahead on the worker threads (ordered_pipeline); the walk uses each result where it
  // would have made the attempt, and drops the others with their counters: the graph and the
  // counters do not depend on the thread count.
  struct Group {
    int id;
    ContactFormation cf;
    std::vector<int> targets;  // the states of that CF
    size_t members;            // the state's witnesses listed when the attempts were
    bool done = false;
  };
  struct Attempt {
    size_t group;
    int member = -1;  // the state's witness it starts from, or -1: a waypoint or a sample
    int target = -1;  // the waypoint's: toward this state,
    double f = 0;     // this fraction of the way
    int sample = -1;  // or this region sample
    MotionCounters counters;
    std::optional<Witness> from;
    std::optional<TryResult> tried;  // none when the start has no hypothesis toward the CF
  };
  std::vector<Group> groups;
  std::vector<Attempt> attempts;
  for (int id = 0; id < n; ++id)
    for (const Hypothesis& h : hypotheses(graph_.states[id].contacts)) {
      Group g{id, h.cf, {}, members_[id].size()};
      for (const State& t : graph_.states)
        if (t.cf == h.cf) g.targets.push_back(t.id);
      if (g.targets.empty() || linked_to_cf(id, h.cf)) continue;  // links are never removed
      for (size_t k = 1; k < g.members; ++k)  // (a copy: the walk may add witnesses meanwhile)
        attempts.push_back({groups.size(), static_cast<int>(k), -1, 0, -1, counters_.fresh(),
                            members_[id][k], {}});
      for (int t : g.targets)
        for (double f : {0.5, 0.75})
          attempts.push_back({groups.size(), -1, t, f, -1, counters_.fresh(), {}, {}});
      for (int i = 0; i < (options_.region_samples ? kRegionSamples : 0); ++i)
        attempts.push_back({groups.size(), -1, -1, 0, i, counters_.fresh(), {}, {}});
      groups.push_back(std::move(g));
    }
  // From `from` (a pose of the group's state's region), the first hypothesis toward its CF.
  auto try_from = [&](const Group& g, const Witness& from, MotionCounters& counters) {
    State start = graph_.states[g.id];
    start.pose = from.pose;
    start.contacts = from.contacts;
    // the plans index the start's own contacts
    for (const Hypothesis& hw : hypotheses(start.contacts)) {
      if (!(hw.cf == g.cf)) continue;
      TryResult r = try_hypothesis(scene_, start, hw, options_.measure_discretisation,
                                   options_.complete_search);
      counters.merge(r.counters);
      return std::optional<TryResult>(std::move(r));
    }
    return std::optional<TryResult>();
  };
  // The walk's use of an attempt's motion: a link when it arrives in a state the graph has.
  auto links_from = [&](const Group& g, const Witness& from, TryResult& r) {
    bool found = false;
    for (Reached& t : r.targets) {
      if (!t.candidate.feasible) continue;
      const int to = find_state(g.cf, t.outcome.end, t.outcome.contacts);
      if (to < 0) continue;
      t.candidate.to = to;
      t.candidate.start = from.pose;
      graph_.candidates.push_back(t.candidate);
      if (listener_) listener_->on_candidate(graph_, graph_.candidates.back());
      add_link(g.id, to, t.candidate.motion);
      found = true;
    }
    return found;
  };
  StateWalk walk{*this, Phase::MissingLinks, n};
  in_order(
      attempts.size(),
      [&](size_t j) {
        // A link added since the attempts were listed (from an earlier state of one region)
        // settles the group: it stays linked.
        Group& g = groups[attempts[j].group];
        if (!g.done && linked_to_cf(g.id, g.cf)) g.done = true;
        return g.done;
      },
      [&](size_t j) {
        Attempt& a = attempts[j];
        const Group& g = groups[a.group];
        if (a.member < 0) {
          a.from = a.sample < 0 ? waypoint(g.id, a.target, a.f, a.counters)
                                : region_sample(g.id, a.sample, a.counters);
          if (!a.from) return;
        }
        a.tried = try_from(g, *a.from, a.counters);
      },
      [&](size_t j) {
        Attempt& a = attempts[j];
        Group& g = groups[a.group];
        walk.upto(g.id);
        // (not done: skip(j) was false just before)
        if (a.member < 0 && g.members < members_[g.id].size()) {
          // Witnesses the walk added to the state since the attempts were listed come before
          // the waypoints: tried here, in order.
          for (size_t k = g.members; k < members_[g.id].size() && !g.done; ++k) {
            const Witness from = members_[g.id][k];
            MotionCounters c = counters_.fresh();
            std::optional<TryResult> r = try_from(g, from, c);
            counters_.merge(c);
            g.done = r && links_from(g, from, *r);
          }
          g.members = members_[g.id].size();
          if (g.done) return true;
        }
        counters_.merge(a.counters);
        g.done = a.from && a.tried && links_from(g, *a.from, *a.tried);
        return true;
      });
  if (!cancelled()) walk.upto(n - 1);
}

RegionSignatures Builder::missing_signatures(const std::vector<PointContact>& contacts,
                                             const Hypothesis& h) const {
  RegionSignatures out;
  // A CF no configuration has (convex_support.h) is no region a retry could reach.
  if (lone_contact_pair(scene_, h.cf)) return out;
  for (RegionSignature& sig : target_signatures(contacts, h)) {
    bool have = false;
    for (const State& s : graph_.states)
      if (s.cf == h.cf && signatures_[s.id] == sig) have = true;
    if (!have) out.push_back(std::move(sig));
  }
  return out;
}

StateGraph Builder::run() {
  const auto t0 = std::chrono::steady_clock::now();
  phase_since_ = t0;
  std::vector<SeedCandidate> seeds;  // Phase::Seeds, the phase a Builder starts in
  if (scene_.spec.auto_seeds) {
    seeds = find_seed_candidates(scene_, counters_, options_.threads);
  } else {
    for (const SeedSpec& s : scene_.spec.seeds) seeds.push_back(seed_from_pose(scene_, s, counters_));
  }
  // Highest cardinality first: a local maximum's LN graph covers the states below it, so later
  // candidates already in the graph add nothing (Section IV: one seed per local maximum).
  // The off-centre pushes' candidates wait until the graph is otherwise complete, and then
  // seed only CFs it lacks: a seed of a CF the growth reaches anyway would grow the graph
  // from other witnesses, and feasibility depends on the witness (mixed in by cardinality,
  // they cost the torus's graph 2 of its 29 distinct CF links).
  std::vector<SeedCandidate> off_centre;
  for (const SeedCandidate& sc : seeds) {
    if (cancelled()) break;
    if (sc.off_centre) {
      off_centre.push_back(sc);
      continue;
    }
    // An automatic candidate whose CF the graph already has adds a seed only for a separate
    // region, and a failed connectivity motion does not prove one; it is left out (a CF that
    // is new to the graph always seeds). Listed seeds are checked for connectivity.
    if (scene_.spec.auto_seeds && holds_cf(sc.cf)) continue;
    if (touches_along_a_curve(scene_, sc.pose, sc.contacts)) continue;
    const int existing = find_state(sc.cf, sc.pose, sc.contacts);
    if (existing >= 0) {
      if (!scene_.spec.auto_seeds) graph_.states[existing].seed = true;
      continue;
    }
    grow(add_state(sc.cf, sc.pose, sc.contacts, true, 0));
  }
  // Local maxima the seeds missed: a motion that met a new contact has reached a state of
  // higher cardinality from below (its GN direction); each such state not yet in the graph
  // seeds an LN graph of its own, linked to the state it was met from. Repeats until none is
  // new, so every local maximum connected to the seeds by neighbouring transitions is found.
  // Then the hypotheses toward CFs still missing, from the states' other witnesses; and the
  // discoveries those motions make, until neither finds anything new.
  for (size_t k = 0;;) {
    // The joins of the discoveries pending now, on the worker threads (those the growth
    // below adds wait for the next pass).
    std::vector<const Discovery*> pending;
    for (size_t i = k; i < discoveries_.size(); ++i) pending.push_back(&discoveries_[i].second);
    const std::vector<JoinsAhead> ahead = joins_ahead_of(pending);
    const size_t first = k;
    for (; k < discoveries_.size() && !cancelled(); ++k) {
      const auto [from, d] = discoveries_[k];
      if (static_cast<int>(graph_.states.size()) >= options_.max_states) break;
      if (touches_along_a_curve(scene_, d.pose, d.contacts)) continue;
      int id = find_state(d.cf, d.pose, d.contacts,
                          k - first < ahead.size() ? &ahead[k - first] : nullptr);
      if (id < 0) {
        id = add_state(d.cf, d.pose, d.contacts, true, 0);
        grow(id);
      }
      // The met state is `from` plus one contact: removing it (the reverse of the motion
      // that met it) leads back down to `from`, an LN transition. (The label names no state:
      // merge_united_states renumbers them, and the link's images keep the label.)
      add_link(id, from, "separation (reverse of the motion that met it)");
    }
    const size_t states = graph_.states.size(), found = discoveries_.size();
    retry_from_other_witnesses();
    if (!cancelled()) add_relabelled_states();
    if (cancelled()) break;
    if (graph_.states.size() == states && discoveries_.size() == found) {
      // Nothing new: then the off-centre pushes' seeds of CFs the graph lacks (once), the
      // mirror images no state's region holds (after the growth, so that every state the
      // motions reach is found first, from its own side), and the states above each state
      // that no motion or probe met.
      bool seeded = false;
      for (const SeedCandidate& sc : off_centre) {
        if (cancelled()) break;
        if (holds_cf(sc.cf) || touches_along_a_curve(scene_, sc.pose, sc.contacts)) continue;
        grow(add_state(sc.cf, sc.pose, sc.contacts, true, 0));
        seeded = true;
      }
      off_centre.clear();
      if (seeded) continue;
      if (options_.mirror_images && add_mirrored_states()) continue;
      if (options_.project_upward && project_upward()) continue;
      break;
    }
  }

  if (!cancelled()) retry_missing_links();
  if (!cancelled()) add_relabelled_links();
  if (!cancelled()) join_duplicate_states();
  merge_united_states();

  switch_phase(phase_);  // the running phase's queries and time so far
  graph_.stats.seconds = std::chrono::duration<double>(phase_since_ - t0).count();
  graph_.stats.collision_queries = counters_.detections;
  for (int p = 0; p < kPhases; ++p) {
    graph_.stats.queries_by_phase.emplace_back(kPhaseNames[p], phase_queries_[p]);
    graph_.stats.seconds_by_phase.emplace_back(kPhaseNames[p], phase_seconds_[p]);
  }
  graph_.stats.pair_solves = counters_.pair_solves;
  graph_.stats.motion_steps = counters_.steps;
  graph_.stats.max_keep_drift = counters_.max_keep_drift;
  graph_.stats.max_step_penetration = counters_.max_step_penetration;
  for (const State& s : graph_.states)
    for (const PointContact& c : s.contacts)
      graph_.stats.max_witness_residual =
          std::max(graph_.stats.max_witness_residual, std::abs(c.gap));
  return std::move(graph_);
}

}  // namespace

StateGraph generate_graph(const SceneGeometry& scene, const GeneratorOptions& options,
                          GeneratorListener* listener, const std::atomic<bool>* cancel) {
  if (options.motion_step < 0)
    throw std::invalid_argument("generate_graph: motion_step must be >= 0, got " +
                                std::to_string(options.motion_step));
  const double step = options.motion_step * scene.tol.length_scale;
  if (options.motion_step > 0 && step != scene.tol.motion_step) {
    // The motions read the step from the scene's tolerances: run on a copy that has it.
    SceneGeometry stepped = scene;
    stepped.tol.motion_step = step;
    Builder b(stepped, options, listener, cancel);
    return b.run();
  }
  Builder b(scene, options, listener, cancel);
  return b.run();
}

State candidate_start(const SceneGeometry& scene, const State& from, const Candidate& candidate) {
  const bool exact = std::all_of(from.contacts.begin(), from.contacts.end(),
                                 [](const PointContact& c) { return c.jacobian.rows() > 0; });
  if (!candidate.start && exact) return from;
  State s = from;
  if (candidate.start) s.pose = *candidate.start;
  s.contacts = detect_contacts(scene, s.pose).contacts;
  return s;
}

bool reaches_target(const SceneGeometry& scene, const Candidate& candidate,
                    const MotionOutcome& outcome) {
  // (try_hypothesis writes a candidate's crossing as signature_text of the signature it wants)
  return outcome.feasible && crossing_text(scene, outcome.contacts) == candidate.crossing;
}

std::string crossing_text(const SceneGeometry& scene, const std::vector<PointContact>& contacts) {
  return signature_text(scene, region_signature(contacts));
}

MotionOutcome replay_candidate(const SceneGeometry& scene, const State& state,
                               const Candidate& candidate, const MotionObserver& observer) {
  const State from = candidate_start(scene, state, candidate);
  MotionCounters counters;
  MotionOutcome last;
  const std::vector<MotionVariant> variants = motion_variants();
  const Candidate::Run& run = candidate.run;
  // every kind of plan (GeneratorOptions::complete_search): the first two are the same
  for (const Hypothesis& h : hypothesise_ln(scene, from.contacts, true)) {
    if (!(h.cf == candidate.cf)) continue;
    const size_t plans = h.plan_options.size();
    MotionStarts starts(scene, from, h);
    auto replay = [&](const MotionStart& start, size_t p, size_t v) {
      MotionOutcome o = run_transition_motion(scene, start.pose, start.contacts, h.plan_options[p],
                                              h.cf, variants[v], counters, observer);
      o.motion = start.prefix + o.motion;
      return o;
    };
    if (run.known()) {
      // The very motion the generator reported.
      if (static_cast<size_t>(run.start) >= starts.size() ||
          static_cast<size_t>(run.plan) >= plans ||
          static_cast<size_t>(run.variant) >= variants.size())
        break;
      const MotionStart& start = starts.at(run.start, counters);
      if (!start.ok) break;
      return replay(start, run.plan, run.variant);
    }
    // A graph that does not say which (older JSON): the first motion of the reported name.
    for (size_t k = 0; k < starts.size(); ++k) {
      const MotionStart& start = starts.at(k, counters);
      if (!start.ok) continue;
      for (size_t p = 0; p < plans; ++p)
        for (size_t v = 0; v < variants.size(); ++v) {
          if (!variant_matters(variants[v], h.plan_options[p], start.contacts)) continue;
          MotionOutcome dry = run_transition_motion(scene, start.pose, start.contacts,
                                                    h.plan_options[p], h.cf, variants[v], counters);
          if (start.prefix + dry.motion == candidate.motion) return replay(start, p, v);
        }
    }
  }
  last.reason = "no motion of this candidate could be replayed";
  return last;
}

}  // namespace pcsg
