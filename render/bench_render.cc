// Time of one 1280x960 frame (4x MSAA, transparency sort, labels, header, contact markers and
// normals) with the context and meshes kept alive across frames, as pcsg draws the many states
// of a graph. Reports wall time (the default) and the process's CPU time per frame: llvmpipe
// rasterises on all cores, so on a busy machine the two differ.
#include <benchmark/benchmark.h>

#include <cmath>
#include <ctime>

#include "engine/contact/contact.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"
#include "render/scene_renderer.h"
#include "tests/render/test_meshes.h"

namespace pcsg::render {
namespace {

void run_frames(benchmark::State& state, SceneRenderer& renderer, const FrameRequest& f) {
  renderer.render(f);  // warm-up: allocates the targets at this size, compiles the shaders
  const std::clock_t cpu0 = std::clock();
  for (auto _ : state) {
    Image image = renderer.render(f);
    benchmark::DoNotOptimize(image.rgba.data());
  }
  const double cpu_ms = 1000.0 * static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  state.counters["cpu_ms_per_frame"] = cpu_ms / static_cast<double>(state.iterations());
}

// Paper Fig. 5b: the ellipsoid resting in the dish, two contacts; ~38k triangles.
void BM_RenderFrame1280x960Example1(benchmark::State& state) {
  const SceneGeometry scene =
      build_scene_geometry(load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/example1.yaml"));
  SceneRenderer renderer(scene);
  FrameRequest f;
  f.title = scene.spec.name;
  f.subtitle = "{(fA-f1, 2)}";
  Pose X;
  X.position = Eigen::Vector3d(0, 0, 1.1441375859758451);
  X.quaternion = Eigen::Quaterniond(std::sqrt(0.5), std::sqrt(0.5), 0, 0);
  f.X_BA = X;
  f.contacts = detect_contacts(scene, X).contacts;
  f.show_normals = true;
  run_frames(state, renderer, f);
}
BENCHMARK(BM_RenderFrame1280x960Example1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The hand-built scene of the tests (~17k triangles), independent of the geometry kernel.
void BM_RenderFrame1280x960Synthetic(benchmark::State& state) {
  const SceneGeometry scene = testing::synthetic_scene();
  SceneRenderer renderer(scene);
  FrameRequest f;
  f.X_BA = testing::synthetic_resting_pose();
  f.title = scene.spec.name;
  f.subtitle = "{(fA-f1, 1)}";
  PointContact c;
  c.point_B = Eigen::Vector3d(0, 0, 1.4);
  c.normal_B = Eigen::Vector3d::UnitZ();
  f.contacts = {c};
  f.show_normals = true;
  run_frames(state, renderer, f);
}
BENCHMARK(BM_RenderFrame1280x960Synthetic)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace pcsg::render

BENCHMARK_MAIN();
