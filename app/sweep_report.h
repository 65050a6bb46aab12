#pragma once
// The outputs of `pcsg sweep`: a CSV of every figure of every run, a Markdown report (table,
// graph differences from the finest run), and the error-against-time chart.
#include <string>
#include <vector>

#include "app/sweep_run.h"

namespace pcsg::app {

struct SweepReport {
  std::string scene_name, scene_path;
  int threads = 1;
  std::vector<SweepRun> runs;  // in sweep order; the reference is `reference`
  int reference = -1;          // index of the finest run
  // The fastest run (by total time) whose graph equals the reference's and whose witnesses
  // all re-check; -1 when none.
  int fastest_matching() const;
};

std::string sweep_csv(const SweepReport& report);
std::string sweep_markdown(const SweepReport& report, const std::string& png_name);
// Writes the chart as a PNG; returns false (writing nothing) when pcsg was built without the
// renderer, whose image and PNG code it uses.
bool write_sweep_chart(const SweepReport& report, const std::string& png_path);

}  // namespace pcsg::app
