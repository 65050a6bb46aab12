// Image comparison: tolerance per channel, share of differing pixels, outputs on failure.
#include "render/image_diff.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "engine/core/error.h"
#include "tests/render/golden.h"

namespace pcsg::render {
namespace {

Image filled(int w, int h, std::uint8_t v) {
  Image im(w, h);
  std::fill(im.rgba.begin(), im.rgba.end(), v);
  return im;
}

TEST(ImageDiffTest, EqualImagesPass) {
  const ImageDiff d = diff_images(filled(10, 10, 100), filled(10, 10, 100));
  EXPECT_TRUE(d.passed);
  EXPECT_EQ(d.differing_pixels, 0);
  EXPECT_EQ(d.max_channel_delta, 0);
}

TEST(ImageDiffTest, DifferencesWithinToleranceDoNotCount) {
  const ImageDiff d = diff_images(filled(10, 10, 100), filled(10, 10, 100 + kChannelTolerance));
  EXPECT_TRUE(d.passed);
  EXPECT_EQ(d.differing_pixels, 0);
  EXPECT_EQ(d.max_channel_delta, kChannelTolerance);
}

TEST(ImageDiffTest, ShareOfDifferingPixelsDecides) {
  // 100 x 100 = 10000 pixels: 10 differing is exactly 0.1% (passes), 11 fails
  Image expected = filled(100, 100, 50), actual = expected;
  for (int i = 0; i < 10; ++i) actual.pixel(i, 0)[1] = 200;
  ImageDiff d = diff_images(expected, actual);
  EXPECT_EQ(d.differing_pixels, 10);
  EXPECT_TRUE(d.passed) << d.summary();
  actual.pixel(10, 0)[1] = 200;
  d = diff_images(expected, actual);
  EXPECT_FALSE(d.passed) << d.summary();
  EXPECT_EQ(d.diff.pixel(10, 0)[0], 255);  // differing pixels are red in the diff image
  EXPECT_LT(d.diff.pixel(10, 0)[1], 100);
}

TEST(ImageDiffTest, DifferentSizesFail) {
  const ImageDiff d = diff_images(filled(10, 10, 0), filled(10, 11, 0));
  EXPECT_FALSE(d.same_size);
  EXPECT_FALSE(d.passed);
}

TEST(ImageDiffTest, FailedGoldenWritesActualExpectedAndDiff) {
  namespace fs = std::filesystem;
  // one folder per test: CTest runs the tests of this file in parallel processes
  const fs::path dir = fs::path(testing::test_output_dir()) / "image_diff_test" / "golden";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string golden = (dir / "square.png").string();
  write_png(filled(8, 8, 10), golden);

  GoldenCheck r = check_golden(filled(8, 8, 10), golden, (dir / "out").string(), false);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_FALSE(fs::exists(dir / "out"));

  r = check_golden(filled(8, 8, 90), golden, (dir / "out").string(), false);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("PCSG_UPDATE_GOLDENS=1"), std::string::npos) << r.message;
  EXPECT_TRUE(fs::exists(dir / "out" / "square.actual.png"));
  EXPECT_TRUE(fs::exists(dir / "out" / "square.expected.png"));
  EXPECT_TRUE(fs::exists(dir / "out" / "square.diff.png"));

  // updating on purpose replaces the golden
  r = check_golden(filled(8, 8, 90), golden, (dir / "out").string(), true);
  EXPECT_TRUE(r.passed);
  EXPECT_TRUE(read_png(golden) == filled(8, 8, 90));
}

TEST(ImageDiffTest, PngRoundTripKeepsRowsTopFirst) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(testing::test_output_dir()) / "image_diff_test" / "round_trip";
  fs::create_directories(dir);
  Image im = filled(3, 2, 0);
  im.pixel(0, 0)[0] = 255;  // top-left red
  im.pixel(2, 1)[2] = 255;  // bottom-right blue
  const std::string path = (dir / "rows.png").string();
  write_png(im, path);
  EXPECT_TRUE(read_png(path) == im);
}

TEST(ImageDiffTest, ReadingAMissingPngThrowsNamingIt) {
  try {
    read_png("/nonexistent/x.png");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.png"), std::string::npos);
  }
}

}  // namespace
}  // namespace pcsg::render
