#pragma once
// An element (face, edge or vertex) of one of the two objects, as the renderer names it for
// highlighting, labels and the element-id pass.
#include <cstdint>

#include "engine/geometry/solid.h"

namespace pcsg::render {

enum class Object { A, B };

struct SceneElement {
  Object object = Object::A;
  ElementId element;
  bool operator==(const SceneElement& o) const {
    return object == o.object && element == o.element;
  }
};

// The element-id pass writes one integer per pixel: 0 for the background, otherwise
// 1 + object bit + kind bits + index (indices below 2^10 per solid and kind).
namespace element_id {
inline constexpr std::int32_t kBackground = 0;
inline constexpr std::int32_t kMaxIndex = 1 << 10;
inline constexpr std::int32_t kKindShift = 10;  // two bits: face 0, edge 1, vertex 2
inline constexpr std::int32_t kObjectBit = 1 << 12;

inline std::int32_t base(Object object, ElementKind kind) {
  return 1 + (object == Object::B ? kObjectBit : 0) +
         (static_cast<std::int32_t>(kind) << kKindShift);
}
inline std::int32_t encode(const SceneElement& e) {
  return base(e.object, e.element.kind) + e.element.index;
}
inline SceneElement decode(std::int32_t id) {
  const std::int32_t v = id - 1;
  SceneElement e;
  e.object = (v & kObjectBit) != 0 ? Object::B : Object::A;
  e.element.kind = static_cast<ElementKind>((v >> kKindShift) & 3);
  e.element.index = v & (kMaxIndex - 1);
  return e;
}
}  // namespace element_id

}  // namespace pcsg::render
