#pragma once
// The threads of `pcsg figures`: a producer (the generator, or a stored graph read back)
// streams graph events; a replay thread re-runs the candidate transition motions that are to
// be drawn (replay_candidate), gives every contact its role over the whole motion, picks the
// frames to draw and streams them; the calling (main) thread owns the GL context and draws
// every event as it arrives. Queues between the stages are bounded and blocking: the stages
// run concurrently, memory stays small, and no event or frame is dropped.
#include <functional>
#include <optional>
#include <set>
#include <variant>

#include "app/render/graph_event_stream.h"
#include "render/contact_roles.h"
#include "render/transition_frame.h"

namespace pcsg::app {

// A candidate's motion is about to be drawn: `frames` frames follow, then TransitionFinished.
struct TransitionStarted {
  int index = -1;  // the candidate's index
  render::TransitionInfo info;
  std::vector<PointContact> start;  // the start state's contacts
  int frames = 0;
  int replayed_steps = 0;           // frames the replay produced (before the stride)
  bool generated_feasible = false;  // the generator's verdict
  bool replay_reached = false;      // the replay's: it reached the target with its crossing
                                    // signs (info.feasible, shown in the header)
  std::vector<Pose> poses;          // A's pose at every frame drawn: one framing for the sequence
};
struct TransitionFrameReady {
  int index = -1;
  int ordinal = 0;  // 0 .. frames-1
  MotionFrame frame;
  std::vector<render::ContactRole> roles;
};
struct TransitionFinished {
  int index = -1;
};
// The replay of a candidate threw: its motion is not drawn (the other figures are).
struct TransitionSkipped {
  int index = -1;
  std::string why;
};
using FigureEvent =
    std::variant<StateFound, CandidateTried, GenerationProgress, GraphFinished, TransitionStarted,
                 TransitionFrameReady, TransitionFinished, TransitionSkipped>;

struct PipelineOptions {
  GeneratorOptions generator;
  bool transitions = true;   // replay and draw candidate motions
  bool failed_only = false;  // only the candidates that failed
  std::set<int> candidates;  // only these candidate indices (empty: all)
  int stride = 0;            // draw every stride-th motion step (0: from max_frames)
  int max_frames = 8;        // with stride 0: about this many frames per motion
  std::size_t queue_capacity = 16;
};

// The frames of a replayed motion to draw: every stride-th, every event, the collision and
// the last. Pure, for tests.
std::vector<int> select_frames(const std::vector<MotionFrame>& frames, int stride, int max_frames);

// Generates the graph of `scene` (or, with `stored`, streams that graph instead), replays the
// selected candidates, and calls `consume` on the calling thread for every event, in order.
// Returns when everything is consumed; rethrows the first error of any stage (the others are
// stopped first).
void run_figure_pipeline(const SceneGeometry& scene, const std::optional<StateGraph>& stored,
                         const PipelineOptions& options,
                         const std::function<void(FigureEvent&)>& consume);

}  // namespace pcsg::app
