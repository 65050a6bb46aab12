// 2D drawing on images (render/canvas.h) and text (render/text_painter.h): coverage where the
// shapes are and nowhere else, dashes with gaps, text inside its measured box.
#include "render/canvas.h"

#include <gtest/gtest.h>

#include "render/text_painter.h"

namespace pcsg::render {
namespace {

Image white(int w, int h) {
  Image image(w, h);
  Canvas(image).fill(palette::kBackground);
  return image;
}

bool inked(const Image& image, int x, int y) { return image.pixel(x, y)[0] < 250; }

int inked_in(const Image& image, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) n += inked(image, x, y);
  return n;
}

TEST(CanvasTest, StrokeCoversItsWidthAndNothingElse) {
  Image image = white(100, 40);
  Canvas(image).stroke({{10, 20}, {90, 20}}, palette::kEdge, 4);
  // the stroke spans rows 18..21 fully between its ends, with round caps
  for (int y = 18; y < 22; ++y) EXPECT_LT(image.pixel(50, y)[0], 60) << "row " << y;
  EXPECT_FALSE(inked(image, 50, 15));
  EXPECT_FALSE(inked(image, 50, 25));
  EXPECT_FALSE(inked(image, 5, 20));
  EXPECT_FALSE(inked(image, 95, 20));
}

TEST(CanvasTest, DashedStrokeHasGaps) {
  Image image = white(200, 20);
  Canvas(image).stroke({{0, 10}, {200, 10}}, palette::kEdge, 2, Dash{10, 10});
  int on = 0;
  for (int x = 0; x < 200; ++x) on += inked(image, x, 10);
  // half the length is drawn, give or take the antialiased ends of the 10 dashes
  EXPECT_GT(on, 80);
  EXPECT_LT(on, 130);
  EXPECT_FALSE(inked(image, 15, 10)) << "the middle of the first gap";
}

TEST(CanvasTest, ConvexFillAndArrowhead) {
  Image image = white(60, 60);
  Canvas canvas(image);
  canvas.arrowhead({50, 30}, {1, 0}, 20, palette::kEdge);
  EXPECT_TRUE(inked(image, 40, 30));
  EXPECT_FALSE(inked(image, 52, 30)) << "nothing beyond the tip";
  EXPECT_FALSE(inked(image, 20, 30)) << "nothing behind the base";
}

TEST(CanvasTest, BezierAndTrimming) {
  const Polyline c = flatten_bezier({{0, 0}, {10, 0}, {20, 0}, {30, 0}}, 8);
  ASSERT_EQ(c.size(), 9u);
  EXPECT_NEAR((c.back() - Eigen::Vector2d(30, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(polyline_length(trim_end(c, 5)), 25, 1e-9);
  EXPECT_EQ(trim_end(c, 100).size(), 1u);
}

TEST(CanvasTest, ResizeKeepsFlatColour) {
  Image image = white(64, 48);
  Canvas(image).fill_rect(0, 0, 64, 48, Rgb{0.2f, 0.4f, 0.6f});
  const Image small = resized(image, 16, 12);
  ASSERT_EQ(small.width, 16);
  EXPECT_NEAR(small.pixel(8, 6)[1], 102, 1);
}

TEST(TextPainterTest, TextLiesInsideItsMeasuredBox) {
  TextPainter text;
  Image image = white(400, 60);
  const double px = 20;
  const double w = text.draw(image, 10, 10, "{(fA-f1, 2)} \xE2\x86\x92 e1", px, palette::kText);
  EXPECT_NEAR(w, text.width("{(fA-f1, 2)} \xE2\x86\x92 e1", px), 1e-9);
  EXPECT_GT(w, 60);
  EXPECT_GT(inked_in(image, 10, 10, static_cast<int>(10 + w) + 1, static_cast<int>(10 + px) + 1), 80);
  // nothing outside the box (a pixel of antialiasing allowed around it)
  EXPECT_EQ(inked_in(image, static_cast<int>(10 + w) + 3, 0, 400, 60), 0);
  EXPECT_EQ(inked_in(image, 0, static_cast<int>(10 + px) + 3, 400, 60), 0);
}

TEST(TextPainterTest, FitCutsWithAnEllipsis) {
  TextPainter text;
  const std::string long_text = "combined+rotation@-45deg: contact fA-f1 leaves its elements";
  const std::string cut = text.fit(long_text, 16, 120);
  EXPECT_LE(text.width(cut, 16), 120);
  EXPECT_LT(cut.size(), long_text.size());
  EXPECT_EQ(text.fit("short", 16, 120), "short");
}

TEST(TextPainterTest, DecodesUtf8) {
  EXPECT_EQ(decode_utf8("a\xE2\x86\x92"), (std::vector<char32_t>{U'a', U'\u2192'}));
  EXPECT_EQ(decode_utf8("\xE2\x86").size(), 2u) << "a cut sequence becomes replacements";
}

}  // namespace
}  // namespace pcsg::render
