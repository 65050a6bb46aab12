// pcsg bench [--repeat N] [--scene FILE ...]: how fast pcsg is, beside the paper's figures.
// Per scene, the median wall time of generating the graph (paper Section IV: 11.272 s and
// 27.364 s on a Pentium 4, 2.8 GHz); then the throughput of the pieces a motion step is made
// of: collision queries (detect_contacts), exact contact solves (solve_pair) and, when built
// with the renderer, frames of 1280x960 per second. Each scene runs in a child process of its
// own, so that its peak memory is its own (issue 5's target: under 200 MB).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/command.h"
#include "app/progress_line.h"
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
  bool quick = false;     // GeneratorOptions::complete_search off
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
  double peak_mb = 0;  // the largest resident set of the runs (VmHWM)
};

// What the first scene's child measures besides its runs.
struct Throughput {
  double queries_per_s = 0, solves_per_s = 0;
  std::string fps;
  size_t witnesses = 0;
};

// The process's peak resident set so far, in MB (VmHWM of /proc/self/status); 0 if unknown.
double peak_resident_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0;
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The throughput of the pieces, at poses where the generator spends its time.
Throughput measure_throughput(const SceneGeometry& scene, const StateGraph& graph,
                              double min_seconds) {
  if (graph.states.empty())
    throw Error("pcsg bench: " + scene.spec.name + " gave no states: nothing to measure at");
  Throughput out;
  out.witnesses = graph.states.size();
  const std::vector<Pose> poses = poses_near_witnesses(scene, graph);
  detect_contacts(scene, poses.front());  // builds the cached collision models first
  // every query a fresh detection: the same poses each round would otherwise be recalled
  DetectOptions fresh;
  fresh.recall = false;
  out.queries_per_s = per_second(min_seconds, [&] {
    for (const Pose& p : poses) detect_contacts(scene, p, fresh);
    return static_cast<long>(poses.size());
  });
  long solves_per_round = 0;
  for (const State& s : graph.states) solves_per_round += s.contacts.size();
  out.solves_per_s = solves_per_round == 0 ? 0 : per_second(min_seconds, [&] {
    long n = 0;
    for (const State& s : graph.states) {
      // one motion step away from the witness, started from the witness's contact points
      const Pose Y = s.pose.displaced(scene.tol.motion_step * Eigen::Vector3d::UnitX(),
                                      Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
      for (const PointContact& c : s.contacts) {
        solve_pair(scene, Y, c.a, c.b, c.type, c.p_A, c.p_B);
        ++n;
      }
    }
    return n;
  });
  out.fps = "not built (PCSG_WITH_RENDER=OFF)";
#ifdef PCSG_WITH_RENDER
  try {
    render::SceneRenderer renderer(scene);
    render::FrameRequest f;
    f.title = scene.spec.name;
    f.X_BA = graph.states.front().pose;
    f.contacts = graph.states.front().contacts;
    f.subtitle = graph.states.front().cf.str(scene);
    renderer.render(f);  // warm-up: targets, shaders
    out.fps = fmt("%.1f", per_second(min_seconds, [&] {
                    renderer.render(f);
                    return 1L;
                  }));
  } catch (const Error& e) {
    out.fps = std::string("unavailable: ") + e.what();
  }
#endif
  return out;
}

// One scene's runs (and, for the first scene, the throughput), written to `out` as lines of
// "key value" for the parent to read: the child's own peak memory is then the scene's.
void bench_scene(const Args& a, const std::string& path, bool first, std::ostream& out) {
  const SceneGeometry scene = build_scene_geometry(load_scene_file(path));
  GeneratorOptions opt;
  opt.threads = a.threads;
  opt.complete_search = !a.quick;
  StateGraph first_graph;
  out << "name " << scene.spec.name << "\n";
  for (int i = 0; i < a.repeat; ++i) {
    ProgressLine progress("pcsg bench: " + std::filesystem::path(path).filename().string() +
                          ", run " + std::to_string(i + 1) + "/" + std::to_string(a.repeat));
    StateGraph g = generate_graph(scene, opt, &progress);
    out << "seconds " << fmt("%.17g", g.stats.seconds) << "\n";
    out << "states " << g.states.size() << "\n";
    out << "queries " << g.stats.collision_queries << "\n";
    if (i == 0) first_graph = std::move(g);
  }
  out << "peak_mb " << fmt("%.17g", peak_resident_mb()) << "\n";
  if (!first) return;
  std::fprintf(stderr, "\rpcsg bench: throughput on %s%30s\n", scene.spec.name.c_str(), "");
  const Throughput t = measure_throughput(scene, first_graph, a.seconds);
  out << "witnesses " << t.witnesses << "\n";
  out << "queries_per_s " << fmt("%.17g", t.queries_per_s) << "\n";
  out << "solves_per_s " << fmt("%.17g", t.solves_per_s) << "\n";
  out << "fps " << t.fps << "\n";
}

// Runs bench_scene in a child process and reads what it wrote; throws what the child threw.
std::string run_in_child(const Args& a, const std::string& path, bool first) {
  int fds[2];
  if (pipe(fds) != 0) throw Error("pcsg bench: cannot create a pipe");
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw Error("pcsg bench: cannot fork");
  if (pid == 0) {
    close(fds[0]);
    std::ostringstream out;
    int code = 0;
    try {
      bench_scene(a, path, first, out);
    } catch (const std::exception& e) {
      out << "error " << e.what() << "\n";
      code = 1;
    }
    const std::string text = out.str();
    for (size_t done = 0; done < text.size();) {
      const ssize_t n = write(fds[1], text.data() + done, text.size() - done);
      if (n <= 0) break;
      done += static_cast<size_t>(n);
    }
    close(fds[1]);
    std::fflush(nullptr);
    _exit(code);
  }
  close(fds[1]);
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) text.append(buf, n);
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  const size_t err = text.rfind("\nerror ");
  if (err != std::string::npos || text.rfind("error ", 0) == 0) {
    std::string what = text.substr(err == std::string::npos ? 6 : err + 7);
    if (!what.empty() && what.back() == '\n') what.pop_back();
    throw Error(what);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error("pcsg bench: the run of " + path + " ended abnormally");
  return text;
}

void run(Args a) {
  if (a.scenes.empty())
    a.scenes = {std::string(PCSG_SOURCE_DIR) + "/scenes/example1.yaml",
                std::string(PCSG_SOURCE_DIR) + "/scenes/example2.yaml"};
  // a bad file fails here, in this process, with its own message, before any run
  for (const std::string& path : a.scenes) load_scene_file(path);
  std::vector<SceneResult> results;
  Throughput t;
  std::string first_name;
  for (size_t i = 0; i < a.scenes.size(); ++i) {
    const std::string& path = a.scenes[i];
    std::istringstream in(run_in_child(a, path, i == 0));
    SceneResult r;
    r.path = path;
    r.paper = paper_seconds(path);
    std::map<std::string, std::vector<std::string>> said;  // key -> values, in order
    for (std::string key; in >> key;) {
      std::string rest;
      std::getline(in, rest);
      said[key].push_back(rest.empty() ? rest : rest.substr(1));
    }
    auto last = [&](const char* key) { return said[key].empty() ? "0" : said[key].back(); };
    for (const std::string& v : said["seconds"]) r.seconds.push_back(std::stod(v));
    r.name = last("name");
    r.states = std::stoi(last("states"));
    r.queries = std::stol(last("queries"));
    r.peak_mb = std::stod(last("peak_mb"));
    if (i == 0) {
      t.witnesses = std::stoul(last("witnesses"));
      t.queries_per_s = std::stod(last("queries_per_s"));
      t.solves_per_s = std::stod(last("solves_per_s"));
      t.fps = last("fps");
    }
    if (r.seconds.empty()) throw Error("pcsg bench: no run of " + path + " was reported");
    if (i == 0) first_name = r.name;
    results.push_back(r);
  }

  std::printf(
      "Graph generation, %s search, wall time of generate_graph (median of %d run%s, %d "
      "thread%s):\n\n",
      a.quick ? "quick" : "complete", a.repeat, a.repeat == 1 ? "" : "s", a.threads,
      a.threads == 1 ? "" : "s");
  std::printf(
      "| scene | states | collision queries | median (s) | min (s) | max (s) | paper, "
      "Pentium 4 2.8 GHz (s) | paper / ours | peak memory (MB) |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const SceneResult& r : results) {
    const double med = median(r.seconds);
    std::printf("| %s | %d | %ld | %.3f | %.3f | %.3f | %s | %s | %.0f |\n", r.name.c_str(),
                r.states, r.queries, med, *std::min_element(r.seconds.begin(), r.seconds.end()),
                *std::max_element(r.seconds.begin(), r.seconds.end()),
                r.paper > 0 ? fmt("%.3f", r.paper).c_str() : "-",
                r.paper > 0 ? fmt("%.1fx", r.paper / med).c_str() : "-", r.peak_mb);
  }
  std::printf(
      "\nThroughput on %s (one thread, at and one motion step around its %zu "
      "witnesses):\n\n| measure | per second |\n|---|---:|\n",
      first_name.c_str(), t.witnesses);
  std::printf("| collision queries (detect_contacts: mesh candidates + exact solves) | %.0f |\n",
              t.queries_per_s);
  std::printf("| exact contact solves (solve_pair from the previous contact points) | %.0f |\n",
              t.solves_per_s);
  std::printf("| rendered frames, 1280x960, 4x MSAA, labels | %s |\n", t.fps.c_str());
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
  cmd->add_flag("--quick", args->quick,
                "Time the quick search (as `pcsg generate --quick`) instead of the complete one");
  cmd->callback([args] { run(*args); });
}

PCSG_REGISTER_COMMAND(70, setup);

}  // namespace
}  // namespace pcsg::app
