#pragma once
// The generator's events as a stream for another thread (MuJoCo's split: the computation on a
// worker thread, drawing on the main one). GeneratorListener callbacks run on the generator's
// thread and must not draw; GraphEventStream copies what they report into a bounded queue,
// blocking the generator while the queue is full, so that no event is lost however slow the
// consumer is. Header-only (engine types only), so that tests/app can check it directly.
#include <atomic>
#include <exception>
#include <string>
#include <variant>

#include "app/render/bounded_queue.h"
#include "engine/generator/generator.h"

namespace pcsg::app {

struct StateFound {
  State state;
};
struct CandidateTried {
  int index = -1;  // in the order the generator reports them (= StateGraph::candidates)
  Candidate candidate;
  State from;  // the state it starts from, with its exact contacts
};
struct GenerationProgress {
  int level = 0, done = 0, total = 0;
  std::size_t states = 0, links = 0;
  std::string phase;  // a phase after the BFS levels (then `done` counts its steps), or empty
};
struct GraphFinished {
  StateGraph graph;
};
using GraphEvent = std::variant<StateFound, CandidateTried, GenerationProgress, GraphFinished>;

class GraphEventStream final : public GeneratorListener {
 public:
  // When the consumer has closed the queue, `cancel` is raised so that the generator stops.
  GraphEventStream(BoundedQueue<GraphEvent>& queue, std::atomic<bool>& cancel)
      : queue_(queue), cancel_(cancel) {}

  void on_state(const StateGraph& graph, const State& state) override {
    (void)graph;
    push(StateFound{state});
  }
  void on_candidate(const StateGraph& graph, const Candidate& candidate) override {
    CandidateTried e{candidates_++, candidate, {}};
    if (candidate.from >= 0 && candidate.from < static_cast<int>(graph.states.size()))
      e.from = graph.states[candidate.from];
    push(std::move(e));
  }
  void on_progress(const StateGraph& graph, int level, int done, int total) override {
    push(GenerationProgress{level, done, total, graph.states.size(), graph.links.size(), {}});
  }
  void on_phase_progress(const StateGraph& graph, const std::string& phase, int done,
                         int total) override {
    push(GenerationProgress{0, done, total, graph.states.size(), graph.links.size(), phase});
  }
  void push(GraphEvent event) {
    if (!queue_.push(std::move(event))) cancel_ = true;
  }

 private:
  BoundedQueue<GraphEvent>& queue_;
  std::atomic<bool>& cancel_;
  int candidates_ = 0;
};

// Runs the generator on the calling thread (meant to be a worker), streaming its events and
// then the finished graph, and closes the queue: the consumer sees the end of the stream.
// An exception is stored in `error` for the consumer's thread to rethrow.
inline void stream_generation(const SceneGeometry& scene, const GeneratorOptions& options,
                              BoundedQueue<GraphEvent>& queue, std::atomic<bool>& cancel,
                              std::exception_ptr& error) {
  try {
    GraphEventStream stream(queue, cancel);
    StateGraph graph = generate_graph(scene, options, &stream, &cancel);
    if (!cancel) stream.push(GraphFinished{std::move(graph)});
  } catch (...) {
    error = std::current_exception();
  }
  queue.close();
}

}  // namespace pcsg::app
