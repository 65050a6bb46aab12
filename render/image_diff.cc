#include "render/image_diff.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "engine/core/error.h"

namespace pcsg::render {

std::string ImageDiff::summary() const {
  if (!same_size) return "image sizes differ";
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%ld pixels (%.4f%%) differ by more than %d levels (allowed %.4f%%); largest "
                "channel difference %d",
                differing_pixels, 100 * differing_share, channel_tolerance,
                100 * max_differing_share, max_channel_delta);
  return buf;
}

ImageDiff diff_images(const Image& expected, const Image& actual, int channel_tolerance,
                      double max_differing_share) {
  ImageDiff d;
  d.channel_tolerance = channel_tolerance;
  d.max_differing_share = max_differing_share;
  d.same_size =
      expected.width == actual.width && expected.height == actual.height && !expected.empty();
  if (!d.same_size) return d;
  d.diff = Image(expected.width, expected.height);
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const auto* e = expected.pixel(x, y);
      const auto* a = actual.pixel(x, y);
      int delta = 0;
      for (int c = 0; c < 4; ++c) delta = std::max(delta, std::abs(int(e[c]) - int(a[c])));
      d.max_channel_delta = std::max(d.max_channel_delta, delta);
      auto* out = d.diff.pixel(x, y);
      if (delta > channel_tolerance) {
        ++d.differing_pixels;
        out[0] = 255;
        out[1] = out[2] = static_cast<std::uint8_t>(std::max(0, 160 - delta));
      } else {
        // the expected image, faded, so that a person sees where the differences are
        const int grey = (e[0] + e[1] + e[2]) / 3;
        out[0] = out[1] = out[2] = static_cast<std::uint8_t>(255 - (255 - grey) / 4);
      }
      out[3] = 255;
    }
  }
  d.differing_share = static_cast<double>(d.differing_pixels) /
                      (static_cast<double>(expected.width) * expected.height);
  d.passed = d.differing_share <= max_differing_share;
  return d;
}

GoldenCheck check_golden(const Image& actual, const std::string& golden_path,
                         const std::string& output_dir, bool update) {
  namespace fs = std::filesystem;
  GoldenCheck result;
  if (update) {
    fs::create_directories(fs::path(golden_path).parent_path());
    write_png(actual, golden_path);
    result.passed = true;
    result.message = "updated golden " + golden_path;
    return result;
  }
  const std::string name = fs::path(golden_path).stem().string();
  const fs::path out = fs::path(output_dir);
  auto write_outputs = [&](const Image* expected, const ImageDiff* diff) {
    fs::create_directories(out);
    write_png(actual, (out / (name + ".actual.png")).string());
    if (expected != nullptr) write_png(*expected, (out / (name + ".expected.png")).string());
    if (diff != nullptr && !diff->diff.empty()) {
      write_png(diff->diff, (out / (name + ".diff.png")).string());
    }
  };
  const std::string how_to_update =
      "If the new look is intended, rerun with PCSG_UPDATE_GOLDENS=1 and review the PNGs.";
  if (!fs::exists(golden_path)) {
    write_outputs(nullptr, nullptr);
    result.message = "no golden image " + golden_path + "; the actual image is in " +
                     (out / (name + ".actual.png")).string() + ". " + how_to_update;
    return result;
  }
  const Image expected = read_png(golden_path);
  const ImageDiff diff = diff_images(expected, actual);
  result.passed = diff.passed;
  if (diff.passed) {
    result.message = golden_path + ": " + diff.summary();
    return result;
  }
  write_outputs(&expected, &diff);
  result.message =
      golden_path + " does not match: " +
      (diff.same_size
           ? diff.summary()
           : "expected " + std::to_string(expected.width) + "x" + std::to_string(expected.height) +
                 ", got " + std::to_string(actual.width) + "x" + std::to_string(actual.height)) +
      ". Actual, expected and diff images are in " + out.string() + "/" + name + ".*.png. " +
      how_to_update;
  return result;
}

}  // namespace pcsg::render
