#pragma once
// The point-contact state graph generator (paper Section III): from seed states, grow each
// seed's LN graph breadth-first by hypothesising LN CFs and proving each with a feasible
// compliant transition motion, and merge the seeds' graphs into one.
//
// Deterministic: the candidates of one BFS level are tried in parallel (each is a pure function
// of the scene, the state and the hypothesis) and merged in a fixed order, so 1 or N threads
// give the same graph.
#include <atomic>
#include <string>

#include "engine/generator/graph.h"
#include "engine/generator/seeds.h"

namespace pcsg {

struct GeneratorOptions {
  int threads = 1;
  // Measure the discretisation error of every accepted motion step (at the step's midpoint:
  // drift of the kept contacts and penetration on the exact surfaces); costs one more contact
  // detection per step. Used by `pcsg sweep`.
  bool measure_discretisation = false;
  // Probe upward from every state (push A toward the elements of B it does not touch) to find
  // states of higher cardinality that the seeds' LN graphs do not reach (other local maxima).
  bool probe_upward = true;
  // After the growth, look for states one contact above each state that no motion or probe
  // met: its witness, turned about A's centre in kUpwardTurns ways (generator.cc), projected
  // onto each CF that adds one PtC to the state's and that the graph does not have; each new
  // state found seeds its own LN graph. On by default since session 26: Example 1's
  // {(fA-e1, 2), (fA-f1, 1)} (both hands) and the torus's {(fA-e2, 2), (fA-f2, 1)} are found
  // by nothing else, in every frame and unit tried (since session 21 the moved frames' links
  // agree too); it costs Example 1 about twice the queries, and the three-sphere lens, where
  // it finds nothing, several times its time (docs/paper-comparison.md, sessions 16 and 26).
  bool project_upward = true;
  // When both solids have a plane of mirror symmetry (symmetry.h), add the mirror image of
  // each state's witness that no state's region holds, as a state of its own, and each link's
  // image: a configuration and its mirror image may lie in different regions of one CF
  // (Example 1's ellipsoid across the dish, wall contact left or right of its rim contact).
  bool mirror_images = true;
  // The complete search (the default since session 47; `pcsg generate --quick` turns it off):
  // where the quick search's motions (each hypothesis's first two plans, settling only where
  // the settling contact turns) reach no target, every kind of plan, settling wherever the new
  // region ends within a step, and the normal drive off an edge (MotionVariant); a symmetry
  // image of a state that joins no state becomes a state. Example 2 then holds 33 CFs (29 with
  // the quick search: the lens on one cap across the rim, {(fA1-e1, 2)}, and {(fA1-e1, 1),
  // (fA1-f1, 1)}, with their images) and the same 211 distinct links in its own frame and B
  // moved, where the quick search grows 29 and 27 CFs; Example 1 two more distinct links. It
  // costs Example 2 about 1.7 times the quick search's collision queries. No part of it is
  // enough alone (session 47: without the normal drive or without the other plans Example 2
  // has the 33 CFs but lacks 24 or 4 of the 211 links, at 1.47 and 1.63 times the queries;
  // with the general settling alone 31 CFs; docs/paper-comparison.md, sessions 40 and 47).
  bool complete_search = true;
  // Retry the hypotheses toward a CF the graph has but a state has no link to also from
  // samples of the state's region around its witness (the witness turned about and moved along
  // A's axes, projected onto the CF and joined to it: region_sample in generator.cc), after the
  // other witnesses and the waypoints fail. Off by default (session 55): it adds two real links
  // to the needle in the dish (scenes/stress/needle_in_dish.yaml, 26 to 28; its far frame
  // also 26 to 28, another two) at about twice its queries, and nothing to Example 1 (no query)
  // or Example 2 (the same 49 states and 604 links at 1.47 times the queries).
  bool region_samples = false;
  // Safety bound on the number of states (a valid scene has far fewer).
  int max_states = 2000;
  // Length of one small motion step relative to the scene's length scale; 0 keeps the scene's
  // own (Tolerances::motion_step, 1e-2 L unless changed).
  double motion_step = 0;
};

// Progress and results as they are found. Called from the thread that runs generate_graph, in
// the deterministic merge order.
class GeneratorListener {
 public:
  virtual ~GeneratorListener() = default;
  virtual void on_state(const StateGraph& graph, const State& state) { (void)graph, (void)state; }
  virtual void on_candidate(const StateGraph& graph, const Candidate& candidate) {
    (void)graph, (void)candidate;
  }
  // `done` of `total` candidates of the current BFS level are tried.
  virtual void on_progress(const StateGraph& graph, int level, int done, int total) {
    (void)graph, (void)level, (void)done, (void)total;
  }
  // Progress through a long phase after the BFS levels: its name as in
  // GraphStats::queries_by_phase and the unit counted ("retries from other witnesses
  // (states)", "... (motions run ahead)"): `done` of `total` units.
  virtual void on_phase_progress(const StateGraph& graph, const std::string& phase, int done,
                                 int total) {
    (void)graph, (void)phase, (void)done, (void)total;
  }
};

StateGraph generate_graph(const SceneGeometry& scene, const GeneratorOptions& options = {},
                          GeneratorListener* listener = nullptr,
                          const std::atomic<bool>* cancel = nullptr);

// The motion variants tried, in order, for one hypothesis (paper Section III-C: the preferred
// finite motions first, then combined ones and other directions on faces).
std::vector<MotionVariant> motion_variants();

// The state `from` at the witness the candidate's motion started from (Candidate::start, its
// contacts re-detected there), or `from` itself when it started from the state's own witness
// (its contacts re-detected when they lack their conditions, as a graph read from JSON does).
State candidate_start(const SceneGeometry& scene, const State& from, const Candidate& candidate);

// Whether a motion's outcome reaches the candidate's target as the generator requires: it
// arrives, and with the candidate's crossing signs (Candidate::crossing; a motion that arrives
// with the other signs is a failure of this candidate).
bool reaches_target(const SceneGeometry& scene, const Candidate& candidate,
                    const MotionOutcome& outcome);
// The crossing signs of contacts' e-e-cross pairs as Candidate::crossing writes them
// ("eA-e1 +"; empty without crossings).
std::string crossing_text(const SceneGeometry& scene, const std::vector<PointContact>& contacts);

// Re-runs the motion that a candidate reports (Candidate::run; by its name for a graph without
// it) with an observer, for animations and frame-by-frame debugging. Deterministic.
MotionOutcome replay_candidate(const SceneGeometry& scene, const State& from,
                               const Candidate& candidate, const MotionObserver& observer);

}  // namespace pcsg
