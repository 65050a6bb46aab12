// Session 40's driver (not built by CMake): generates a scene with B's frame moved as
// Generator.StatesAreIdenticalUnderRigidMotion moves it (0.7 rad about (1, 2, 2), then
// (3, -2, 5)), or scaled, and writes graph.json. Build from the repository root after a build:
//   g++ -I. -isystem /usr/include/eigen3 -O2 -DNDEBUG -std=c++20 \
//     docs/experiments/generate_moved.cc -o /tmp/generate_moved build/engine/libpcsg_generator.a \
//     build/engine/libpcsg_contact.a build/engine/libpcsg_geometry.a \
//     $(ls build/engine/*.a | grep -v -e generator -e contact -e geometry) \
//     -lfcl -lyaml-cpp -lccd -lpthread
//   /tmp/generate_moved scenes/example1.yaml moved|1e-3|1e3|none OUT.json [complete]
// ("complete": GeneratorOptions::complete_search)
#include <cstdio>
#include <fstream>
#include <string>

#include "engine/generator/generator.h"
#include "engine/generator/graph_io.h"
#include "engine/scene/scene.h"
using namespace pcsg;
int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "generate_moved SCENE moved|1e-3|1e3|none OUT.json\n");
    return 2;
  }
  SceneSpec spec = load_scene_file(argv[1]);
  const std::string how = argv[2];
  if (how == "moved") {
    Pose X;
    X.position = {3.0, -2.0, 5.0};
    X.quaternion =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 2).normalized()));
    spec = moved_scene(spec, X);
  } else if (how != "none") {
    spec = scaled_scene(spec, std::stod(how));
  }
  const SceneGeometry scene = build_scene_geometry(spec);
  GeneratorOptions opt;
  opt.threads = 2;
  opt.complete_search = argc > 4 && std::string(argv[4]) == "complete";
  const StateGraph g = generate_graph(scene, opt);
  std::ofstream(argv[3]) << graph_to_json(g, scene);
  std::fprintf(stderr, "%zu states, %zu links\n", g.states.size(), g.links.size());
}
