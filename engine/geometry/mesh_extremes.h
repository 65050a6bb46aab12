#pragma once
// Tips that the meshing grid cuts off. Marching tetrahedra sees a solid only at its grid's
// points: where a face narrows to a tip thinner than a cell (a needle's ends, radius of
// curvature 2.5e-4 against cells of 6e-3, scenes/stress/needle_in_dish.yaml) the mesh ends up
// to a few cells short of the exact surface, and inflating the mesh along its vertex normals
// (sideways at such a tip) does not reach the lost end. The collision checks then miss
// penetrations of the tip (measured: 1.3e-3 deep, reported as apart).
//
// The remedy here: along a fixed set of directions (the solid frame's axes and the mesh's
// principal axes, both ways), the exact extreme point of each face is solved for on the smooth
// surface; where it lies beyond the mesh by more than half the chordal error, it becomes a mesh
// vertex, joined to the rim of the mesh triangles it sees (one step of an incremental convex
// hull: a cut tip is convex).
#include "engine/core/tolerances.h"
#include "engine/geometry/mesh.h"
#include "engine/geometry/solid.h"

namespace pcsg {

// Adds the missing extreme points to `mesh` (built for `solid`). Deterministic. Returns the
// number of points added.
int cover_extremes(const Solid& solid, SolidMesh& mesh, const Tolerances& tol);

}  // namespace pcsg
