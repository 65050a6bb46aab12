#pragma once
// The mesh of one surface's part on a solid's boundary: the surface's marching-tetrahedra mesh
// over a box, its vertices projected exactly onto the surface, clipped against every other
// inequality of the solid. Cut points are projected exactly onto the curve where the two
// surfaces meet (or onto the point where three meet), and every vertex records which other
// surfaces it lies on, so boundary curves are known exactly and shared between neighbouring
// triangles. Used both to discover a solid's faces and edges and to mesh them.
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "engine/core/tolerances.h"
#include "engine/poly/polynomial.h"

namespace pcsg {

struct SurfacePatch {
  int surface = -1;
  std::vector<Eigen::Vector3d> positions;  // on the surface (and on the surfaces in `on`)
  std::vector<std::uint64_t> on;           // bit j: the vertex also lies on surface j
  std::vector<Eigen::Vector3i> triangles;  // counter-clockwise seen from outside the solid
};

// Most inequalities an object may have: one bit each in SurfacePatch::on.
constexpr int kMaxSurfaces = 64;

// The part of surfaces[i] = 0 inside `box` where all other surfaces[j] <= 0, meshed on a grid of
// spacing h (plus a margin of two cells so the box's boundary never cuts the patch).
SurfacePatch surface_patch(const std::vector<Polynomial>& surfaces, int i,
                           const Eigen::AlignedBox3d& box, double h, const Tolerances& tol);

// Connected components of a patch's triangles (sharing an edge); returns the label of each
// triangle, labels 0..count-1 in order of first appearance.
std::vector<int> triangle_components(const SurfacePatch& patch, int* count);

}  // namespace pcsg
