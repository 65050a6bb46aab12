// Session 48's driver (not built by CMake): a witness whose edge contact lies on its normal
// cone's boundary (the normal within ~1e-6 rad of a face's), pushed into the cone's interior:
// A turned about the edge's tangent through the contact point by +-0.003 to +-0.1 rad, projected
// back onto the CF (project_onto_cf), each result's smallest cone margin printed with whether
// it joins the witness (connected_within_cf either way) and whether it joins the second pose
// (joined_by_parameter_path, joined_within_cf, joined_by_roadmap from it aligned by symmetry).
// Build like replay_hypothesis.cc; run:
//   /tmp/interior scenes/stress/needle_far_rotated.yaml "X Y Z QW QX QY QZ" "X Y Z QW QX QY QZ"
// (poses X_BA as in graph.json; the first holds the boundary witness).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "engine/contact/contact.h"
#include "engine/generator/cf_parameter_path.h"
#include "engine/generator/state_identity.h"
#include "engine/generator/symmetry.h"
#include "engine/scene/scene.h"
using namespace pcsg;
static double margin(const SceneGeometry& scene, const PointContact& c) {
  if (c.b.kind != ElementKind::Edge) return 1;
  const Solid& S = scene.B;
  double m = 10;
  for (int s : {S.edges[c.b.index].surface1, S.edges[c.b.index].surface2}) {
    Eigen::Vector3d g = S.surfaces[s].gradient(c.p_B).normalized();
    m = std::min(m, std::acos(std::clamp(g.dot(c.normal_B), -1.0, 1.0)));
  }
  return m;
}
int main(int argc, char** argv) {
  SceneSpec spec = load_scene_file(argv[1]);
  const SceneGeometry scene = build_scene_geometry(spec);
  const Pose a = parse_pose(argv[2]), b = parse_pose(argv[3]);
  const ContactReport ra = detect_contacts(scene, a);
  const ContactFormation cf = ContactFormation::of(ra.contacts);
  const SceneSymmetry sym = SceneSymmetry::of(scene);
  int e = -1;
  for (size_t k = 0; k < ra.contacts.size(); ++k)
    if (ra.contacts[k].b.kind == ElementKind::Edge) e = k;
  const PointContact& c = ra.contacts[e];
  std::printf("a margin %.3g\n", margin(scene, c));
  for (double d : {0.003, -0.003, 0.01, -0.01, 0.03, -0.03, 0.1, -0.1}) {
    Pose t = turned_about_B(a, {c.point_B, c.tangent_b_B}, d);
    ProjectionResult p = project_onto_cf(scene, t, cf);
    if (!p.ok) {
      std::printf("d %g: projection failed: %s\n", d, p.reason.c_str());
      continue;
    }
    double m = 10;
    for (auto& q : p.contacts) m = std::min(m, margin(scene, q));
    MotionCounters k1, k2;
    bool j1 = connected_within_cf(scene, a, p.pose, cf, k1) ||
              connected_within_cf(scene, p.pose, a, cf, k1);
    bool j2 = joined_by_parameter_path(scene, p.pose, b, cf, k2, sym);
    MotionCounters k3, k4;
    RoadmapStats st;
    bool j3 = joined_within_cf(scene, p.pose, b, cf, k3, sym, 1);
    bool j4 = j1 && joined_by_roadmap(scene, aligned_by_symmetry(scene, p.pose, b, sym), b, cf,
                                      region_signature(p.contacts), k4, &st);
    std::printf("d %g: margin %.3g  a<->a' %d  a'->b path %d within %d roadmap %d (%d nodes)\n", d,
                m, j1, j2, j3, j4, st.nodes);
  }
}
