// pcsg generate SCENE [-o DIR] [--threads N] [--no-project-upward] [--region-samples]: the
// point-contact state graph of a scene.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "app/command.h"
#include "app/progress_line.h"
#include "engine/core/error.h"
#include "engine/generator/generator.h"
#include "engine/generator/graph_io.h"
#include "engine/scene/scene.h"

namespace pcsg::app {
namespace {

void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  if (!f) throw Error("cannot write " + p.string());
  f << text;
}

// "phase P%, ..." for the phases' shares of `total`, largest first, each with its seconds when
// they are seconds (T floating); phases without a share left out (below a millisecond: nothing
// to look for).
template <typename T>
std::string phase_shares(std::vector<std::pair<std::string, T>> by_phase, T total) {
  constexpr bool seconds = std::is_floating_point_v<T>;
  std::stable_sort(by_phase.begin(), by_phase.end(),
                   [](const auto& x, const auto& y) { return x.second > y.second; });
  std::string out;
  for (const auto& [phase, amount] : by_phase) {
    if (seconds ? amount < 1e-3 : amount == 0) continue;
    char buf[112];
    std::snprintf(buf, sizeof buf, "%s%s %.0f%%", out.empty() ? "" : ", ", phase.c_str(),
                  100.0 * static_cast<double>(amount) /
                      std::max(static_cast<double>(total), seconds ? 1e-9 : 1.0));
    out += buf;
    if (seconds) {
      std::snprintf(buf, sizeof buf, " (%.2f s)", static_cast<double>(amount));
      out += buf;
    }
  }
  return out;
}

struct Args {
  std::string scene;
  std::string out = "out";
  // Every core by default: the graph does not depend on the number (GeneratorOptions).
  int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 256u));
  bool quiet = false;
  bool no_project_upward = false;
  bool no_mirror_images = false;
  bool quick = false;
  bool region_samples = false;
  bool complete = false;  // the default since session 47; still accepted
};

void run(const Args& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const SceneSpec spec = load_scene_file(a.scene);
  const SceneGeometry scene = build_scene_geometry(spec);
  GeneratorOptions opt;
  opt.threads = a.threads;
  opt.project_upward = !a.no_project_upward;
  opt.mirror_images = !a.no_mirror_images;
  opt.complete_search = !a.quick;
  opt.region_samples = a.region_samples;
  ProgressLine progress("pcsg generate", !a.quiet);
  const StateGraph g = generate_graph(scene, opt, &progress);
  progress.finish();
  std::filesystem::create_directories(a.out);
  write_file(std::filesystem::path(a.out) / "graph.json", graph_to_json(g, scene));
  write_file(std::filesystem::path(a.out) / "graph.dot", graph_to_dot(g, scene));
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  int feasible = 0;
  for (const Candidate& c : g.candidates) feasible += c.feasible;
  std::printf("%s: %zu states, %zu links, %zu candidates tried (%d feasible), %ld collision "
              "queries, %.3f s (generation %.3f s)\n",
              spec.name.c_str(), g.states.size(), g.links.size(), g.candidates.size(), feasible,
              g.stats.collision_queries, total, g.stats.seconds);
  // where the queries and the time went: the generator's phases, largest share first
  std::printf("  collision queries by phase: %s\n",
              phase_shares(g.stats.queries_by_phase, g.stats.collision_queries).c_str());
  std::printf("  time by phase: %s\n",
              phase_shares(g.stats.seconds_by_phase, g.stats.seconds).c_str());
  for (const State& s : g.states)
    std::printf("  state %d%s: %s\n", s.id, s.seed ? " (seed)" : "", s.cf.str(scene).c_str());
  std::printf("wrote %s/graph.json and %s/graph.dot\n", a.out.c_str(), a.out.c_str());
}

void setup(CLI::App& cli) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = cli.add_subcommand("generate", "Generate the point-contact state graph of a scene");
  cmd->add_option("scene", args->scene, "Scene file (YAML)")->required();
  cmd->add_option("-o,--out", args->out, "Output directory for graph.json and graph.dot")
      ->capture_default_str();
  cmd->add_option("-j,--threads", args->threads, "Worker threads (results do not depend on it)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line on stderr");
  cmd->add_flag("--no-project-upward", args->no_project_upward,
                "Leave out the search for the states one contact above each state by "
                "projecting turned witnesses (GeneratorOptions::project_upward): faster, and "
                "Example 1 then lacks its 3-contact state");
  cmd->add_flag("--no-mirror-images", args->no_mirror_images,
                "Leave out the mirror images of the states that no state's region holds "
                "(GeneratorOptions::mirror_images)");
  CLI::Option* quick = cmd->add_flag("--quick", args->quick,
                "Try only the quick search's motions, each hypothesis's first two plans "
                "(GeneratorOptions::complete_search off): about 1.7 times fewer collision "
                "queries on Example 2, which then lacks 4 of its 33 CFs");
  cmd->add_flag("--region-samples", args->region_samples,
                "Retry the hypotheses toward CFs a state is not linked to also from 30 samples "
                "of its region around its witness (GeneratorOptions::region_samples): the needle "
                "in the dish gains 2 links at twice its queries, Example 2 nothing at 1.47 times");
  cmd->add_flag("--complete", args->complete,
                "The complete search (the default): where the quick search's motions reach no "
                "target, every kind of plan, settling wherever the new region ends and the "
                "normal drive off an edge")
      ->excludes(quick);
  cmd->callback([args] { run(*args); });
}

PCSG_REGISTER_COMMAND(30, setup);

}  // namespace
}  // namespace pcsg::app
