#pragma once
// A solid's boundary representation from its inequalities (paper Section II-A): faces are the
// connected patches of each surface on the solid's boundary, edges the connected curves where
// two faces meet, vertices the points where three or more surfaces meet on the boundary.
//
// Discovery runs on a coarse grid (Tolerances::discovery_cells across the solid's box, and at
// least discovery_cells_across across its thickness, geometry/solid_extent.h): each
// surface is meshed and clipped against the other inequalities (geometry/surface_patch.h); the
// clipped pieces' connected components are the faces, and their cut points seed the edges,
// which are then traced exactly (geometry/edge_tracer.h) until they close or end at vertices.
#include <string>
#include <vector>

#include "engine/geometry/solid.h"
#include "engine/scene/scene.h"

namespace pcsg {

// Builds object's solid in its own frame, its surfaces expanded about a point near it
// (Polynomial::recentred). Throws SceneError naming the file, line and value for an empty,
// unbounded or too thin solid (at the object), two faces meeting tangentially (at the first
// face), an edge that cannot be traced, and named edges or vertices that do not exist (at the
// name). Appends a warning for every inequality that contributes no face.
Solid build_solid(const ObjectSpec& object, std::vector<std::string>* warnings);

}  // namespace pcsg
