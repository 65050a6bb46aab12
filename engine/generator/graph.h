#pragma once
// The point-contact state graph (paper Section II-D, III): states <CF, witness>, the links
// between neighbouring states, and every candidate transition that was tried.
#include <optional>
#include <string>
#include <vector>

#include "engine/contact/contact_formation.h"

namespace pcsg {

struct State {
  int id = -1;
  ContactFormation cf;
  Pose pose;                           // the witness configuration X_BA
  std::vector<PointContact> contacts;  // its exact contacts, re-detected at `pose`
  bool seed = false;
  int depth = 0;  // BFS depth from its seed
};

enum class LinkKind { LN, GN };

struct Link {
  int from = -1, to = -1;
  LinkKind kind = LinkKind::LN;  // LN: card(to) <= card(from); GN: the reverse of an LN
  std::string motion;            // "slidingA", "slidingB", "rotation", "combined", ...
};

// One hypothesised LN CF of a state and the outcome of trying to reach it.
struct Candidate {
  int from = -1;
  ContactFormation cf;
  bool feasible = false;
  int to = -1;         // the state reached, when feasible
  std::string motion;  // the motion that worked, or the last one tried
  std::string reason;  // for failures: what collided or what went wrong, where
  int steps = 0;       // motion steps taken in the motion reported
  int attempts = 0;    // motions tried
  // When the CF has e-e-cross contacts: the crossing signs the transition must arrive with
  // (region_signature, state_identity.h), e.g. "eA-eB +"; each sign is its own candidate.
  std::string crossing;
  // The witness of `from` the motion started from, when it is not the state's own (the
  // retries start from other witnesses of the same region); replays start there too.
  std::optional<Pose> start;
  // Which of the hypothesis's motions `motion` is (try_hypothesis): the index of its start
  // (the witness, or one turned about a normal), its plan and its variant (motion_variants()).
  // Several share a name; replays re-run exactly this one. -1 when unknown (older graphs).
  struct Run {
    int start = -1, plan = -1, variant = -1;
    bool known() const { return start >= 0 && plan >= 0 && variant >= 0; }
  } run;
};

struct GraphStats {
  double seconds = 0;
  long collision_queries = 0;  // contact/collision detections at a pose
  long pair_solves = 0;        // exact element-pair solves
  long motion_steps = 0;
  // With GeneratorOptions::measure_discretisation: the largest residual of a kept contact and
  // the deepest penetration, both at the midpoints of accepted motion steps (before
  // re-projection), over the whole run; and the largest witness contact residual.
  double max_keep_drift = 0;
  double max_step_penetration = 0;
  double max_witness_residual = 0;
  // The collision queries by the part of the generator that asked them, in a fixed order
  // (generator.cc, kPhaseNames); they sum to collision_queries.
  std::vector<std::pair<std::string, long>> queries_by_phase;
  // The wall time by the same phases, in the same order: the time each phase ran on the
  // generator's own thread. Work its worker threads ran ahead counts in the phase that was
  // running then (the motions' probes run beside the motions and count there), so this says
  // where the run's seconds went, and queries_by_phase what each phase asked for. Sums to
  // `seconds`.
  std::vector<std::pair<std::string, double>> seconds_by_phase;
};

struct StateGraph {
  std::string scene;
  std::vector<State> states;
  std::vector<Link> links;
  std::vector<Candidate> candidates;
  GraphStats stats;
};

}  // namespace pcsg
