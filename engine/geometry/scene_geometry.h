#pragma once
// A scene ready for computation: both solids' boundary representations, their meshes and the
// scene's tolerances. Built once from a SceneSpec; read-only (and thread-safe to share) after.
#include <string>
#include <vector>

#include "engine/core/tolerances.h"
#include "engine/geometry/mesh.h"
#include "engine/geometry/solid.h"
#include "engine/scene/scene.h"

namespace pcsg {

struct BuildOptions {
  // Relative chordal error of the meshes (times the length scale); 0 keeps the default of
  // Tolerances::mesh_chordal_error.
  double mesh_chordal_error_relative = 0;
};

struct SceneGeometry {
  SceneSpec spec;
  Solid A, B;                 // A in its own frame, B in the world frame
  Tolerances tol;             // from length_scale = larger bbox diagonal of A and B
  SolidMesh mesh_A, mesh_B;   // for collision checks and rendering only
  std::vector<std::string> warnings;  // e.g. an inequality that contributes no face
};

// Derives the B-reps, validates them (throws SceneError naming the file, face and value for
// straight segments, empty or unbounded solids, tangential face meetings, unknown named edges)
// and meshes them.
SceneGeometry build_scene_geometry(const SceneSpec& spec, const BuildOptions& options = {});

}  // namespace pcsg
