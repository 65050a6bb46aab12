#pragma once
// The paper's objects are strictly curved: "no line segment on their boundary surfaces"
// (Section I). Rejects any face whose patch holds a straight segment.
#include "engine/core/tolerances.h"
#include "engine/geometry/solid.h"
#include "engine/scene/scene.h"

namespace pcsg {

// Throws SceneError at the face's place in the file, naming the face, its inequality and the
// segment's point and direction, when a face's surface holds a straight line through one of
// its patch samples (planes, cylinders, cones, one-sheet hyperboloids, hyperbolic paraboloids).
void check_strictly_curved(const Solid& solid, const ObjectSpec& object, const Tolerances& tol);

}  // namespace pcsg
