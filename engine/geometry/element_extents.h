#pragma once
// Exact extents of a solid's boundary elements: bounding boxes whose extremes are refined onto
// the true critical points (a paraboloid's tip, the top of an edge), edge lengths, faces'
// interior points and largest curvatures.
#include "engine/core/tolerances.h"
#include "engine/geometry/solid.h"

namespace pcsg {

// An edge's box: its samples, each extreme refined by Newton on g_a = g_b = 0 with the curve's
// tangent orthogonal to the axis (the Lagrange condition of an extreme on the curve).
Eigen::AlignedBox3d edge_bbox(const std::vector<Polynomial>& surfaces, const Edge& edge,
                              const Tolerances& tol);

// Fills each face's bbox (its samples, its edges' boxes and the interior critical points of
// each coordinate, where grad g is parallel to the axis), interior_point (the sample farthest
// inside the other inequalities) and max_curvature. Needs the edges' boxes. `search_radius`
// bounds how far a refined critical point may lie from the sample it started from.
void compute_face_extents(Solid& solid, double search_radius, const Tolerances& tol);

}  // namespace pcsg
