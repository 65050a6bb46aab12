#include "engine/scene/scene_swap.h"

#include <string_view>
#include <utility>

namespace pcsg {
namespace {

constexpr std::string_view kSwappedSuffix = " (A and B swapped)";

}  // namespace

SceneSpec swap_objects(const SceneSpec& scene) {
  SceneSpec out = scene;
  std::swap(out.A, out.B);
  out.A.name = "A";
  out.B.name = "B";
  // the name says what happened, and swapping back restores it
  const std::string& n = scene.name;
  if (n.size() >= kSwappedSuffix.size() &&
      n.compare(n.size() - kSwappedSuffix.size(), kSwappedSuffix.size(), kSwappedSuffix) == 0)
    out.name = n.substr(0, n.size() - kSwappedSuffix.size());
  else
    out.name = n + std::string(kSwappedSuffix);
  for (SeedSpec& seed : out.seeds)
    seed.pose = seed.pose.inverse().canonical();  // canonical: equal poses print equally
  return out;
}

}  // namespace pcsg
