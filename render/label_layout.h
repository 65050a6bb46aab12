#pragma once
// Greedy placement of element labels (paper Fig. 5a/7a: every face and edge named, with a
// leader line to it): each label in turn takes the best box around one of its candidate
// anchors that overlaps no earlier box, no obstacle and no other anchor, and stays inside the
// image. Plain geometry in pixels (x right, y down), no GL, so it is tested on its own.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace pcsg::render {

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // x0 <= x1, y0 <= y1
  bool overlaps(const Box& o, double gap = 0) const {
    return x0 < o.x1 + gap && o.x0 < x1 + gap && y0 < o.y1 + gap && o.y0 < y1 + gap;
  }
  bool contains(const Eigen::Vector2d& p) const {
    return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1;
  }
  Eigen::Vector2d clamp(const Eigen::Vector2d& p) const {
    return {std::min(std::max(p.x(), x0), x1), std::min(std::max(p.y(), y0), y1)};
  }
};

// Share of each box covered by the objects, from a coarse mask (summed-area table), so that
// labels prefer the white background to sitting on top of the objects.
class CoverageMap {
 public:
  CoverageMap() = default;
  // mask: width x height cells, rows top first, each cell `scale` image pixels wide.
  CoverageMap(int width, int height, double scale, const std::vector<char>& mask);
  double share(const Box& box) const;  // in [0, 1]; 0 when the map is empty

 private:
  int width_ = 0, height_ = 0;
  double scale_ = 1;
  std::vector<int> sums_;  // (width+1) x (height+1)
};

struct LabelRequest {
  Eigen::Vector2d size{0, 0};            // box size in pixels (text plus padding)
  std::vector<Eigen::Vector2d> anchors;  // candidate anchor points, best first
};

struct PlacedLabel {
  bool placed = false;  // false only when no free spot exists (tiny images)
  Eigen::Vector2d anchor{0, 0};
  Box box;
  Eigen::Vector2d leader_end{0, 0};  // point of the box nearest to the anchor
};

struct LabelLayoutOptions {
  double width = 0, height = 0;  // the image
  double margin = 4;             // kept free along the image border
  double gap = 4;                // between two label boxes
  double anchor_clearance = 5;   // radius around every anchor that no box may cover
  std::vector<double> leader_lengths = {26, 44, 70, 110};  // tried in this order
  // Extra lengths tried only when nothing else fits.
  std::vector<double> fallback_leader_lengths = {160, 240, 340, 480};
  std::vector<Box> obstacles;  // header, contact markers: never covered
  const CoverageMap* coverage = nullptr;
};

// Places the labels in the given order (earlier labels get the better spots). Deterministic:
// ties go to the first candidate. Never returns two overlapping placed boxes.
std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& labels,
                                      const LabelLayoutOptions& options);

}  // namespace pcsg::render
