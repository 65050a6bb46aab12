#include "app/render/figure_pipeline.h"

#include <algorithm>
#include <thread>

namespace pcsg::app {

namespace {

// A changing contact may move this many motion steps between two recorded frames and still
// be followed across its change of elements (events are located within one step).
constexpr double kMatchSteps = 5;

// A stored graph, streamed as the generator would: its states, then its candidates. The
// states' contacts are re-detected at their witnesses: a replay needs their exact local data,
// which graph.json does not keep.
void stream_stored(const SceneGeometry& scene, StateGraph graph, BoundedQueue<GraphEvent>& queue,
                   std::atomic<bool>& cancel, std::exception_ptr& error) {
  try {
    for (State& s : graph.states) {
      const ContactReport rep = detect_contacts(scene, s.pose);
      if (ContactFormation::of(rep.contacts) == s.cf) s.contacts = rep.contacts;
    }
    GraphEventStream stream(queue, cancel);
    for (const State& s : graph.states) {
      if (cancel) break;
      stream.on_state(graph, s);
    }
    for (const Candidate& c : graph.candidates) {
      if (cancel) break;
      stream.on_candidate(graph, c);
    }
    if (!cancel) stream.push(GraphFinished{std::move(graph)});
  } catch (...) {
    error = std::current_exception();
  }
  queue.close();
}

bool wanted(const CandidateTried& c, const PipelineOptions& o) {
  if (!o.transitions) return false;
  if (o.failed_only && c.candidate.feasible) return false;
  return o.candidates.empty() || o.candidates.count(c.index) > 0;
}

// Replays one candidate and streams its frames; false when the consumer has stopped.
bool replay_and_stream(const SceneGeometry& scene, const CandidateTried& c,
                       const PipelineOptions& o, BoundedQueue<FigureEvent>& out) {
  std::vector<MotionFrame> frames;
  // (the state at the witness the motion started from: a retry's is another of its witnesses)
  const State from = candidate_start(scene, c.from, c.candidate);
  const MotionOutcome outcome = replay_candidate(
      scene, c.from, c.candidate, [&](const MotionFrame& f) { frames.push_back(f); });
  // a motion that stops because a kept contact left its elements reports its last frame as a
  // "collision" without elements (default ids): keep only the elements there are
  for (MotionFrame& f : frames) {
    auto invalid = [](const ElementId& e) { return e.index < 0; };
    std::erase_if(f.collided_a, invalid);
    std::erase_if(f.collided_b, invalid);
  }
  std::vector<std::vector<PointContact>> contacts;
  for (const MotionFrame& f : frames) contacts.push_back(f.contacts);
  const bool failed_at_last = !frames.empty() && frames.back().phase == "collision";
  const auto roles = render::assign_contact_roles(
      from.contacts, contacts, c.candidate.cf, kMatchSteps * scene.tol.motion_step, failed_at_last);
  const std::vector<int> chosen = select_frames(frames, o.stride, o.max_frames);

  TransitionStarted start;
  start.index = c.index;
  start.info.from = c.candidate.from;
  start.info.from_cf = c.from.cf.str(scene);
  start.info.target_cf = c.candidate.cf.str(scene);
  start.info.motion = outcome.motion.empty() ? c.candidate.motion : outcome.motion;
  // Feasible as the generator judges it: a motion that arrives with the other crossing signs
  // fails this candidate (reaches_target).
  start.replay_reached = reaches_target(scene, c.candidate, outcome);
  start.info.feasible = start.replay_reached;
  start.info.to = c.candidate.to;
  start.info.reason = outcome.reason;
  if (outcome.feasible && !start.replay_reached)
    start.info.reason = "arrives with the crossing " + crossing_text(scene, outcome.contacts) +
                        ", not " + c.candidate.crossing;
  start.info.steps = outcome.steps;
  start.start = from.contacts;
  start.frames = static_cast<int>(chosen.size());
  start.replayed_steps = static_cast<int>(frames.size());
  start.generated_feasible = c.candidate.feasible;
  for (int i : chosen) start.poses.push_back(frames[i].pose);
  if (!out.push(std::move(start))) return false;
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const int i = chosen[k];
    if (!out.push(TransitionFrameReady{c.index, static_cast<int>(k), std::move(frames[i]), roles[i]}))
      return false;
  }
  return out.push(TransitionFinished{c.index});
}

}  // namespace

std::vector<int> select_frames(const std::vector<MotionFrame>& frames, int stride, int max_frames) {
  std::vector<int> out;
  const int n = static_cast<int>(frames.size());
  if (n == 0) return out;
  if (stride <= 0) stride = std::max(1, (n + std::max(1, max_frames) - 1) / std::max(1, max_frames));
  for (int i = 0; i < n; ++i) {
    const std::string& phase = frames[i].phase;
    // events, collisions and the end are what a reader looks for: never skipped
    if (i % stride == 0 || i == n - 1 || phase == "event" || phase == "collision" || phase == "done")
      out.push_back(i);
  }
  return out;
}

void run_figure_pipeline(const SceneGeometry& scene, const std::optional<StateGraph>& stored,
                         const PipelineOptions& options,
                         const std::function<void(FigureEvent&)>& consume) {
  BoundedQueue<GraphEvent> graph_events(options.queue_capacity);
  BoundedQueue<FigureEvent> figure_events(options.queue_capacity);
  std::atomic<bool> cancel{false};
  std::exception_ptr producer_error, replay_error;

  std::thread producer([&] {
    if (stored) {
      stream_stored(scene, *stored, graph_events, cancel, producer_error);
    } else {
      stream_generation(scene, options.generator, graph_events, cancel, producer_error);
    }
  });
  // the replay stage: forwards graph events, and after each wanted candidate its frames
  std::thread replayer([&] {
    try {
      while (std::optional<GraphEvent> e = graph_events.pop()) {
        bool ok = true;
        if (auto* c = std::get_if<CandidateTried>(&*e); c != nullptr && wanted(*c, options)) {
          const CandidateTried candidate = *c;
          ok = figure_events.push(std::move(*c));
          // a motion that cannot be replayed costs its pictures, not the other figures
          try {
            ok = ok && replay_and_stream(scene, candidate, options, figure_events);
          } catch (const std::exception& x) {
            ok = figure_events.push(TransitionSkipped{candidate.index, x.what()});
          }
        } else {
          ok = std::visit([&](auto&& v) { return figure_events.push(std::move(v)); }, *e);
        }
        if (!ok) break;  // the consumer stopped
      }
    } catch (...) {
      replay_error = std::current_exception();
    }
    // stop the producer too (a no-op when it has finished) and end the consumer's stream
    cancel = cancel || replay_error != nullptr;
    graph_events.close();
    figure_events.close();
  });

  std::exception_ptr consumer_error;
  try {
    while (std::optional<FigureEvent> e = figure_events.pop()) consume(*e);
  } catch (...) {
    consumer_error = std::current_exception();
    cancel = true;
    figure_events.close();
    graph_events.close();
  }
  replayer.join();
  producer.join();
  if (consumer_error) std::rethrow_exception(consumer_error);
  if (producer_error) std::rethrow_exception(producer_error);
  if (replay_error) std::rethrow_exception(replay_error);
}

}  // namespace pcsg::app
