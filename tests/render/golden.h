#pragma once
// Golden-image checks for the render tests: compares with screenshots/<name>.png; on failure
// the actual, expected and diff images go to $PCSG_TEST_OUTPUT/render (build/tests-output/
// render under CTest). To accept a new look on purpose:
//   PCSG_UPDATE_GOLDENS=1 ./build/tests/pcsg_render_tests   (then review screenshots/*.png)
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "render/embedded_resources.h"
#include "render/image_diff.h"

namespace pcsg::render::testing {

inline bool update_goldens() {
  const char* v = std::getenv("PCSG_UPDATE_GOLDENS");
  return v != nullptr && std::string(v) == "1";
}

inline std::string test_output_dir() {
  const char* v = std::getenv("PCSG_TEST_OUTPUT");
  return std::string(v != nullptr ? v : PCSG_BINARY_DIR "/tests-output") + "/render";
}

// Goldens are drawn with the embedded DejaVu Sans; without it every label differs.
#define PCSG_SKIP_WITHOUT_LABEL_FONT()                                                          \
  if (!::pcsg::render::has_label_font()) {                                                      \
    GTEST_SKIP() << "built without DejaVuSans.ttf (fonts-dejavu-core): goldens not comparable"; \
  }

inline void expect_matches_golden(const Image& actual, const std::string& name) {
  const std::string golden = std::string(PCSG_SOURCE_DIR) + "/screenshots/" + name + ".png";
  const GoldenCheck r = check_golden(actual, golden, test_output_dir(), update_goldens());
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace pcsg::render::testing
