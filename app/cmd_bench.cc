// pcsg bench [--repeat N] [--scene FILE ...]: how fast pcsg is, beside the paper's figures.
// Per scene, the median wall time of generating the graph (paper Section IV: 11.272 s and
// 27.364 s on a Pentium 4, 2.8 GHz); then the throughput of the pieces a motion step is made
// of: collision queries (detect_contacts), exact contact solves (solve_pair) and, when built
// with the renderer, frames of 1280x960 per second.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "app/command.h"
#include "engine/contact/contact.h"
#include "engine/core/error.h"
#include "engine/generator/generator.h"
#include "engine/scene/scene.h"

#ifdef PCSG_WITH_RENDER
#include "render/scene_renderer.h"
#endif

namespace pcsg::app {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Args {
  std::vector<std::string> scenes;
  int repeat = 3;
  int threads = 1;
  double seconds = 1.0;  // minimum time of each throughput measurement
};

// The paper's running times (Section IV), by the shipped scenes' file names.
double paper_seconds(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  if (name == "example1.yaml") return 11.272;
  if (name == "example2.yaml") return 27.364;
  return 0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Poses near the witnesses, as a motion step sees them: each witness, and each displaced by
// one motion step along a fixed set of twists (translations and rotations about A's centre).
std::vector<Pose> poses_near_witnesses(const SceneGeometry& scene, const StateGraph& g) {
  std::vector<Pose> out;
  const double h = scene.tol.motion_step;
  const double size = std::max(scene.A.bbox.diagonal().norm() / 2, h);
  for (const State& s : g.states) {
    out.push_back(s.pose);
    const Eigen::Vector3d c = s.pose.apply(scene.A.bbox.center());
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
      out.push_back(s.pose.displaced(h * e, Eigen::Vector3d::Zero(), c));
      out.push_back(s.pose.displaced(Eigen::Vector3d::Zero(), (h / size) * e, c));
    }
  }
  return out;
}

// Calls `op` over and over for at least `min_seconds`; returns calls per second.
template <class Op>
double per_second(double min_seconds, Op op) {
  long calls = 0;
  const auto t0 = Clock::now();
  double t = 0;
  do {
    calls += op();
    t = seconds_since(t0);
  } while (t < min_seconds);
  return calls / t;
}

struct SceneResult {
  std::string name, path;
  int states = 0;
  long queries = 0;
  std::vector<double> seconds;
  double paper = 0;
};

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

void run(Args a) {
  if (a.scenes.empty())
    a.scenes = {std::string(PCSG_SOURCE_DIR) + "/scenes/example1.yaml",
                std::string(PCSG_SOURCE_DIR) + "/scenes/example2.yaml"};
  std::vector<SceneResult> results;
  std::unique_ptr<SceneGeometry> first;  // the first scene, for the throughput measurements
  StateGraph first_graph;
  for (const std::string& path : a.scenes) {
    auto scene = std::make_unique<SceneGeometry>(build_scene_geometry(load_scene_file(path)));
    SceneResult r{scene->spec.name, path, 0, 0, {}, paper_seconds(path)};
    GeneratorOptions opt;
    opt.threads = a.threads;
    for (int i = 0; i < a.repeat; ++i) {
      std::fprintf(stderr, "\rpcsg bench: %s, run %d/%d   ",
                   std::filesystem::path(path).filename().c_str(), i + 1, a.repeat);
      std::fflush(stderr);
      StateGraph g = generate_graph(*scene, opt);
      r.seconds.push_back(g.stats.seconds);
      r.states = static_cast<int>(g.states.size());
      r.queries = g.stats.collision_queries;
      if (!first) first_graph = std::move(g);
    }
    results.push_back(r);
    if (!first) first = std::move(scene);
  }
  std::fprintf(stderr, "\rpcsg bench: throughput on %s%30s\n", first->spec.name.c_str(), "");
  if (first_graph.states.empty())
    throw Error("pcsg bench: " + a.scenes.front() + " gave no states: nothing to measure at");

  // throughput of the pieces, at poses where the generator spends its time
  const std::vector<Pose> poses = poses_near_witnesses(*first, first_graph);
  detect_contacts(*first, poses.front());  // builds the cached collision models first
  // every query a fresh detection: the same poses each round would otherwise be recalled
  DetectOptions fresh;
  fresh.recall = false;
  const double queries_per_s = per_second(a.seconds, [&] {
    for (const Pose& p : poses) detect_contacts(*first, p, fresh);
    return static_cast<long>(poses.size());
  });
  long solves_per_round = 0;
  for (const State& s : first_graph.states) solves_per_round += s.contacts.size();
  const double solves_per_s = solves_per_round == 0 ? 0 : per_second(a.seconds, [&] {
    long n = 0;
    for (const State& s : first_graph.states) {
      // one motion step away from the witness, started from the witness's contact points
      const Pose Y = s.pose.displaced(first->tol.motion_step * Eigen::Vector3d::UnitX(),
                                      Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
      for (const PointContact& c : s.contacts) {
        solve_pair(*first, Y, c.a, c.b, c.type, c.p_A, c.p_B);
        ++n;
      }
    }
    return n;
  });
  std::string fps = "not built (PCSG_WITH_RENDER=OFF)";
#ifdef PCSG_WITH_RENDER
  try {
    render::SceneRenderer renderer(*first);
    render::FrameRequest f;
    f.title = first->spec.name;
    f.X_BA = first_graph.states.front().pose;
    f.contacts = first_graph.states.front().contacts;
    f.subtitle = first_graph.states.front().cf.str(*first);
    renderer.render(f);  // warm-up: targets, shaders
    fps = fmt("%.1f", per_second(a.seconds, [&] {
      renderer.render(f);
      return 1L;
    }));
  } catch (const Error& e) {
    fps = std::string("unavailable: ") + e.what();
  }
#endif

  std::printf("Graph generation, wall time of generate_graph (median of %d run%s, %d thread%s):\n\n",
              a.repeat, a.repeat == 1 ? "" : "s", a.threads, a.threads == 1 ? "" : "s");
  std::printf("| scene | states | collision queries | median (s) | min (s) | max (s) | paper, "
              "Pentium 4 2.8 GHz (s) | paper / ours |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const SceneResult& r : results) {
    const double med = median(r.seconds);
    std::printf("| %s | %d | %ld | %.3f | %.3f | %.3f | %s | %s |\n", r.name.c_str(), r.states,
                r.queries, med, *std::min_element(r.seconds.begin(), r.seconds.end()),
                *std::max_element(r.seconds.begin(), r.seconds.end()),
                r.paper > 0 ? fmt("%.3f", r.paper).c_str() : "-",
                r.paper > 0 ? fmt("%.1fx", r.paper / med).c_str() : "-");
  }
  std::printf("\nThroughput on %s (one thread, at and one motion step around its %zu "
              "witnesses):\n\n| measure | per second |\n|---|---:|\n",
              first->spec.name.c_str(), first_graph.states.size());
  std::printf("| collision queries (detect_contacts: mesh candidates + exact solves) | %.0f |\n",
              queries_per_s);
  std::printf("| exact contact solves (solve_pair from the previous contact points) | %.0f |\n",
              solves_per_s);
  std::printf("| rendered frames, 1280x960, 4x MSAA, labels | %s |\n", fps.c_str());
}

void setup(CLI::App& cli) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = cli.add_subcommand(
      "bench", "Time graph generation (beside the paper's), collision queries, solves, frames");
  cmd->add_option("--scene", args->scenes,
                  "Scene file(s) to time (default: the paper's examples 1 and 2)");
  cmd->add_option("-n,--repeat", args->repeat, "Generation runs per scene (the median is shown)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("-j,--threads", args->threads, "Worker threads of the generator")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  cmd->add_option("--seconds", args->seconds, "Minimum time of each throughput measurement")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->callback([args] { run(*args); });
}

PCSG_REGISTER_COMMAND(70, setup);

}  // namespace
}  // namespace pcsg::app
