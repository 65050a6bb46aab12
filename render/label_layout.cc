#include "render/label_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcsg::render {

namespace {

// Directions tried around an anchor: 16 (every 22.5 degrees), starting at "up-right" where
// labels of the paper's figures usually sit.
constexpr int kDirections = 16;
constexpr double kPi = 3.14159265358979323846;
// Score weights (pixels of leader length that each flaw is worth): a worse-ranked anchor, a
// box on top of the objects, a leader crossing another leader, an anchor under an obstacle.
constexpr double kAnchorRankCost = 30;
constexpr double kCoverageCost = 90;
constexpr double kCrossingCost = 120;
constexpr double kCoveredAnchorCost = 200;

bool segments_cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d) {
  auto orient = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
  };
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  return ((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0)) && o1 != 0 && o2 != 0 && o3 != 0 &&
         o4 != 0;
}

// Does the segment a-b pass through the box (shrunk slightly so touching does not count)?
bool segment_hits_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Box& box) {
  const Box inner{box.x0 + 1, box.y0 + 1, box.x1 - 1, box.y1 - 1};
  if (inner.x0 >= inner.x1 || inner.y0 >= inner.y1) return false;
  if (inner.contains(a) || inner.contains(b)) return true;
  const Eigen::Vector2d c[4] = {
      {inner.x0, inner.y0}, {inner.x1, inner.y0}, {inner.x1, inner.y1}, {inner.x0, inner.y1}};
  for (int i = 0; i < 4; ++i) {
    if (segments_cross(a, b, c[i], c[(i + 1) % 4])) return true;
  }
  return false;
}

struct Candidate {
  double score = std::numeric_limits<double>::infinity();
  PlacedLabel label;
};

}  // namespace

CoverageMap::CoverageMap(int width, int height, double scale, const std::vector<char>& mask)
    : width_(width),
      height_(height),
      scale_(scale),
      sums_(static_cast<std::size_t>(width + 1) * (height + 1), 0) {
  for (int y = 0; y < height; ++y) {
    int row = 0;
    for (int x = 0; x < width; ++x) {
      row += mask[static_cast<std::size_t>(y) * width + x] ? 1 : 0;
      sums_[static_cast<std::size_t>(y + 1) * (width + 1) + x + 1] =
          sums_[static_cast<std::size_t>(y) * (width + 1) + x + 1] + row;
    }
  }
}

double CoverageMap::share(const Box& box) const {
  if (width_ == 0 || height_ == 0) return 0;
  auto cell = [&](double v, int n) {
    return std::clamp(static_cast<int>(std::lround(v / scale_)), 0, n);
  };
  const int x0 = cell(box.x0, width_), x1 = cell(box.x1, width_);
  const int y0 = cell(box.y0, height_), y1 = cell(box.y1, height_);
  const int area = (x1 - x0) * (y1 - y0);
  if (area <= 0) return 0;
  auto at = [&](int x, int y) { return sums_[static_cast<std::size_t>(y) * (width_ + 1) + x]; };
  return static_cast<double>(at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0)) / area;
}

std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& labels,
                                      const LabelLayoutOptions& o) {
  std::vector<PlacedLabel> placed(labels.size());
  std::vector<Box> taken = o.obstacles;  // boxes no later label may overlap
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> leaders;
  // every label's best anchor stays uncovered, so that no box hides what another points at
  std::vector<Eigen::Vector2d> anchors;
  for (const auto& l : labels) {
    if (!l.anchors.empty()) anchors.push_back(l.anchors.front());
  }

  auto try_lengths = [&](const LabelRequest& l, const std::vector<double>& lengths) {
    Candidate best;
    for (std::size_t ai = 0; ai < l.anchors.size(); ++ai) {
      const Eigen::Vector2d& anchor = l.anchors[ai];
      // an anchor under a contact marker would point at the marker rather than the element
      double anchor_cost = kAnchorRankCost * static_cast<double>(ai);
      for (const Box& b : o.obstacles) {
        if (b.contains(anchor)) anchor_cost += kCoveredAnchorCost;
      }
      for (double length : lengths) {
        for (int k = 0; k < kDirections; ++k) {
          const double angle = -kPi / 4 + 2 * kPi * k / kDirections;
          const Eigen::Vector2d dir(std::cos(angle), -std::sin(angle));  // y grows downward
          // the box sits beyond the leader's end, its nearest side facing the anchor
          const Eigen::Vector2d end = anchor + length * dir;
          const double t =
              std::min(std::abs(dir.x()) > 1e-9 ? 0.5 * l.size.x() / std::abs(dir.x()) : 1e30,
                       std::abs(dir.y()) > 1e-9 ? 0.5 * l.size.y() / std::abs(dir.y()) : 1e30);
          const Eigen::Vector2d centre = end + t * dir;
          const Box box{centre.x() - 0.5 * l.size.x(), centre.y() - 0.5 * l.size.y(),
                        centre.x() + 0.5 * l.size.x(), centre.y() + 0.5 * l.size.y()};
          // hard constraints: inside the image, nothing overlapped, no anchor covered
          if (box.x0 < o.margin || box.y0 < o.margin || box.x1 > o.width - o.margin ||
              box.y1 > o.height - o.margin) {
            continue;
          }
          bool blocked = false;
          for (const Box& b : taken) blocked = blocked || box.overlaps(b, o.gap);
          const Box grown{box.x0 - o.anchor_clearance, box.y0 - o.anchor_clearance,
                          box.x1 + o.anchor_clearance, box.y1 + o.anchor_clearance};
          for (const auto& a : anchors) blocked = blocked || grown.contains(a);
          if (blocked) continue;
          // leaders never run through another label (through a marker or the header is
          // allowed: an anchor may lie under one)
          const Eigen::Vector2d leader_end = box.clamp(anchor);
          for (std::size_t b = o.obstacles.size(); b < taken.size(); ++b) {
            blocked = blocked || segment_hits_box(anchor, leader_end, taken[b]);
          }
          if (blocked) continue;

          // soft costs: length, anchor rank, covering the objects, crossing other leaders
          double score = length + anchor_cost;
          if (o.coverage != nullptr) score += kCoverageCost * o.coverage->share(box);
          for (const auto& [a, b] : leaders) {
            if (segments_cross(anchor, leader_end, a, b)) score += kCrossingCost;
          }
          if (score < best.score) {
            best.score = score;
            best.label = PlacedLabel{true, anchor, box, leader_end};
          }
        }
      }
    }
    return best;
  };

  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i].anchors.empty()) continue;
    Candidate best = try_lengths(labels[i], o.leader_lengths);
    if (!best.label.placed) best = try_lengths(labels[i], o.fallback_leader_lengths);
    if (!best.label.placed) continue;
    placed[i] = best.label;
    taken.push_back(best.label.box);
    anchors.push_back(best.label.anchor);  // (a no-op duplicate when it was the best anchor)
    leaders.emplace_back(best.label.anchor, best.label.leader_end);
  }
  return placed;
}

}  // namespace pcsg::render
