#include "engine/geometry/scene_geometry.h"

#include <algorithm>

#include "engine/geometry/brep_builder.h"
#include "engine/geometry/mesh_measures.h"
#include "engine/geometry/mesher.h"
#include "engine/geometry/strictly_curved_check.h"

namespace pcsg {

SceneGeometry build_scene_geometry(const SceneSpec& spec, const BuildOptions& options) {
  SceneGeometry g;
  g.spec = spec;
  // B-reps first, each in its own frame with its own tolerances; then the scene's length scale
  g.A = build_solid(spec.A, &g.warnings);
  g.B = build_solid(spec.B, &g.warnings);
  const double L = std::max(g.A.bbox.diagonal().norm(), g.B.bbox.diagonal().norm());
  g.tol = Tolerances::for_length_scale(L);
  check_strictly_curved(g.A, spec.A, g.tol);
  check_strictly_curved(g.B, spec.B, g.tol);
  const double chordal = options.mesh_chordal_error_relative > 0
                             ? options.mesh_chordal_error_relative * L
                             : g.tol.mesh_chordal_error;
  g.mesh_A = mesh_solid(g.A, chordal, g.tol);
  g.mesh_B = mesh_solid(g.B, chordal, g.tol);
  // face areas from the meshes, refined toward the exact surfaces
  for (auto [solid, mesh] : {std::pair{&g.A, &g.mesh_A}, std::pair{&g.B, &g.mesh_B}}) {
    const std::vector<double> areas = face_areas(*solid, *mesh);
    for (std::size_t f = 0; f < areas.size(); ++f) solid->faces[f].area = areas[f];
  }
  return g;
}

}  // namespace pcsg
