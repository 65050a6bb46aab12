#include "app/render/figure_writer.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "engine/core/error.h"
#include "engine/generator/graph_io.h"
#include "render/canvas.h"
#include "render/contact_sheet.h"
#include "render/png_writer.h"
#include "render/transition_json.h"

namespace pcsg::app {

namespace {

namespace fs = std::filesystem;

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  if (!f) throw Error("cannot write '" + path + "'");
  f << text;
}

std::string two_digits(int i) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d", i);
  return buf;
}

}  // namespace

FigureWriter::FigureWriter(const SceneGeometry& scene, const FigureWriterOptions& options)
    : scene_(scene), options_(options) {
  fs::create_directories(options_.folder);
  if (options_.states) fs::create_directories(path("states"));
  renderer_ = std::make_unique<render::SceneRenderer>(scene_);
  options_.thumbnail.camera = options_.camera;
  options_.frame.camera = options_.camera;
}

FigureWriter::~FigureWriter() = default;

std::string FigureWriter::path(const std::string& relative) const {
  return (fs::path(options_.folder) / relative).string();
}

void FigureWriter::draw_apart() {
  render::FrameRequest f;
  f.width = options_.picture_width;
  f.height = options_.picture_height;
  f.camera = options_.camera;
  f.title = scene_.spec.name;
  f.subtitle = "objects apart";
  render::write_png_fast(renderer_->render(f), path("apart.png"));
  summary_.figures.push_back(path("apart.png"));
}

void FigureWriter::consume(FigureEvent& event) {
  std::visit([&](auto& e) { on(e); }, event);
}

render::Image FigureWriter::draw_state(const State& s) {
  render::StatePictureOptions big;
  big.width = options_.picture_width;
  big.height = options_.picture_height;
  big.camera = options_.camera;
  big.labels = true;
  big.header = true;
  const render::Image picture = renderer_->render(render::state_frame_request(scene_, s, big));
  render::write_png_fast(picture, path("states/state-" + two_digits(s.id) + ".png"));
  return picture;
}

void FigureWriter::on(StateFound& e) {
  // each state's own picture, framed on it; the diagram's and the grid's thumbnails are drawn
  // at the end, framed alike on all states
  const State& s = e.state;
  if (!options_.states) return;
  const render::Image picture = draw_state(s);
  if (static_cast<int>(drawn_.size()) <= s.id) drawn_.resize(s.id + 1);
  drawn_[s.id] = s;
  if (s.seed && !seed_written_) {  // the first seed: the paper's Fig. 5b / 7b
    seed_written_ = true;
    render::write_png_fast(picture, path("seed.png"));
    summary_.figures.push_back(path("seed.png"));
  }
}

void FigureWriter::redraw_renumbered_states(const StateGraph& g) {
  // States that the generator proved one region are merged when it ends and the rest
  // renumbered (generator.h): a picture drawn under an id that now names another state is
  // drawn again, and those beyond the last id are removed.
  for (const State& s : g.states) {
    const size_t i = static_cast<size_t>(s.id);
    if (i < drawn_.size() && drawn_[i].cf == s.cf && drawn_[i].pose.position == s.pose.position &&
        drawn_[i].pose.quaternion.coeffs() == s.pose.quaternion.coeffs())
      continue;
    draw_state(s);
  }
  for (size_t i = g.states.size(); i < drawn_.size(); ++i)
    fs::remove(path("states/state-" + two_digits(static_cast<int>(i)) + ".png"));
  drawn_.resize(g.states.size());
}

std::string FigureWriter::transition_folder(const render::TransitionInfo& info, int index,
                                            std::map<std::string, int>& owners) const {
  const std::string slug = render::transition_slug(info);
  const auto [it, first] = owners.emplace(slug, index);
  return path("transitions/" +
              (first || it->second == index ? slug : slug + "-c" + std::to_string(index)));
}

void FigureWriter::renumber_transitions(const StateGraph& g) {
  struct Move {
    DrawnTransition* d;
    std::string folder;
    bool redraw;  // the ids changed, not only the folder's name
  };
  std::vector<Move> moves;
  std::map<std::string, int> owners;
  for (DrawnTransition& d : transitions_) {  // in the candidates' order, as streamed
    if (d.index < 0 || d.index >= static_cast<int>(g.candidates.size())) continue;
    const Candidate& c = g.candidates[d.index];
    render::TransitionInfo& info = d.record.info;
    // info.to is the candidate's target as streamed (replay_and_stream), whatever the replay's
    // outcome: a feasible candidate whose replay fails still names its state, renumbered too.
    const int to = c.to;
    const bool renumbered = c.from != info.from || to != info.to;
    info.from = c.from;
    info.to = to;
    const std::string folder = transition_folder(info, d.index, owners);
    if (renumbered || folder != d.folder) moves.push_back({&d, folder, renumbered});
  }
  // Out of the way first: a folder's new name may be another's old one.
  for (Move& m : moves) {
    const std::string staging = path("transitions/.renumbering-" + std::to_string(m.d->index));
    fs::remove_all(staging);
    fs::rename(m.d->folder, staging);
    m.d->folder = staging;
  }
  for (Move& m : moves) {
    DrawnTransition& d = *m.d;
    fs::remove_all(m.folder);
    if (!m.redraw) {
      fs::rename(d.folder, m.folder);
      d.folder = m.folder;
      continue;
    }
    const render::TransitionRecord& r = d.record;
    fs::create_directories(m.folder);
    std::vector<render::Image> cells;
    for (size_t k = 0; k < d.ordinals.size(); ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame-%04d.png", d.ordinals[k]);
      const render::Image old = render::read_png((fs::path(d.folder) / name).string());
      const int top = old.height - d.view_height;
      if (top < 0)
        throw Error("transition frame '" + std::string(name) + "' is shorter than its view");
      const render::Image view = render::cropped(old, 0, top, old.width, d.view_height);
      render::write_png_fast(
          render::add_transition_header(view, scene_, r.info, r.frames[k], r.start, r.roles[k],
                                        text_, k + 1 == d.ordinals.size()),
          (fs::path(m.folder) / name).string());
      const int h = view.height * options_.sheet_cell_width / view.width;
      cells.push_back(render::resized(view, options_.sheet_cell_width, std::max(1, h)));
    }
    write_transition_summary(m.folder, r, cells);
    fs::remove_all(d.folder);
    d.folder = m.folder;
  }
}

void FigureWriter::write_transition_summary(const std::string& folder,
                                            const render::TransitionRecord& r,
                                            const std::vector<render::Image>& cells) {
  if (!cells.empty())  // the cells already have the sheet's cell width: no second resize
    render::write_png_fast(
        render::transition_contact_sheet(r.info, cells, r.frames, r.roles, r.start, scene_,
                                         options_.sheet_cell_width, text_),
        (fs::path(folder) / "contact_sheet.png").string());
  write_text((fs::path(folder) / "frames.json").string(), render::transition_to_json(r, scene_));
}

void FigureWriter::remove_stale_transitions() {
  const fs::path top = path("transitions");
  if (!fs::is_directory(top)) return;
  std::set<fs::path> written;
  for (const DrawnTransition& d : transitions_) written.insert(fs::path(d.folder).filename());
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(top))
    if (entry.is_directory() && written.count(entry.path().filename()) == 0)
      stale.push_back(entry.path());
  for (const fs::path& p : stale) fs::remove_all(p);
}

void FigureWriter::on(CandidateTried& e) {
  ++summary_.candidates;
  summary_.feasible += e.candidate.feasible;
}

void FigureWriter::on(TransitionStarted& e) {
  if (e.generated_feasible != e.replay_reached)
    summary_.disagreeing.push_back(
        "candidate " + std::to_string(e.index) + " from " + std::to_string(e.info.from) + " to " +
        e.info.target_cf + " (" + e.info.motion + "): " +
        (e.generated_feasible
             ? "feasible in the generation, the replay did not reach it: " + e.info.reason
             : "failed in the generation, the replay arrived"));
  current_ = e;
  current_folder_ = transition_folder(e.info, e.index, folder_owners_);
  fs::create_directories(current_folder_);
  // a sequence written again (a second run into the same folder) must not keep old frames
  for (const auto& entry : fs::directory_iterator(current_folder_))
    if (entry.path().filename().string().rfind("frame-", 0) == 0) fs::remove(entry.path());
  sheet_frames_.clear();
  sheet_meta_.clear();
  current_roles_.clear();
  current_ordinals_.clear();
  // one framing for the whole sequence: the animation does not jitter
  current_renderer_.reset();
  current_scene_ = std::make_unique<SceneGeometry>(
      render::framed_scene(scene_, render::extent_of_A(scene_, e.poses)));
  current_renderer_ = std::make_unique<render::SceneRenderer>(*current_scene_);
}

void FigureWriter::on(TransitionFrameReady& e) {
  const render::Image view =
      render::draw_transition_view(*current_renderer_, *current_scene_, current_.info, e.frame,
                                   current_.start, e.roles, options_.frame);
  const render::Image frame =
      render::add_transition_header(view, scene_, current_.info, e.frame, current_.start, e.roles,
                                    text_, e.ordinal + 1 == current_.frames);
  char name[32];
  std::snprintf(name, sizeof name, "frame-%04d.png", e.ordinal);
  render::write_png_fast(frame, (fs::path(current_folder_) / name).string());
  const int h = view.height * options_.sheet_cell_width / view.width;
  sheet_frames_.push_back(render::resized(view, options_.sheet_cell_width, std::max(1, h)));
  sheet_meta_.push_back(std::move(e.frame));
  current_roles_.push_back(std::move(e.roles));
  current_ordinals_.push_back(e.ordinal);
  current_view_height_ = view.height;
  ++summary_.frames;
}

void FigureWriter::on(TransitionFinished& e) {
  (void)e;
  render::TransitionRecord record{current_.info, current_.start, std::move(sheet_meta_),
                                  std::move(current_roles_)};
  write_transition_summary(current_folder_, record, sheet_frames_);
  transitions_.push_back({current_.index, current_folder_, std::move(record),
                          std::move(current_ordinals_), current_view_height_});
  current_ordinals_.clear();
  sheet_frames_.clear();
  sheet_meta_.clear();
  current_roles_.clear();
  current_renderer_.reset();
  current_scene_.reset();
  ++summary_.transitions;
}

void FigureWriter::on(TransitionSkipped& e) {
  summary_.skipped.push_back("candidate " + std::to_string(e.index) + ": " + e.why);
}

void FigureWriter::on(GraphFinished& e) {
  const StateGraph& g = e.graph;
  summary_.states = g.states.size();
  summary_.links = g.links.size();
  summary_.generation_seconds = g.stats.seconds;
  summary_.finished = true;
  write_text(path("graph.json"), graph_to_json(g, scene_));
  write_text(path("graph.dot"), graph_to_dot(g, scene_));
  if (options_.states) redraw_renumbered_states(g);
  renumber_transitions(g);
  if (options_.transitions && options_.every_transition) remove_stale_transitions();
  // the thumbnails of the diagram and the grid, all framed alike
  std::vector<render::Image> pictures;
  if (options_.diagram || options_.states)
    pictures = render::draw_state_thumbnails(scene_, g.states, options_.thumbnail);
  if (options_.diagram && !g.states.empty()) {
    render::StateDiagramOptions d;
    d.motion_labels = options_.motion_labels;
    const render::Diagram diagram = render::draw_state_diagram(g, scene_, pictures, d, text_);
    render::write_png_fast(diagram.image, path("diagram.png"));
    write_text(path("diagram.dot"), diagram.dot);
    summary_.figures.push_back(path("diagram.png"));
  }
  if (options_.states && !g.states.empty()) {
    std::vector<render::SheetCell> cells;
    for (std::size_t i = 0; i < g.states.size(); ++i)
      cells.push_back({pictures[i], render::state_caption(g.states[i], scene_), false, g.states[i].seed});
    render::SheetOptions o;
    o.title = g.scene;
    o.subtitle = std::to_string(g.states.size()) + " valid point-contact states";
    render::write_png_fast(render::compose_contact_sheet(cells, o, text_), path("states.png"));
    summary_.figures.push_back(path("states.png"));
  }
}

}  // namespace pcsg::app
