#pragma once
// Measures of a solid's mesh: its topology (is it closed and consistently oriented?), its
// volume, and the faces' areas refined toward the exact surfaces.
#include <vector>

#include "engine/core/tolerances.h"
#include "engine/geometry/mesh.h"
#include "engine/geometry/solid.h"

namespace pcsg {

struct MeshTopology {
  int edges = 0;              // distinct undirected mesh edges
  int boundary_edges = 0;     // used by one triangle: a hole
  int nonmanifold_edges = 0;  // used by three or more triangles
  int misoriented_edges = 0;  // used twice in the same direction
  // Closed, two triangles per edge, each edge once in each direction.
  bool watertight() const {
    return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0;
  }
};
MeshTopology mesh_topology(const SolidMesh& mesh);

// Signed volume enclosed by the mesh (positive for outward orientation).
double mesh_volume(const SolidMesh& mesh);

// Area of each of the solid's faces from its mesh: the triangles' area, and again with every
// triangle split in four at its sides' midpoints projected exactly onto the face (or onto the
// edge curve for sides along an edge), Richardson-extrapolated as (4 A_fine - A_coarse) / 3.
// The inscribed-area error, O(h^2), drops to O(h^4): ~1e-6 relative at the default chordal error.
std::vector<double> face_areas(const Solid& solid, const SolidMesh& mesh);

}  // namespace pcsg
