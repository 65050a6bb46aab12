// pcsg sweep SCENE [--out DIR] [--levels F,...] [--vary both|step|mesh]: the generator over a
// range of resolutions (motion step, mesh chordal error), reporting per run the run time, the
// largest contact residual at the witnesses, the drift of kept contacts and the penetration
// along accepted motions, and how the graph differs from the finest run's; as a CSV, a Markdown
// table and a log-log chart of error against run time.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include "app/command.h"
#include "app/progress_line.h"
#include "app/sweep_report.h"
#include "engine/core/error.h"

namespace pcsg::app {
namespace {

struct Args {
  std::string scene;
  std::string out = "sweep";
  // Factors on the default step (1e-2 L) and mesh error (1e-3 L), coarse to fine: five runs
  // whose total time is ~8x one default run (the finest costs ~4x).
  std::vector<double> levels = {4, 2, 1, 0.5, 0.25};
  std::string vary = "both";
  int threads = 1;
  bool quiet = false;
};

void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  if (!f) throw Error("cannot write " + p.string());
  f << text;
}

void run(const Args& a) {
  static const std::map<std::string, SweepVary> kVary = {
      {"both", SweepVary::Both}, {"step", SweepVary::Step}, {"mesh", SweepVary::Mesh}};
  const SceneSpec spec = load_scene_file(a.scene);
  const std::vector<SweepLevel> levels = sweep_levels(a.levels, kVary.at(a.vary));

  SweepReport report;
  report.scene_name = spec.name;
  report.scene_path = a.scene;
  report.threads = a.threads;
  for (size_t i = 0; i < levels.size(); ++i) {
    char run[128];
    std::snprintf(run, sizeof run, "pcsg sweep: run %zu/%zu (step %g L, mesh %g L)", i + 1,
                  levels.size(), levels[i].motion_step, levels[i].mesh_chordal_error);
    ProgressLine progress(run, !a.quiet);
    report.runs.push_back(run_sweep_level(spec, levels[i], a.threads, &progress));
    const SweepRun& r = report.runs.back();
    if (!a.quiet)
      std::fprintf(stderr, "\r%s: %d states, %d links, %.2f s%30s\n", run, r.states, r.links,
                   r.total_seconds(), "");
  }
  // the reference: the finest run (smallest step, then smallest mesh error)
  report.reference = 0;
  for (int i = 1; i < static_cast<int>(report.runs.size()); ++i) {
    const SweepLevel &l = report.runs[i].level, &b = report.runs[report.reference].level;
    if (l.motion_step < b.motion_step ||
        (l.motion_step == b.motion_step && l.mesh_chordal_error < b.mesh_chordal_error))
      report.reference = i;
  }
  for (SweepRun& r : report.runs)
    r.diff = diff_graphs(r.signature, report.runs[report.reference].signature);

  const std::filesystem::path out(a.out);
  std::filesystem::create_directories(out);
  const std::string png = "sweep.png";
  const bool chart = write_sweep_chart(report, (out / png).string());
  const std::string md = sweep_markdown(report, chart ? png : "");
  write_file(out / "sweep.csv", sweep_csv(report));
  write_file(out / "sweep.md", md);
  std::printf("%s", md.c_str());
  std::printf("\nwrote %s/sweep.csv, %s/sweep.md%s\n", a.out.c_str(), a.out.c_str(),
              chart ? (" and " + a.out + "/" + png).c_str() : "");
  if (!chart)
    std::printf("no chart: pcsg was built without the renderer (PCSG_WITH_RENDER=OFF), whose "
                "image and PNG code the chart uses\n");
}

void setup(CLI::App& cli) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = cli.add_subcommand(
      "sweep", "Run the generator over a range of resolutions: error against run time");
  cmd->add_option("scene", args->scene, "Scene file (YAML)")->required();
  cmd->add_option("-o,--out", args->out, "Output directory for sweep.csv, sweep.md, sweep.png")
      ->capture_default_str();
  cmd->add_option("--levels", args->levels,
                  "Factors on the default motion step (1e-2 L) and mesh chordal error "
                  "(1e-3 L), one run each; the smallest is the reference")
      ->delimiter(',')
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--vary", args->vary, "Which knobs the factors scale")
      ->check(CLI::IsMember({"both", "step", "mesh"}))
      ->capture_default_str();
  cmd->add_option("-j,--threads", args->threads, "Worker threads per run")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", args->quiet, "No progress on stderr");
  cmd->callback([args] { run(*args); });
}

PCSG_REGISTER_COMMAND(60, setup);

}  // namespace
}  // namespace pcsg::app
