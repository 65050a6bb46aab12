#pragma once
// Orders a solid's edges and vertices deterministically, links faces, edges and vertices to
// each other (paper Section II-D adjacency) and names them: the scene's names where given
// (EdgeNameSpec, VertexNameSpec), else generated ones, "e_f1_f2" and "v_f1_f2_f3", with "#2",
// "#3", ... for further components on the same surfaces.
#include "engine/geometry/solid.h"
#include "engine/scene/scene.h"

namespace pcsg {

// Expects faces named and edges/vertices filled (surfaces, faces, end vertices, samples).
// Throws SceneError at a named edge's (vertex's) place in the file when its faces never meet
// on the solid's boundary, or name a face the object does not have.
void name_and_link_elements(Solid& solid, const ObjectSpec& object);

}  // namespace pcsg
