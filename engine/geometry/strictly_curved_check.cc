#include "engine/geometry/strictly_curved_check.h"

#include <cstdio>

#include "engine/geometry/straight_line.h"

namespace pcsg {
namespace {

// Patch samples tested per face: a ruled surface has lines through every point, so a few
// hundred well-spread samples find one; testing all ~10^3-10^4 would only cost time.
constexpr std::size_t kSamplesPerFace = 200;

std::string vec_str(const Eigen::Vector3d& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
  return buf;
}

}  // namespace

void check_strictly_curved(const Solid& solid, const ObjectSpec& object, const Tolerances& tol) {
  for (const Face& f : solid.faces) {
    std::vector<Eigen::Vector3d> pts;
    const std::size_t stride = std::max<std::size_t>(1, f.samples.size() / kSamplesPerFace);
    for (std::size_t k = 0; k < f.samples.size(); k += stride) pts.push_back(f.samples[k]);
    const auto line = find_straight_line(solid.surfaces[f.surface], pts, tol.length_scale);
    if (!line) continue;
    const FaceSpec& spec = object.faces[f.surface];
    throw SceneError(spec.where,
                     "face " + f.name + " ('" + spec.text + "') of object " + object.name +
                         " contains a straight segment through " + vec_str(line->point) +
                         " along " + vec_str(line->direction) +
                         "; pcsg needs strictly curved objects (no planes, cylinders, cones, "
                         "one-sheet hyperboloids or hyperbolic paraboloids)");
  }
}

}  // namespace pcsg
