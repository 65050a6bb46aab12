// Session 40's join driver (not built by CMake): whether two witnesses of one CF are joined,
// by each of the generator's joins (joined_within_cf, joined_by_parameter_path,
// joined_by_tangent_walk since session 52, joined_by_roadmap). Build like replay_hypothesis.cc; run:
//   /tmp/join scenes/example1.yaml "X Y Z QW QX QY QZ" "X Y Z QW QX QY QZ" [moved1|none] [LEVELS]
// (poses X_BA as in graph.json; "moved1" moves B as generate_moved.cc does).
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "engine/contact/contact.h"
#include "engine/generator/cf_parameter_path.h"
#include "engine/generator/state_identity.h"
#include "engine/scene/scene.h"
using namespace pcsg;
int main(int argc, char** argv) {
  if (argc < 4) return 2;
  SceneSpec spec = load_scene_file(argv[1]);
  if (argc > 4 && std::string(argv[4]) == "moved1") {
    Pose X;
    X.position = {3.0, -2.0, 5.0};
    X.quaternion =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 2).normalized()));
    spec = moved_scene(spec, X);
  }
  const SceneGeometry scene = build_scene_geometry(spec);
  const Pose a = parse_pose(argv[2]), b = parse_pose(argv[3]);
  const ContactReport ra = detect_contacts(scene, a), rb = detect_contacts(scene, b);
  const ContactFormation cf = ContactFormation::of(ra.contacts);
  std::printf("a: %s (pen %d)  b: %s (pen %d)\n", cf.str(scene).c_str(), (int)ra.penetrating(),
              ContactFormation::of(rb.contacts).str(scene).c_str(), (int)rb.penetrating());
  const SceneSymmetry sym = SceneSymmetry::of(scene);
  MotionCounters c1, c2, c3;
  for (int levels = 1; levels <= (argc > 5 ? std::atoi(argv[5]) : 1); ++levels)
    std::printf("joined_within_cf (midpoint levels %d) %d\n", levels,
                (int)joined_within_cf(scene, a, b, cf, c1, sym, levels));
  std::printf("joined_by_parameter_path %d\n",
              (int)joined_by_parameter_path(scene, a, b, cf, c2, sym));
  MotionCounters c5;
  std::printf("joined_by_tangent_walk %d\n", (int)joined_by_tangent_walk(scene, a, b, cf, c5, sym));
  RoadmapStats st;
  {
    // the roadmap from a turned by the solids' symmetries toward b (every contact kept)
    const Pose aligned = aligned_by_symmetry(scene, a, b, sym);
    MotionCounters c4;
    RoadmapStats st2;
    const bool joined =
        joined_by_roadmap(scene, aligned, b, cf, region_signature(ra.contacts), c4, &st2);
    std::printf("joined_by_roadmap from a aligned %d (nodes %d motions %d)\n", (int)joined,
                st2.nodes, st2.motions);
  }
  std::printf("joined_by_roadmap %d (nodes %d motions %d)\n",
              (int)joined_by_roadmap(scene, a, b, cf, region_signature(ra.contacts), c3, &st),
              st.nodes, st.motions);
}
