#ifdef PCSG_WITH_RENDER
#include "app/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace pcsg::app {
namespace {

constexpr Rgb kInk{30, 30, 30}, kGrid{225, 225, 225}, kMinorGrid{242, 242, 242},
    kGuide{150, 150, 150}, kWhite{255, 255, 255};
constexpr double kTitlePx = 26, kLabelPx = 20, kTickPx = 17, kSmallPx = 15;

struct Axis {
  double lo, hi;  // data range (log scale)
  double p0, p1;  // pixel range
  double map(double v) const {
    return p0 + (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) * (p1 - p0);
  }
};

// The positive range of the data, widened by `pad` (a factor) on both sides; a single value
// or no value gives one decade around it.
std::pair<double, double> positive_range(const std::vector<double>& v, double pad) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (double x : v)
    if (x > 0 && std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  if (hi == 0) return {0.1, 10};
  if (hi / lo < 1.5) return {lo / 1.6, hi * 1.6};
  return {lo / pad, hi * pad};
}

}  // namespace

std::vector<double> log_axis_ticks(double lo, double hi) {
  std::vector<double> out;
  const int k0 = static_cast<int>(std::floor(std::log10(lo))) - 1;
  const int k1 = static_cast<int>(std::ceil(std::log10(hi))) + 1;
  const double decades = std::log10(hi / lo);
  const double tiny = 1e-9;  // relative slack when comparing a tick with the range ends
  auto ticks = [&](std::initializer_list<double> mantissas) {
    out.clear();
    for (int k = k0; k <= k1; ++k) {
      if (decades > 8 && k % 2 != 0 && mantissas.size() == 1) continue;
      for (double m : mantissas) out.push_back(m * std::pow(10.0, k));
    }
    std::erase_if(out, [&](double t) { return t < lo * (1 - tiny) || t > hi * (1 + tiny); });
  };
  if (decades > 2) {
    ticks({1.0});
  } else {
    ticks({1.0, 2.0, 5.0});
    if (out.size() < 3) ticks({1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0});  // < half a decade
  }
  return out;
}

std::string tick_label(double v) {
  char buf[32];
  const double e = std::log10(v);
  if (e >= -3 && e < 5)
    std::snprintf(buf, sizeof buf, "%g", v);
  else
    std::snprintf(buf, sizeof buf, "%.0e", v);  // "1e-06"
  return buf;
}

render::Image draw_loglog_chart(const LogLogChart& chart, int width, int height) {
  PlotCanvas c(width, height, kWhite);
  std::vector<double> xs, ys;
  for (const PlotSeries& s : chart.series) {
    xs.insert(xs.end(), s.x.begin(), s.x.end());
    ys.insert(ys.end(), s.y.begin(), s.y.end());
  }
  auto [xlo, xhi] = positive_range(xs, 1.3);
  auto [ylo, yhi] = positive_range(ys, 1.0);
  // whole decades on the error axis, with room so that no marker sits on the frame
  ylo = std::pow(10.0, std::floor(std::log10(ylo / 2)));
  yhi = std::pow(10.0, std::ceil(std::log10(yhi * 2)));
  // layout: title on top, then the guides' labels in rows above the axes box (each label in
  // the first row where it overlaps no other), legend column on the right
  const double left = 120, right = width - 330, bottom = height - 90;
  const Axis ax{xlo, xhi, left, right};
  const double line_h = kSmallPx + 3;
  std::vector<std::vector<std::pair<double, double>>> rows;
  std::vector<size_t> guide_row(chart.guides.size(), 0);
  size_t max_lines = 0;
  for (size_t k = 0; k < chart.guides.size(); ++k) {
    const PlotGuide& g = chart.guides[k];
    if (!(g.x > 0)) continue;
    double w = 0;
    for (const std::string& l : g.lines) w = std::max(w, c.text_width(l, kSmallPx));
    const double x = ax.map(g.x);
    const std::pair<double, double> span{x - w / 2 - 6, x + w / 2 + 6};
    size_t row = 0;
    for (; row < rows.size(); ++row)
      if (std::none_of(rows[row].begin(), rows[row].end(),
                       [&](auto s) { return s.first < span.second && span.first < s.second; }))
        break;
    if (row == rows.size()) rows.emplace_back();
    rows[row].push_back(span);
    guide_row[k] = row;
    max_lines = std::max(max_lines, g.lines.size());
  }
  const double row_h = line_h * max_lines + 8;
  const double top = 75 + row_h * rows.size() + 10;
  const Axis ay{ylo, yhi, bottom, top};
  // rows from the box upward (row 0 right above it); leader lines first, then the labels on
  // white so that a leader of a higher row never crosses a label's text
  auto label_bottom = [&](size_t k) { return top - 6 - row_h * guide_row[k]; };
  for (size_t k = 0; k < chart.guides.size(); ++k)
    if (chart.guides[k].x > 0) {
      const double x = ax.map(chart.guides[k].x);
      c.line(x, label_bottom(k), x, bottom, 1.2, kGuide, 5);
    }
  for (size_t k = 0; k < chart.guides.size(); ++k) {
    const PlotGuide& g = chart.guides[k];
    if (!(g.x > 0)) continue;
    const double x = ax.map(g.x), y1 = label_bottom(k), y0 = y1 - line_h * g.lines.size();
    double w = 0;
    for (const std::string& l : g.lines) w = std::max(w, c.text_width(l, kSmallPx));
    c.fill_rect(x - w / 2 - 4, y0 - 2, x + w / 2 + 4, y1, kWhite);
    for (size_t i = 0; i < g.lines.size(); ++i)
      c.text(x, y0 + line_h * (i + 1) - 4, g.lines[i], kSmallPx, kInk, Align::Center);
  }

  // grid, minor grid, ticks and their labels
  auto minor_ticks = [](double lo, double hi) {
    std::vector<double> out;
    if (std::log10(hi / lo) > 8) return out;
    for (int k = static_cast<int>(std::floor(std::log10(lo))); k <= std::ceil(std::log10(hi)); ++k)
      for (int m = 2; m <= 9; ++m) {
        const double t = m * std::pow(10.0, k);
        if (t >= lo && t <= hi) out.push_back(t);
      }
    return out;
  };
  for (double t : minor_ticks(xlo, xhi)) c.line(ax.map(t), top, ax.map(t), bottom, 1, kMinorGrid);
  for (double t : minor_ticks(ylo, yhi)) c.line(left, ay.map(t), right, ay.map(t), 1, kMinorGrid);
  for (double t : log_axis_ticks(xlo, xhi)) {
    const double x = ax.map(t);
    c.line(x, top, x, bottom, 1, kGrid);
    c.line(x, bottom, x, bottom + 7, 1.5, kInk);
    c.text(x, bottom + 27, tick_label(t), kTickPx, kInk, Align::Center);
  }
  for (double t : log_axis_ticks(ylo, yhi)) {
    const double y = ay.map(t);
    c.line(left, y, right, y, 1, kGrid);
    c.line(left - 7, y, left, y, 1.5, kInk);
    c.text(left - 12, y + 6, tick_label(t), kTickPx, kInk, Align::Right);
  }
  c.stroke_rect(left, top, right, bottom, 1.5, kInk);

  // the series: lines first, then markers on top; values <= 0 hollow on the floor
  bool any_floor = false;
  for (const PlotSeries& s : chart.series) {
    auto py = [&](double y) { return y > 0 ? ay.map(std::clamp(y, ylo, yhi)) : bottom; };
    for (size_t i = 0; i + 1 < s.x.size(); ++i)
      if (s.y[i] > 0 && s.y[i + 1] > 0)
        c.line(ax.map(s.x[i]), py(s.y[i]), ax.map(s.x[i + 1]), py(s.y[i + 1]), 2.5, s.color);
    for (size_t i = 0; i < s.x.size(); ++i) {
      any_floor = any_floor || !(s.y[i] > 0);
      c.marker(ax.map(s.x[i]), py(s.y[i]), s.marker, 7, s.color, !(s.y[i] > 0));
    }
  }

  // titles
  c.text(left, 45, chart.title, kTitlePx, kInk);
  c.text((left + right) / 2, height - 25, chart.x_label, kLabelPx, kInk, Align::Center);
  c.text(35, (top + bottom) / 2, chart.y_label, kLabelPx, kInk, Align::Center, true);

  // legend and notes
  const double lx = right + 30;
  double ly = top + 10;
  c.text(lx, ly + 8, "Legend", kLabelPx, kInk);
  ly += 36;
  for (const PlotSeries& s : chart.series) {
    c.line(lx, ly, lx + 40, ly, 2.5, s.color);
    c.marker(lx + 20, ly, s.marker, 7, s.color);
    c.text(lx + 52, ly + 6, s.name, kSmallPx, kInk);
    ly += 30;
  }
  if (any_floor) {
    c.marker(lx + 20, ly, Marker::Circle, 7, kInk, true);
    c.text(lx + 52, ly + 6, "value 0 (drawn on the axis)", kSmallPx, kInk);
    ly += 30;
  }
  ly += 12;
  for (const std::string& n : chart.notes) {
    c.text(lx, ly, n, kSmallPx, kInk);
    ly += kSmallPx + 6;
  }
  return c.image();
}

}  // namespace pcsg::app
#endif  // PCSG_WITH_RENDER
