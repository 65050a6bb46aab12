#include "render/palette.h"

#include <algorithm>
#include <array>

namespace pcsg::render {

unsigned Rgb::packed(float alpha) const {
  auto byte = [](float v) { return static_cast<unsigned>(std::clamp(v, 0.f, 1.f) * 255.f + 0.5f); };
  return (byte(alpha) << 24) | (byte(b) << 16) | (byte(g) << 8) | byte(r);
}

namespace palette {

Rgb face(bool of_B, int i) {
  // Pastel hues, none close to the red warning colour: warm ones for A (the moving object),
  // cool and green ones for B, so that A stands out inside B.
  static constexpr std::array<Rgb, 4> kA = {{
      {0.98f, 0.62f, 0.24f},  // orange
      {0.92f, 0.52f, 0.74f},  // pink
      {0.96f, 0.80f, 0.26f},  // yellow
      {0.62f, 0.66f, 0.40f},  // olive
  }};
  static constexpr std::array<Rgb, 4> kB = {{
      {0.36f, 0.58f, 0.92f},  // blue
      {0.42f, 0.78f, 0.46f},  // green
      {0.70f, 0.52f, 0.90f},  // violet
      {0.30f, 0.76f, 0.78f},  // teal
  }};
  const auto k = static_cast<std::size_t>(i);
  return of_B ? kB[k % kB.size()] : kA[k % kA.size()];
}

}  // namespace palette
}  // namespace pcsg::render
