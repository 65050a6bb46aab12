#pragma once
// Comparison of rendered images with golden ones (screenshots/*.png), tolerant of the small
// differences between llvmpipe builds, strict about anything a person would notice. A failed
// comparison writes the actual image and a diff image where a person can open them.
#include <string>

#include "render/image.h"

namespace pcsg::render {

// A channel differs when |expected - actual| exceeds this: Mesa versions round blending and
// MSAA resolves differently by 1-2 levels (Drake's render tests use the same 2).
inline constexpr int kChannelTolerance = 2;
// The images match when at most this share of pixels differ: antialiased edge pixels that
// move between Mesa versions stay far below it, while a moved label (~1500 px at 1024x768,
// 0.2%) or a missing edge exceeds it.
inline constexpr double kMaxDifferingShare = 0.001;

struct ImageDiff {
  bool same_size = false;
  long differing_pixels = 0;  // pixels with any channel off by more than the tolerance
  double differing_share = 0;
  int max_channel_delta = 0;
  int channel_tolerance = kChannelTolerance;  // the limits it was judged by
  double max_differing_share = kMaxDifferingShare;
  bool passed = false;
  // White where equal, grey (the expected image, faded) where within tolerance, red where a
  // pixel differs, brighter for larger differences. Empty when the sizes differ.
  Image diff;
  std::string summary() const;
};

ImageDiff diff_images(const Image& expected, const Image& actual,
                      int channel_tolerance = kChannelTolerance,
                      double max_differing_share = kMaxDifferingShare);

struct GoldenCheck {
  bool passed = false;
  std::string message;  // what was compared, the result, and where the outputs were written
};

// Compares `actual` with the PNG at `golden_path`. On failure (or a missing golden) writes
// <output_dir>/<name>.actual.png, .expected.png and .diff.png, creating the folder.
// With `update`, writes `actual` to golden_path instead and passes: the documented way to
// accept a new look on purpose (tests read PCSG_UPDATE_GOLDENS=1).
GoldenCheck check_golden(const Image& actual, const std::string& golden_path,
                         const std::string& output_dir, bool update);

}  // namespace pcsg::render
