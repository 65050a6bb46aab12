#pragma once
// Meshes a solid's B-rep for collision checks and rendering (exact geometry decides contacts).
//
// Each face is meshed on its own grid (spacing from the chordal error and the face's largest
// curvature) by marching tetrahedra on its surface, with vertices projected exactly onto it, and
// clipped against the solid's other inequalities with cut points projected exactly onto the
// edge curves (geometry/surface_patch.h). The faces are then stitched along each edge: the
// boundary points of both faces on the edge are merged into one ordered set of exact curve
// points (close pairs unified), and each face's boundary triangles are split so that both faces
// use exactly that set. The result is conforming, and watertight when every face's patch was
// resolved by its grid.
#include "engine/core/tolerances.h"
#include "engine/geometry/mesh.h"
#include "engine/geometry/solid.h"

namespace pcsg {

// `chordal_error` (> 0, a length) bounds the distance between a triangle and the surface
// (estimated from the face's largest curvature: edge length <= sqrt(8 chordal_error / kappa)).
// Deterministic: the same solid gives the same mesh.
SolidMesh mesh_solid(const Solid& solid, double chordal_error, const Tolerances& tol);

}  // namespace pcsg
