#include "app/sweep_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/contact/contact.h"

namespace pcsg::app {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double largest_residual(const std::vector<PointContact>& contacts) {
  double r = 0;
  for (const PointContact& c : contacts) {
    r = std::max(r, std::abs(c.gap));
    if (c.residual.size() > 0) r = std::max(r, c.residual.cwiseAbs().maxCoeff());
  }
  return r;
}

}  // namespace

std::vector<SweepLevel> sweep_levels(const std::vector<double>& factors, SweepVary vary) {
  const SweepLevel defaults;
  std::vector<SweepLevel> levels;
  for (double f : factors) {
    SweepLevel l = defaults;
    if (vary != SweepVary::Mesh) l.motion_step *= f;
    if (vary != SweepVary::Step) l.mesh_chordal_error *= f;
    levels.push_back(l);
  }
  return levels;
}

SweepRun run_sweep_level(const SceneSpec& spec, const SweepLevel& level, int threads,
                         GeneratorListener* listener) {
  SweepRun r;
  r.level = level;
  const auto t0 = std::chrono::steady_clock::now();
  BuildOptions build;
  build.mesh_chordal_error_relative = level.mesh_chordal_error;
  SceneGeometry scene = build_scene_geometry(spec, build);
  // the motion step is a scene tolerance (generator.h has no override): set it on this copy
  scene.tol.mesh_chordal_error = level.mesh_chordal_error * scene.tol.length_scale;
  scene.tol.motion_step = level.motion_step * scene.tol.length_scale;
  r.build_seconds = seconds_since(t0);
  r.length_scale = scene.tol.length_scale;
  r.triangles = static_cast<long>(scene.mesh_A.triangles.size() + scene.mesh_B.triangles.size());

  GeneratorOptions options;
  options.threads = threads;
  options.measure_discretisation = true;
  const auto t1 = std::chrono::steady_clock::now();
  const StateGraph g = generate_graph(scene, options, listener);
  r.generate_seconds = seconds_since(t1);

  r.states = static_cast<int>(g.states.size());
  r.links = static_cast<int>(g.links.size());
  r.collision_queries = g.stats.collision_queries;
  r.pair_solves = g.stats.pair_solves;
  r.motion_steps = g.stats.motion_steps;
  r.keep_drift = g.stats.max_keep_drift;
  r.step_penetration = g.stats.max_step_penetration;
  // the witnesses, re-checked by the exact contact computation (not the stored contacts)
  r.witness_residual = g.stats.max_witness_residual;
  for (const State& s : g.states) {
    const ContactReport rep = detect_contacts(scene, s.pose);
    r.witness_residual = std::max(r.witness_residual, largest_residual(rep.contacts));
    if (!(ContactFormation::of(rep.contacts) == s.cf) || rep.penetrating())
      ++r.witness_cf_mismatches;
  }
  r.signature = graph_signature(g, scene);
  return r;
}

}  // namespace pcsg::app
