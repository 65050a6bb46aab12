#include "app/sweep_report.h"

#include <cstdio>

#ifdef PCSG_WITH_RENDER
#include "app/plot.h"
#endif

namespace pcsg::app {
namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string sci(double v) { return v == 0 ? "0" : fmt("%.1e", v); }

}  // namespace

int SweepReport::fastest_matching() const {
  int best = -1;
  for (int i = 0; i < static_cast<int>(runs.size()); ++i) {
    const SweepRun& r = runs[i];
    if (!r.diff.same_cfs_and_links() || r.witness_cf_mismatches > 0) continue;
    if (best < 0 || r.total_seconds() < runs[best].total_seconds()) best = i;
  }
  return best;
}

std::string sweep_csv(const SweepReport& report) {
  std::string out =
      "run,motion_step_rel,mesh_chordal_error_rel,length_scale,triangles,build_s,generate_s,"
      "total_s,states,distinct_cfs,links,collision_queries,pair_solves,motion_steps,"
      "witness_residual,witness_residual_rel,witness_cf_mismatches,keep_drift,keep_drift_rel,"
      "step_penetration,step_penetration_rel,cfs_added,cfs_missing,links_added,links_missing,"
      "repeated_states,reference\n";
  for (size_t i = 0; i < report.runs.size(); ++i) {
    const SweepRun& r = report.runs[i];
    const double L = r.length_scale;
    char line[1024];
    std::snprintf(line, sizeof line,
                  "%zu,%.6g,%.6g,%.17g,%ld,%.4f,%.4f,%.4f,%d,%zu,%d,%ld,%ld,%ld,%.6e,%.6e,%d,%.6e,"
                  "%.6e,%.6e,%.6e,%zu,%zu,%zu,%zu,%d,%d\n",
                  i + 1, r.level.motion_step, r.level.mesh_chordal_error, L, r.triangles,
                  r.build_seconds, r.generate_seconds, r.total_seconds(), r.states,
                  r.signature.cfs().size(), r.links, r.collision_queries, r.pair_solves,
                  r.motion_steps, r.witness_residual, r.witness_residual / L,
                  r.witness_cf_mismatches, r.keep_drift, r.keep_drift / L, r.step_penetration,
                  r.step_penetration / L, r.diff.cfs_added.size(), r.diff.cfs_missing.size(),
                  r.diff.links_added.size(), r.diff.links_missing.size(), r.diff.repeats,
                  static_cast<int>(i) == report.reference ? 1 : 0);
    out += line;
  }
  return out;
}

std::string sweep_markdown(const SweepReport& report, const std::string& png_name) {
  std::string md = "# Sweep: " + report.scene_name + "\n\n";
  md += "Scene file `" + report.scene_path + "`, " + std::to_string(report.threads) +
        " worker thread" + (report.threads == 1 ? "" : "s") +
        ". Each run builds the scene with the given mesh chordal error and generates its graph "
        "with the given motion step (both relative to the length scale L), measuring the "
        "discretisation error of every accepted motion step at its midpoint. Times include "
        "those measurements (one more contact detection per step). Errors are relative to L. "
        "States: all states (CFs: the distinct contact formations among them; a CF held by "
        "several states is a repeat). The last column compares each run's distinct CFs and LN "
        "links with the finest run's, and its repeats.\n\n";
  md += "| run | motion step / L | mesh error / L | triangles | build s | generate s | total s "
        "| states | CFs | links | queries | witness residual / L | keep drift / L | step "
        "penetration / L | bad witnesses | graph vs finest |\n";
  md += "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (size_t i = 0; i < report.runs.size(); ++i) {
    const SweepRun& r = report.runs[i];
    const double L = r.length_scale;
    md += "| " + std::to_string(i + 1) + " | " + fmt("%g", r.level.motion_step) + " | " +
          fmt("%g", r.level.mesh_chordal_error) + " | " + std::to_string(r.triangles) + " | " +
          fmt("%.2f", r.build_seconds) + " | " + fmt("%.2f", r.generate_seconds) + " | " +
          fmt("%.2f", r.total_seconds()) + " | " + std::to_string(r.states) + " | " +
          std::to_string(r.signature.cfs().size()) + " | " + std::to_string(r.links) + " | " +
          std::to_string(r.collision_queries) + " | " +
          sci(r.witness_residual / L) + " | " + sci(r.keep_drift / L) + " | " +
          sci(r.step_penetration / L) + " | " + std::to_string(r.witness_cf_mismatches) + " | " +
          (static_cast<int>(i) == report.reference ? "reference" : r.diff.summary()) + " |\n";
  }
  const int best = report.fastest_matching();
  md += "\n";
  if (best >= 0)
    md += "Fastest run with the finest run's CFs and links and valid witnesses: run " +
          std::to_string(best + 1) + " (" + fmt("%.2f", report.runs[best].total_seconds()) +
          " s).\n";
  else
    md += "No run has the finest run's CFs and links with valid witnesses.\n";
  // the differences, spelled out
  std::string details;
  const GraphSignature& ref = report.runs[report.reference].signature;
  for (size_t i = 0; i < report.runs.size(); ++i) {
    const GraphDiff& d = report.runs[i].diff;
    if (d.same_cfs_and_links()) continue;
    details += "\nRun " + std::to_string(i + 1) + ":\n";
    for (const auto& s : d.cfs_added) details += "- extra CF `" + s + "`\n";
    for (const auto& s : d.cfs_missing) details += "- missing CF `" + s + "`\n";
    for (const auto& s : d.links_added) details += "- extra link `" + s + "`\n";
    for (const auto& s : d.links_missing) details += "- missing link `" + s + "`\n";
  }
  if (!details.empty()) md += "\n## Differences from the finest run\n" + details;
  // the repeated CFs of every run: two regions of one CF, or one region found twice
  std::string repeats;
  for (size_t i = 0; i < report.runs.size(); ++i) {
    const std::vector<std::string>& st = report.runs[i].signature.states;
    std::string line;
    for (size_t k = 0; k < st.size();) {
      size_t n = 1;
      while (k + n < st.size() && st[k + n] == st[k]) ++n;
      if (n > 1) line += (line.empty() ? "" : ", ") + ("`" + st[k] + "` x" + std::to_string(n));
      k += n;
    }
    if (!line.empty()) repeats += "- run " + std::to_string(i + 1) + ": " + line + "\n";
  }
  if (!repeats.empty())
    md += "\n## Repeated CFs\n\nStates sharing a CF (the finest run has " +
          std::to_string(ref.repeats()) + "):\n\n" + repeats;
  if (!png_name.empty()) md += "\n![error against run time](" + png_name + ")\n";
  return md;
}

#ifdef PCSG_WITH_RENDER
bool write_sweep_chart(const SweepReport& report, const std::string& png_path) {
  LogLogChart chart;
  chart.title = "Error against run time: " + report.scene_name;
  chart.x_label = "run time (s): scene build + graph generation";
  chart.y_label = "error / length scale L";
  PlotSeries residual{"witness contact residual", {}, {}, Marker::Circle, {0, 114, 178}};
  PlotSeries drift{"kept-contact drift (step midpoint)", {}, {}, Marker::Square, {230, 159, 0}};
  PlotSeries pen{"penetration (step midpoint)", {}, {}, Marker::Triangle, {0, 158, 115}};
  for (size_t i = 0; i < report.runs.size(); ++i) {
    const SweepRun& r = report.runs[i];
    const double t = r.total_seconds(), L = r.length_scale;
    residual.x.push_back(t), residual.y.push_back(r.witness_residual / L);
    drift.x.push_back(t), drift.y.push_back(r.keep_drift / L);
    pen.x.push_back(t), pen.y.push_back(r.step_penetration / L);
    chart.guides.push_back(
        {t,
         {"run " + std::to_string(i + 1), "step " + fmt("%g", r.level.motion_step),
          "mesh " + fmt("%g", r.level.mesh_chordal_error),
          static_cast<int>(i) == report.reference ? "reference" : "graph: " + r.diff.summary()}});
  }
  chart.series = {residual, drift, pen};
  chart.notes = {"step, mesh: motion step and mesh",
                 "chordal error, relative to L.",
                 "graph: CFs and links added (+) or",
                 "missing (-) against the finest run;",
                 "repeats: states sharing a CF."};
  render::write_png(draw_loglog_chart(chart), png_path);
  return true;
}
#else
bool write_sweep_chart(const SweepReport&, const std::string&) { return false; }
#endif

}  // namespace pcsg::app
