#pragma once
// A log-log chart as a PNG, for `pcsg sweep`'s error against run time: series of points with
// markers and lines, decade ticks with labels, axis titles, a legend, and labelled vertical
// guides (one per run). Compiled only with PCSG_WITH_RENDER (it writes through render/image.h).
#ifdef PCSG_WITH_RENDER
#include <string>
#include <vector>

#include "app/plot_canvas.h"

namespace pcsg::app {

struct PlotSeries {
  std::string name;
  std::vector<double> x, y;  // y <= 0 cannot be shown on a log axis: drawn hollow on the floor
  Marker marker = Marker::Circle;
  Rgb color{0, 114, 178};
};

// A vertical guide at x with a few short lines of text above the data (e.g. a run's settings).
struct PlotGuide {
  double x = 0;
  std::vector<std::string> lines;
};

struct LogLogChart {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  std::vector<PlotGuide> guides;
  std::vector<std::string> notes;  // printed under the legend, one per line
};

render::Image draw_loglog_chart(const LogLogChart& chart, int width = 1400, int height = 850);

// The ticks of a log axis over [lo, hi] (0 < lo < hi): 1-2-5 steps when it spans at most two
// decades, decades (every other one beyond eight) otherwise. Exposed for tests.
std::vector<double> log_axis_ticks(double lo, double hi);
// "0.01", "2", "50", "1e-06": the shortest faithful label of a tick value.
std::string tick_label(double v);

}  // namespace pcsg::app
#endif  // PCSG_WITH_RENDER
