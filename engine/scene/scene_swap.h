#pragma once
// Swapping the roles of the two objects, for the metamorphic test "swapping A and B gives the
// mirrored graph": every f-e contact becomes e-f, slidingA becomes slidingB.
#include "engine/scene/scene.h"

namespace pcsg {

// The same two solids with A and B exchanged. B's faces are written in the world frame and
// A's in A's own frame, so the polynomials carry over unchanged: the new A is the old B in its
// (old world) frame, the new B is the old A in its (old own) frame, which becomes the world.
// Element names are kept (they do not depend on the object's role). Listed seeds invert: a
// pose X_BA of the old A becomes X_AB = X_BA^-1, the pose of the old B in the old A's frame.
// Swapping twice gives back the scene (seeds up to round-off).
SceneSpec swap_objects(const SceneSpec& scene);

}  // namespace pcsg
