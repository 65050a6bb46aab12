// pcsg figures [--out DIR] [--scene FILE]... [--graph GRAPH.json] [--only WHAT]... [options]
// The paper's figures (Tang & Xiao 2006, Fig. 5-8) from scenes/example1.yaml and
// scenes/example2.yaml, or the same set of pictures for any scene: the objects apart, every
// valid state, the graph as a diagram of state pictures, and every candidate transition
// motion as a PNG sequence with a contact sheet. The generator runs on a worker thread and a
// replay thread re-runs the candidates' motions while this (main) thread draws their events
// as they arrive (app/render/figure_pipeline.h).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/command.h"
#include "app/render/figure_writer.h"
#include "engine/core/error.h"
#include "engine/scene/scene.h"
#include "render/graph_json_reader.h"

namespace pcsg::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kMaxImageSide = 8192;  // as `pcsg render`: far above any figure
// Progress is redrawn at most this often: a line per frame would flood a log.
constexpr double kProgressSeconds = 0.25;

// Which paper figure each example's pictures are.
struct PaperFigures {
  const char* stem;
  const char *apart, *seed, *graph;
  bool graph_is_diagram;  // Fig. 6 is the LN graph; Fig. 8 a grid of states
};
constexpr PaperFigures kPaper[] = {{"example1", "fig5a", "fig5b", "fig6", true},
                                   {"example2", "fig7a", "fig7b", "fig8", false}};

struct Args {
  std::string out = "out", graph, size = "640x480", thumb = "300x240", camera;
  std::vector<std::string> scenes, only;
  std::vector<int> candidates;
  bool failed_only = false, no_motion_labels = false, quiet = false;
  int stride = 0, max_frames = 8, threads = 1;
};

void parse_size(const std::string& option, const std::string& text, int* w, int* h) {
  char x = 0;
  std::string rest;
  std::istringstream in(text);
  if (!(in >> *w >> x >> *h) || (x != 'x' && x != 'X') || (in >> rest) || *w < 64 || *h < 64 ||
      *w > kMaxImageSide || *h > kMaxImageSide) {
    throw UsageError(option + " \"" + text + "\": expected WIDTHxHEIGHT, each 64.." +
                     std::to_string(kMaxImageSide) + ", e.g. 640x480");
  }
}

// scenes/<name> of the working folder, else of the source tree this pcsg was built from.
std::string example_scene(const std::string& name) {
  const fs::path local = fs::path("scenes") / name;
  if (fs::exists(local)) return local.string();
  const fs::path source = fs::path(PCSG_SOURCE_DIR) / "scenes" / name;
  if (fs::exists(source)) return source.string();
  throw UsageError("cannot find scenes/" + name + " (run from the pcsg folder or give --scene)");
}

// One line on stderr, rewritten in place.
class Progress {
 public:
  Progress(bool enabled, std::string name, bool generating)
      : enabled_(enabled), generating_(generating), name_(std::move(name)) {}
  void update(const FigureSummary& s, bool force = false) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (!force && std::chrono::duration<double>(now - last_).count() < kProgressSeconds) return;
    last_ = now;
    const double t = std::chrono::duration<double>(now - start_).count();
    std::string stage;
    if (!generating_) {
      stage = "stored graph";
    } else if (s.finished) {
      stage = "generated";
    } else if (!s.progress.phase.empty()) {
      stage = "generating: " + s.progress.phase + ", " + std::to_string(s.progress.done) + "/" +
              std::to_string(s.progress.total) + ", " + std::to_string(s.progress.states) +
              " states";
    } else {
      stage = "generating: level " + std::to_string(s.progress.level) + ", candidate " +
              std::to_string(s.progress.done) + "/" + std::to_string(s.progress.total) + ", " +
              std::to_string(s.progress.states) + " states";
    }
    std::fprintf(stderr, "\r[%s] %s | %zu candidates seen, %d motions and %d frames drawn | %.0f s   ",
                 name_.c_str(), stage.c_str(), s.candidates, s.transitions, s.frames, t);
    std::fflush(stderr);
  }
  void finish(const FigureSummary& s) {
    update(s, true);
    if (enabled_) std::fprintf(stderr, "\n");
  }

 private:
  bool enabled_, generating_;
  std::string name_;
  Clock::time_point start_ = Clock::now(), last_{};
};

void run_scene(const Args& a, const std::string& scene_file, const std::string& folder,
               const PaperFigures* paper) {
  const auto t0 = Clock::now();
  const SceneGeometry scene = build_scene_geometry(load_scene_file(scene_file));
  std::optional<StateGraph> stored;
  if (!a.graph.empty()) stored = render::read_graph_json(a.graph, scene);

  const bool all = a.only.empty();
  auto wants = [&](const char* what) { return all || std::find(a.only.begin(), a.only.end(), what) != a.only.end(); };
  FigureWriterOptions w;
  w.folder = folder;
  if (!a.camera.empty()) w.camera = render::parse_camera(a.camera);
  parse_size("--size", a.size, &w.frame.width, &w.frame.height);
  parse_size("--thumb", a.thumb, &w.thumbnail.width, &w.thumbnail.height);
  w.states = wants("states");
  w.diagram = wants("diagram");
  w.transitions = wants("transitions");
  w.motion_labels = !a.no_motion_labels;
  w.every_transition = !a.failed_only && a.candidates.empty();
  PipelineOptions p;
  p.generator.threads = a.threads;
  p.transitions = w.transitions;
  p.failed_only = a.failed_only;
  p.candidates.insert(a.candidates.begin(), a.candidates.end());
  p.stride = a.stride;
  p.max_frames = a.max_frames;

  FigureWriter writer(scene, w);
  if (w.states) writer.draw_apart();
  Progress progress(!a.quiet, fs::path(folder).filename().string(), !stored);
  run_figure_pipeline(scene, stored, p, [&](FigureEvent& e) {
    writer.consume(e);
    progress.update(writer.summary());
  });
  progress.finish(writer.summary());

  // the paper's figure names, next to the scenes' folders
  if (paper != nullptr) {
    const fs::path top = fs::path(folder).parent_path();
    auto copy = [&](const char* from, const char* figure) {
      const fs::path src = fs::path(folder) / from;
      if (fs::exists(src))
        fs::copy_file(src, top / (std::string(figure) + ".png"), fs::copy_options::overwrite_existing);
    };
    copy("apart.png", paper->apart);
    copy("seed.png", paper->seed);
    copy(paper->graph_is_diagram ? "diagram.png" : "states.png", paper->graph);
  }
  const FigureSummary& s = writer.summary();
  const double total = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("%s: %zu states, %zu links, %zu candidates (%zu feasible); drew %d transitions "
              "(%d frames); %s %.1f s, total %.1f s -> %s/\n",
              scene.spec.name.c_str(), s.states, s.links, s.candidates, s.feasible, s.transitions,
              s.frames, stored ? "graph read from file; its generation took" : "generation",
              s.generation_seconds, total, folder.c_str());
  for (const std::string& why : s.skipped)
    std::printf("  not drawn (its replay failed): %s\n", why.c_str());
  for (const std::string& why : s.disagreeing)
    std::printf("  replay differs from the generation: %s\n", why.c_str());
  std::fflush(stdout);
}

void run(const Args& a) {
  const auto t0 = Clock::now();
  for (const std::string& o : a.only)
    if (o != "states" && o != "diagram" && o != "transitions")
      throw UsageError("--only " + o + ": expected states, diagram or transitions");
  if (a.stride < 0) throw UsageError("--stride must be >= 0");
  if (a.max_frames < 1) throw UsageError("--max-frames must be >= 1");
  std::vector<std::string> scenes = a.scenes;
  if (scenes.empty()) {
    if (!a.graph.empty()) throw UsageError("--graph needs --scene (the scene it was generated from)");
    scenes = {example_scene("example1.yaml"), example_scene("example2.yaml")};
  }
  if (!a.graph.empty() && scenes.size() != 1) throw UsageError("--graph takes exactly one --scene");
  for (const std::string& file : scenes) {
    const std::string stem = fs::path(file).stem().string();
    const PaperFigures* paper = nullptr;
    for (const PaperFigures& p : kPaper)
      if (stem == p.stem) paper = &p;
    run_scene(a, file, (fs::path(a.out) / stem).string(), paper);
  }
  std::printf("figures: %zu scene%s in %.1f s; the paper's figures are %s/fig*.png\n",
              scenes.size(), scenes.size() == 1 ? "" : "s",
              std::chrono::duration<double>(Clock::now() - t0).count(), a.out.c_str());
}

void setup(CLI::App& cli) {
  auto a = std::make_shared<Args>();
  CLI::App* cmd = cli.add_subcommand(
      "figures", "Draw the paper's figures: states, graph diagrams and transition motions");
  cmd->add_option("-o,--out", a->out, "Output folder (one subfolder per scene)")->capture_default_str();
  cmd->add_option("--scene", a->scenes,
                  "Scene file (repeatable; default: scenes/example1.yaml and example2.yaml)");
  cmd->add_option("--graph", a->graph,
                  "Draw this graph.json (from `pcsg generate`) instead of generating; needs --scene");
  cmd->add_option("--only", a->only, "Only these: states, diagram, transitions (repeatable)")
      ->delimiter(',');
  cmd->add_flag("--failed-only", a->failed_only, "Draw only the failed candidates' motions");
  cmd->add_option("--candidate", a->candidates,
                  "Draw only these candidates' motions (index in graph.json, repeatable)");
  cmd->add_option("--stride", a->stride, "Draw every N-th motion step (default: from --max-frames)");
  cmd->add_option("--max-frames", a->max_frames,
                  "With no --stride: about this many frames per motion (events always drawn)")
      ->capture_default_str();
  cmd->add_option("--size", a->size, "Transition frame size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--thumb", a->thumb, "State picture size in diagrams and grids")->capture_default_str();
  cmd->add_option("--camera", a->camera, "\"azimuth elevation zoom\" (default \"-60 20 1\")");
  cmd->add_flag("--no-motion-labels", a->no_motion_labels, "Leave the motion names off the diagram's links");
  cmd->add_option("-j,--threads", a->threads, "Generator worker threads")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", a->quiet, "No progress line on stderr");
  cmd->callback([a] { run(*a); });
}

}  // namespace

PCSG_REGISTER_COMMAND(50, setup);

}  // namespace pcsg::app
