#include "engine/generator/generator.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>
#include <thread>

#include "engine/generator/hypothesis.h"

namespace pcsg {

std::vector<MotionVariant> motion_variants() {
  return {
      {true, 0.0, false},         // slidingA / slidingB, least-norm separation
      {true, 0.0, true},          // the same with separation by rotation
      {false, 0.0, false},        // combined sliding
      {false, M_PI / 4, false},   // combined, other paths on the face
      {false, -M_PI / 4, false},
  };
}

namespace {

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

struct TryResult {
  Candidate candidate;
  MotionOutcome outcome;
  MotionCounters counters;
  std::vector<Discovery> discovered;  // higher-cardinality states met by failed motions
};

// Whether a variant differs from an earlier one for this plan (turns only matter when a contact
// slides toward a lower-dimensional element; the separation style only with removals).
bool variant_matters(const MotionVariant& v, const std::vector<ContactPlan>& plan) {
  bool approach = false, removes = false;
  for (const ContactPlan& p : plan) {
    if (p.action == ContactAction::Remove) removes = true;
    if (p.action == ContactAction::Change) approach = true;
  }
  if (v.turn != 0 && !approach) return false;
  if (v.remove_by_rotation && !removes) return false;
  if (!v.fix_unchanged_side && !approach) return false;
  return true;
}

// Plans that differ only by which of several identical contacts changes are the same up to
// that choice; trying two of them covers asymmetric situations without trying all.
constexpr size_t kMaxPlansPerHypothesis = 2;

TryResult try_hypothesis(const SceneGeometry& scene, const State& s, const Hypothesis& h,
                         bool measure) {
  TryResult r;
  r.counters.measure = measure;
  r.candidate.from = s.id;
  r.candidate.cf = h.cf;
  std::string reasons;
  const size_t plans = std::min(h.plan_options.size(), kMaxPlansPerHypothesis);
  for (size_t p = 0; p < plans; ++p)
    for (const MotionVariant& v : motion_variants()) {
      if (!variant_matters(v, h.plan_options[p])) continue;
      ++r.candidate.attempts;
      MotionOutcome o = run_transition_motion(scene, s.pose, s.contacts, h.plan_options[p], h.cf,
                                              v, r.counters);
      r.candidate.motion = o.motion;
      r.candidate.steps = o.steps;
      if (o.discovered) r.discovered.push_back(*o.discovered);
      if (o.feasible) {
        r.candidate.feasible = true;
        r.outcome = std::move(o);
        return r;
      }
      if (!reasons.empty()) reasons += "; ";
      reasons += o.motion + ": " + o.reason;
      r.outcome = std::move(o);
    }
  r.candidate.reason = reasons;
  return r;
}

// An upward probe of a state: a push toward a point (pivot < 0) or a turn about an axis
// through the point of contact `pivot`.
struct Probe {
  int state;
  int pivot;
  Eigen::Vector3d vector;
};

class Builder {
 public:
  Builder(const SceneGeometry& scene, const GeneratorOptions& options,
          GeneratorListener* listener, const std::atomic<bool>* cancel)
      : scene_(scene), options_(options), listener_(listener), cancel_(cancel) {
    graph_.scene = scene.spec.name;
  }

  StateGraph run();

 private:
  bool cancelled() const { return cancel_ && cancel_->load(); }
  // The state of this CF whose region holds `pose`, or -1.
  int find_state(const ContactFormation& cf, const Pose& pose);
  int add_state(const ContactFormation& cf, const Pose& pose,
                const std::vector<PointContact>& contacts, bool seed, int depth);
  void grow(int seed_id);
  void add_link(int from, int to, const std::string& motion);
  // Where the upward probes of a state push A's centre: toward each element of B that none
  // of its contacts touches (a face's interior point, an edge's middle, a vertex).
  std::vector<Eigen::Vector3d> probe_goals(const State& s) const;

  const SceneGeometry& scene_;
  GeneratorOptions options_;
  GeneratorListener* listener_;
  const std::atomic<bool>* cancel_;
  StateGraph graph_;
  MotionCounters counters_;
  std::map<std::pair<int, int>, bool> linked_;
  // States of higher cardinality met by motions from state `from`, in merge order.
  std::vector<std::pair<int, Discovery>> discoveries_;
};

int Builder::find_state(const ContactFormation& cf, const Pose& pose) {
  for (const State& s : graph_.states) {
    if (!(s.cf == cf)) continue;
    if (connected_within_cf(scene_, s.pose, pose, cf, counters_) ||
        connected_within_cf(scene_, pose, s.pose, cf, counters_))
      return s.id;
  }
  return -1;
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
  if (listener_) listener_->on_state(graph_, graph_.states.back());
  return s.id;
}

void Builder::add_link(int from, int to, const std::string& motion) {
  if (from == to || linked_[{from, to}]) return;
  linked_[{from, to}] = true;
  graph_.links.push_back({from, to, LinkKind::LN, motion});
  // The reverse of an LN transition that drops cardinality is a GN link (Section II-D).
  if (graph_.states[to].cf.cardinality() < graph_.states[from].cf.cardinality()) {
    graph_.links.push_back({to, from, LinkKind::GN, motion});
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

void Builder::grow(int seed_id) {
  std::vector<int> frontier = {seed_id};
  int level = 0;
  while (!frontier.empty() && !cancelled()) {
    // Every hypothesis of every state on this level, in a fixed order.
    std::vector<std::pair<int, Hypothesis>> jobs;
    for (int id : frontier)
      for (Hypothesis& h : hypothesise_ln(scene_, graph_.states[id].contacts))
        jobs.emplace_back(id, std::move(h));
    // And the upward probes of each state: toward every element of B it does not touch.
    std::vector<Probe> probes;
    if (options_.probe_upward)
      for (int id : frontier) {
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
    std::vector<std::optional<Discovery>> probed(probes.size());
    std::vector<MotionCounters> probe_counters(probes.size());
    std::atomic<size_t> next{0};
    auto worker = [&] {
      for (size_t j; (j = next.fetch_add(1)) < jobs.size() + probes.size();) {
        if (cancelled()) break;
        if (j < jobs.size()) {
          results[j] = try_hypothesis(scene_, graph_.states[jobs[j].first], jobs[j].second,
                                      options_.measure_discretisation);
        } else {
          const Probe& p = probes[j - jobs.size()];
          const State& st = graph_.states[p.state];
          probed[j - jobs.size()] =
              p.pivot < 0 ? probe_for_contact(scene_, st.pose, st.contacts, p.vector,
                                              probe_counters[j - jobs.size()])
                          : probe_by_rotation(scene_, st.pose, st.contacts, p.pivot, p.vector,
                                              probe_counters[j - jobs.size()]);
        }
      }
    };
    const int threads =
        std::max(1, std::min<int>(options_.threads, jobs.size() + probes.size()));
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (cancelled()) break;

    // Merge in job order: deterministic whatever the thread count.
    std::vector<int> next_frontier;
    for (size_t j = 0; j < jobs.size(); ++j) {
      TryResult& r = results[j];
      counters_.merge(r.counters);
      Candidate& c = r.candidate;
      if (c.feasible) {
        int to = find_state(c.cf, r.outcome.end);
        if (to < 0 && static_cast<int>(graph_.states.size()) < options_.max_states) {
          to = add_state(c.cf, r.outcome.end, r.outcome.contacts, false,
                         graph_.states[c.from].depth + 1);
          next_frontier.push_back(to);
        }
        c.to = to;
        if (to >= 0) add_link(c.from, to, c.motion);
      }
      for (Discovery& d : r.discovered)
        if (adds_one_contact(graph_.states[c.from].cf, d.cf))
          discoveries_.push_back({c.from, std::move(d)});
      graph_.candidates.push_back(c);
      if (listener_) {
        listener_->on_candidate(graph_, graph_.candidates.back());
        listener_->on_progress(graph_, level, static_cast<int>(j + 1),
                               static_cast<int>(jobs.size()));
      }
    }
    for (size_t k = 0; k < probes.size(); ++k) {
      counters_.merge(probe_counters[k]);
      if (probed[k] && adds_one_contact(graph_.states[probes[k].state].cf, probed[k]->cf))
        discoveries_.push_back({probes[k].state, std::move(*probed[k])});
    }
    frontier = std::move(next_frontier);
    ++level;
  }
}

StateGraph Builder::run() {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<SeedCandidate> seeds;
  if (scene_.spec.auto_seeds) {
    seeds = find_seed_candidates(scene_, counters_, options_.threads);
  } else {
    for (const SeedSpec& s : scene_.spec.seeds) seeds.push_back(seed_from_pose(scene_, s, counters_));
  }
  // Highest cardinality first: a local maximum's LN graph covers the states below it, so later
  // candidates already in the graph add nothing (Section IV: one seed per local maximum).
  for (const SeedCandidate& sc : seeds) {
    if (cancelled()) break;
    // An automatic candidate whose CF the graph already has adds a seed only for a separate
    // region, and a failed connectivity motion does not prove one; it is left out (a CF that
    // is new to the graph always seeds). Listed seeds are checked for connectivity.
    if (scene_.spec.auto_seeds &&
        std::any_of(graph_.states.begin(), graph_.states.end(),
                    [&](const State& s) { return s.cf == sc.cf; }))
      continue;
    const int existing = find_state(sc.cf, sc.pose);
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
  for (size_t k = 0; k < discoveries_.size() && !cancelled(); ++k) {
    const auto [from, d] = discoveries_[k];
    if (static_cast<int>(graph_.states.size()) >= options_.max_states) break;
    int id = find_state(d.cf, d.pose);
    if (id < 0) {
      id = add_state(d.cf, d.pose, d.contacts, true, 0);
      grow(id);
    }
    // The met state is `from` plus one contact: removing it (the reverse of the motion that
    // met it) leads back down to `from`, an LN transition.
    add_link(id, from, "separation (reverse of a motion from state " + std::to_string(from) + ")");
  }

  graph_.stats.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  graph_.stats.collision_queries = counters_.detections;
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

MotionOutcome replay_candidate(const SceneGeometry& scene, const State& from,
                               const Candidate& candidate, const MotionObserver& observer) {
  MotionCounters counters;
  MotionOutcome last;
  for (const Hypothesis& h : hypothesise_ln(scene, from.contacts)) {
    if (!(h.cf == candidate.cf)) continue;
    const size_t plans = std::min(h.plan_options.size(), kMaxPlansPerHypothesis);
    for (size_t p = 0; p < plans; ++p)
      for (const MotionVariant& v : motion_variants()) {
        if (!variant_matters(v, h.plan_options[p])) continue;
        // Replay only the motion the candidate reports (its last or successful one).
        MotionOutcome dry = run_transition_motion(scene, from.pose, from.contacts,
                                                  h.plan_options[p], h.cf, v, counters);
        if (dry.motion != candidate.motion) continue;
        return run_transition_motion(scene, from.pose, from.contacts, h.plan_options[p], h.cf,
                                     v, counters, observer);
      }
  }
  last.reason = "no motion of this candidate could be replayed";
  return last;
}

}  // namespace pcsg
