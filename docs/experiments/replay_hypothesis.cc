// Session 39's replay driver (not built by CMake): from a witness pose, the hypothesis toward a
// CF, tried as the generator tries it (try_hypothesis: every start, plan and variant), with the
// outcome and reasons. It includes generator.cc to reach its internal functions. Build from
// the repository root after a Release build:
//   g++ -I. -isystem /usr/include/eigen3 -O2 -DNDEBUG -std=c++20 \
//     docs/experiments/replay_hypothesis.cc -o /tmp/replay build/engine/libpcsg_generator.a \
//     build/engine/libpcsg_contact.a build/engine/libpcsg_geometry.a \
//     $(ls build/engine/*.a | grep -v -e generator -e contact -e geometry) \
//     -lfcl -lyaml-cpp -lccd -lpthread
//   /tmp/replay scenes/example2.yaml X Y Z QW QX QY QZ "{(eA-f2, 1)}" [moved|moved1]
// (the pose X_BA as in graph.json; "moved" maps it by example2_moved.yaml's (R, t) first;
// "moved1" moves B as generate_moved.cc does, the pose given in the moved frame). Every run
// is then listed as try_hypothesis would try it.
#include <cstdio>

#include "engine/generator/generator.cc"
using namespace pcsg;
int main(int argc, char** argv) {
  if (argc < 10) {
    std::fprintf(stderr, "dbg scene px py pz qw qx qy qz CF [moved]\n");
    return 2;
  }
  SceneSpec spec = load_scene_file(argv[1]);
  if (argc > 10 && std::string(argv[10]) == "moved1") {  // generate_moved.cc's motion of B
    Pose X;
    X.position = {3.0, -2.0, 5.0};
    X.quaternion =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 2).normalized()));
    spec = moved_scene(spec, X);
  }
  SceneGeometry scene = build_scene_geometry(spec);
  Pose p;
  p.position = {atof(argv[2]), atof(argv[3]), atof(argv[4])};
  p.quaternion =
      Eigen::Quaterniond(atof(argv[5]), atof(argv[6]), atof(argv[7]), atof(argv[8])).normalized();
  if (argc > 10 && std::string(argv[10]) == "moved") {
    Eigen::Matrix3d R;
    R << 0.6, -0.224, 0.768, 0.8, 0.168, -0.576, 0, 0.96, 0.28;
    Eigen::Vector3d t(0.5, -0.25, 0.125);
    p.position = R * p.position + t;
    p.quaternion = (Eigen::Quaterniond(R) * p.quaternion).normalized();
    if (p.quaternion.w() < 0) p.quaternion.coeffs() *= -1;
  }
  ContactReport rep = detect_contacts(scene, p);
  std::printf("pose %.9f %.9f %.9f  %.9f %.9f %.9f %.9f penetrating %d\n", p.position.x(),
              p.position.y(), p.position.z(), p.quaternion.w(), p.quaternion.x(), p.quaternion.y(),
              p.quaternion.z(), (int)rep.penetrating());
  ContactFormation cf = ContactFormation::of(rep.contacts);
  std::printf("CF %s\n", cf.str(scene).c_str());
  ContactFormation want = ContactFormation::parse(argv[9], scene);
  State s;
  s.id = 0;
  s.cf = cf;
  s.pose = p;
  s.contacts = rep.contacts;
  for (const Hypothesis& h : hypothesise_ln(scene, rep.contacts, /*complete=*/true)) {
    if (!(h.cf == want)) continue;
    std::printf("hypothesis %s: %zu plans\n", h.cf.str(scene).c_str(), h.plan_options.size());
    TryResult r = try_hypothesis(scene, s, h, false, /*complete=*/true);
    // Every run, as try_hypothesis would try it (without its early stops).
    MotionStarts starts(scene, s, h);
    const std::vector<MotionVariant> variants = motion_variants();
    MotionCounters counters;
    for (size_t k = 0; k < starts.size(); ++k) {
      const MotionStart& start = starts.at(k, counters);
      if (!start.ok) continue;
      for (size_t pl = 0; pl < h.plan_options.size(); ++pl)
        for (size_t v = 0; v < variants.size(); ++v) {
          if (!variant_matters(variants[v], h.plan_options[pl], start.contacts)) continue;
          MotionOutcome o = run_transition_motion(scene, start.pose, start.contacts,
                                                  h.plan_options[pl], h.cf, variants[v], counters);
          std::printf("  run %zu/%zu/%zu %s%s: feasible %d general stop %d steps %d %s\n", k, pl, v,
                      start.prefix.c_str(), o.motion.c_str(), (int)o.feasible,
                      (int)o.general_stop, o.steps, o.reason.c_str());
          if (o.feasible)
            std::printf("    end %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", o.end.position.x(),
                        o.end.position.y(), o.end.position.z(), o.end.quaternion.w(),
                        o.end.quaternion.x(), o.end.quaternion.y(), o.end.quaternion.z());
        }
    }
    for (auto& t : r.targets)
      std::printf("  feasible %d motion %s run %d/%d/%d attempts %d\n  reason: %s\n",
                  (int)t.candidate.feasible, t.candidate.motion.c_str(), t.candidate.run.start,
                  t.candidate.run.plan, t.candidate.run.variant, t.candidate.attempts,
                  t.candidate.reason.c_str());
  }
}
