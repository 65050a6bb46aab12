#pragma once
// The main thread's side of `pcsg figures`: draws every event of the figure pipeline as it
// arrives and writes the files of one scene into its folder:
//   apart.png                     the objects apart, every face and edge named (Fig. 5a, 7a)
//   states/state-NN.png           every valid state with its CF and contacts (Fig. 5b, 7b)
//   states.png                    the grid of all valid states (Fig. 8)
//   diagram.png, diagram.dot      the graph as a diagram of state pictures (Fig. 6)
//   graph.json, graph.dot         the graph (engine/generator/graph_io.h)
//   transitions/<from>-<cf>/      frame-NNNN.png, contact_sheet.png, frames.json per candidate
//                                 (-c<candidate> after it for a second candidate of that name)
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/render/figure_pipeline.h"
#include "render/framed_scene.h"
#include "render/scene_renderer.h"
#include "render/state_diagram.h"
#include "render/text_painter.h"
#include "render/transition_json.h"

namespace pcsg::app {

struct FigureWriterOptions {
  std::string folder;  // where the scene's files go (created)
  render::Camera camera;
  int picture_width = 1280, picture_height = 960;  // states/state-NN.png, apart.png
  render::StatePictureOptions thumbnail;           // diagram nodes and grid cells
  render::TransitionFrameStyle frame;              // transition frames
  int sheet_cell_width = 400;                      // frames in a contact sheet
  bool states = true, diagram = true, transitions = true;
  // every candidate's motion is drawn: at the end, transitions/ keeps only this run's folders
  // (a run into a used folder would otherwise keep an older graph's transitions)
  bool every_transition = false;
  bool motion_labels = true;
};

struct FigureSummary {
  std::size_t states = 0, links = 0, candidates = 0, feasible = 0;
  int transitions = 0, frames = 0;   // drawn
  std::vector<std::string> skipped;  // candidates whose motion could not be replayed, and why
  // Transitions whose replay ended otherwise than the generation's motion (feasible against
  // failed, or the reverse): the frames do not show what the graph says.
  std::vector<std::string> disagreeing;
  double generation_seconds = 0;
  GenerationProgress progress;  // the last reported
  bool finished = false;
  std::vector<std::string> figures;  // files written that a reader looks at first
};

class FigureWriter {
 public:
  FigureWriter(const SceneGeometry& scene, const FigureWriterOptions& options);
  ~FigureWriter();
  // apart.png; before the stream starts.
  void draw_apart();
  void consume(FigureEvent& event);
  const FigureSummary& summary() const { return summary_; }
  const std::string& folder() const { return options_.folder; }

 private:
  void on(StateFound& e);
  // states/state-NN.png of state s (its id); the picture.
  render::Image draw_state(const State& s);
  void redraw_renumbered_states(const StateGraph& g);
  // Transitions whose start or end state was renumbered by the final merge (as for the
  // states' pictures): moved to the folder of their final ids, their frames' headers, contact
  // sheet and frames.json written again with those ids (the 3D views, read back from the
  // frames, are kept: they do not show ids).
  void renumber_transitions(const StateGraph& g);
  // With every_transition: removes the folders under transitions/ this run did not write.
  void remove_stale_transitions();
  // A transition's contact sheet (of `cells`, the views at the sheet's cell width) and
  // frames.json, into `folder`.
  void write_transition_summary(const std::string& folder, const render::TransitionRecord& r,
                                const std::vector<render::Image>& cells);
  // A transition's folder: "<from>-<target CF>", or with "-c<candidate index>" after it when
  // an earlier candidate (in `owners`, by index) has that name (two candidates from one state
  // toward one CF: a retry from another witness).
  std::string transition_folder(const render::TransitionInfo& info, int index,
                                std::map<std::string, int>& owners) const;
  void on(CandidateTried& e);
  void on(GenerationProgress& e) { summary_.progress = e; }
  void on(GraphFinished& e);
  void on(TransitionStarted& e);
  void on(TransitionFrameReady& e);
  void on(TransitionFinished& e);
  void on(TransitionSkipped& e);
  std::string path(const std::string& relative) const;

  const SceneGeometry& scene_;
  FigureWriterOptions options_;
  std::unique_ptr<render::SceneRenderer> renderer_;
  render::TextPainter text_;
  // the transition being drawn, with a renderer framed on all its poses (render/framed_scene.h)
  TransitionStarted current_;
  std::unique_ptr<SceneGeometry> current_scene_;
  std::unique_ptr<render::SceneRenderer> current_renderer_;
  std::string current_folder_;
  std::vector<render::Image> sheet_frames_;
  std::vector<MotionFrame> sheet_meta_;
  std::vector<std::vector<render::ContactRole>> current_roles_;
  FigureSummary summary_;
  bool seed_written_ = false;
  std::vector<State> drawn_;  // the state each states/state-NN.png shows, by NN
  // every transition drawn, as written (for renumber_transitions)
  struct DrawnTransition {
    int index = -1;  // the candidate's
    std::string folder;
    render::TransitionRecord record;  // with the ids streamed when it was drawn
    std::vector<int> ordinals;        // the frames' file numbers
    int view_height = 0;              // of the 3D view under each frame's header
  };
  std::vector<DrawnTransition> transitions_;
  std::vector<int> current_ordinals_;
  std::map<std::string, int> folder_owners_;  // transition_folder's names, as streamed
  int current_view_height_ = 0;
};

}  // namespace pcsg::app
