#pragma once
// The colours of a frame: soft, clearly distinct face colours (A and B draw from separate
// lists, so no two faces of a scene share a colour and B keeps its colours whatever A is), dark
// edges, and one warning colour for the elements of a collision. Display (sRGB) values in [0, 1].
#include <Eigen/Core>

namespace pcsg::render {

struct Rgb {
  float r = 0, g = 0, b = 0;
  // Linear blend toward `o` by t in [0, 1].
  Rgb mix(const Rgb& o, float t) const {
    return {r + (o.r - r) * t, g + (o.g - g) * t, b + (o.b - b) * t};
  }
  // 32-bit ABGR as Dear ImGui packs it (IM_COL32).
  unsigned packed(float alpha = 1.f) const;
};

namespace palette {

inline constexpr Rgb kBackground{1.f, 1.f, 1.f};
inline constexpr Rgb kEdge{0.13f, 0.14f, 0.18f};
inline constexpr Rgb kWarning{0.86f, 0.12f, 0.10f};
inline constexpr Rgb kContact{0.85f, 0.10f, 0.35f};
inline constexpr Rgb kText{0.08f, 0.08f, 0.10f};
inline constexpr Rgb kLeader{0.25f, 0.26f, 0.30f};

// The colour of face i of A or of B (`of_B`), cycling after 4 per object.
Rgb face(bool of_B, int i);

// Opacity of the faces: a surface seen through two others (A inside the dish inside B) still
// shows (1 - 0.35)^2 = 42% of its colour, while a single face remains clearly tinted.
inline constexpr float kFaceAlpha = 0.35f;
// Collision elements are drawn more opaque so that they stand out even behind other faces.
inline constexpr float kWarningFaceAlpha = 0.6f;

}  // namespace palette
}  // namespace pcsg::render
