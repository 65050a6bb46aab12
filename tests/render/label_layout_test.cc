// Greedy label placement: no two boxes overlap, all stay inside the image, obstacles and
// anchors stay uncovered, and the result is deterministic.
#include "render/label_layout.h"

#include <gtest/gtest.h>

namespace pcsg::render {
namespace {

LabelLayoutOptions image_of(double w, double h) {
  LabelLayoutOptions o;
  o.width = w;
  o.height = h;
  return o;
}

void expect_valid(const std::vector<PlacedLabel>& placed, const LabelLayoutOptions& o) {
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (!placed[i].placed) continue;
    const Box& b = placed[i].box;
    EXPECT_GE(b.x0, o.margin);
    EXPECT_GE(b.y0, o.margin);
    EXPECT_LE(b.x1, o.width - o.margin);
    EXPECT_LE(b.y1, o.height - o.margin);
    for (const Box& obstacle : o.obstacles) EXPECT_FALSE(b.overlaps(obstacle)) << i;
    for (std::size_t j = 0; j < placed.size(); ++j) {
      if (j == i || !placed[j].placed) continue;
      EXPECT_FALSE(b.overlaps(placed[j].box)) << i << " overlaps " << j;
      EXPECT_FALSE(b.contains(placed[j].anchor)) << i << " covers the anchor of " << j;
    }
  }
}

TEST(LabelLayoutTest, CrowdedAnchorsGetSeparateBoxes) {
  // twelve labels all pointing at nearly the same spot
  std::vector<LabelRequest> labels(12);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    labels[i].size = Eigen::Vector2d(40, 22);
    labels[i].anchors = {Eigen::Vector2d(300 + 3.0 * i, 200 + 2.0 * i)};
  }
  const LabelLayoutOptions o = image_of(640, 480);
  const auto placed = place_labels(labels, o);
  for (const auto& p : placed) EXPECT_TRUE(p.placed);
  expect_valid(placed, o);
}

TEST(LabelLayoutTest, ObstaclesAndBordersAreRespected) {
  std::vector<LabelRequest> labels(3);
  for (auto& l : labels) l.size = Eigen::Vector2d(50, 20);
  labels[0].anchors = {Eigen::Vector2d(5, 5)};      // in the corner, under the header
  labels[1].anchors = {Eigen::Vector2d(635, 475)};  // the opposite corner
  labels[2].anchors = {Eigen::Vector2d(320, 60)};   // under the header
  LabelLayoutOptions o = image_of(640, 480);
  o.obstacles = {Box{0, 0, 640, 50}};
  const auto placed = place_labels(labels, o);
  for (const auto& p : placed) EXPECT_TRUE(p.placed);
  expect_valid(placed, o);
}

TEST(LabelLayoutTest, LeaderEndsOnTheBoxNearestTheAnchor) {
  std::vector<LabelRequest> labels(1);
  labels[0].size = Eigen::Vector2d(30, 16);
  labels[0].anchors = {Eigen::Vector2d(200, 200)};
  const auto placed = place_labels(labels, image_of(400, 400));
  ASSERT_TRUE(placed[0].placed);
  const PlacedLabel& p = placed[0];
  EXPECT_EQ(p.leader_end, p.box.clamp(p.anchor));
  // the box's nearest point is at most the shortest leader length tried from the anchor
  const double length = (p.leader_end - p.anchor).norm();
  EXPECT_LE(length, LabelLayoutOptions{}.leader_lengths.front() + 1e-9);
  EXPECT_GT(length, 0.5 * LabelLayoutOptions{}.leader_lengths.front());
}

TEST(LabelLayoutTest, PrefersTheBackgroundOverTheObjects) {
  // the left half of the image is covered by an object
  std::vector<char> mask(100 * 100, 0);
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 50; ++x) mask[y * 100 + x] = 1;
  }
  const CoverageMap coverage(100, 100, 4.0, mask);  // 400 x 400 image
  EXPECT_DOUBLE_EQ(coverage.share(Box{0, 0, 200, 400}), 1.0);
  EXPECT_DOUBLE_EQ(coverage.share(Box{200, 0, 400, 400}), 0.0);
  std::vector<LabelRequest> labels(1);
  labels[0].size = Eigen::Vector2d(30, 16);
  labels[0].anchors = {Eigen::Vector2d(200, 200)};  // on the boundary
  LabelLayoutOptions o = image_of(400, 400);
  o.coverage = &coverage;
  const auto placed = place_labels(labels, o);
  ASSERT_TRUE(placed[0].placed);
  EXPECT_GT(placed[0].box.x0, 200);
}

TEST(LabelLayoutTest, UnplaceableLabelIsDroppedNotOverlapped) {
  // a label larger than the free image
  std::vector<LabelRequest> labels(2);
  labels[0].size = Eigen::Vector2d(30, 16);
  labels[0].anchors = {Eigen::Vector2d(50, 50)};
  labels[1].size = Eigen::Vector2d(500, 16);
  labels[1].anchors = {Eigen::Vector2d(60, 60)};
  const LabelLayoutOptions o = image_of(100, 100);
  const auto placed = place_labels(labels, o);
  EXPECT_TRUE(placed[0].placed);
  EXPECT_FALSE(placed[1].placed);
  expect_valid(placed, o);
}

TEST(LabelLayoutTest, IsDeterministic) {
  std::vector<LabelRequest> labels(8);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    labels[i].size = Eigen::Vector2d(30 + 5.0 * i, 20);
    labels[i].anchors = {Eigen::Vector2d(100 + 20.0 * i, 150), Eigen::Vector2d(100, 100 + 9.0 * i)};
  }
  const auto a = place_labels(labels, image_of(400, 300));
  const auto b = place_labels(labels, image_of(400, 300));
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].box.x0, b[i].box.x0);
    EXPECT_EQ(a[i].box.y0, b[i].box.y0);
  }
}

}  // namespace
}  // namespace pcsg::render
