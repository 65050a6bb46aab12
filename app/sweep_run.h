#pragma once
// One run of `pcsg sweep`: the generator on a scene at one resolution, with the figures that
// say how accurate and how fast it was.
#include <string>
#include <vector>

#include "app/graph_diff.h"
#include "engine/generator/generator.h"
#include "engine/scene/scene.h"

namespace pcsg::app {

// The accuracy knobs, relative to the scene's length scale L (engine/core/tolerances.h).
struct SweepLevel {
  double motion_step = 1e-2;        // Tolerances::motion_step / L
  double mesh_chordal_error = 1e-3; // Tolerances::mesh_chordal_error / L
};

// Which knobs a sweep varies: both together (the default: they trade accuracy for time in the
// same direction), or one with the other at its default.
enum class SweepVary { Both, Step, Mesh };

// One level per factor (> 0), each knob's default times the factor, in the given order.
std::vector<SweepLevel> sweep_levels(const std::vector<double>& factors, SweepVary vary);

struct SweepRun {
  SweepLevel level;
  double length_scale = 0;
  long triangles = 0;             // of both meshes
  double build_seconds = 0;       // B-reps and meshes
  double generate_seconds = 0;    // generate_graph, with the discretisation measurements
  int states = 0, links = 0;      // links: LN and GN
  long collision_queries = 0, pair_solves = 0, motion_steps = 0;
  // Errors, as lengths (divide by length_scale for the relative figures):
  double witness_residual = 0;    // largest |contact residual| re-detected at the witnesses
  int witness_cf_mismatches = 0;  // witnesses whose re-detected CF is not their state's
  double keep_drift = 0;          // largest kept-contact residual at step midpoints
  double step_penetration = 0;    // deepest penetration at step midpoints (exact surfaces)
  GraphSignature signature;
  GraphDiff diff;                 // against the reference (finest) run; set by the caller
  double total_seconds() const { return build_seconds + generate_seconds; }
};

// Builds the scene at the level's mesh resolution, generates its graph with the level's motion
// step and the discretisation measurements on, and re-checks every witness.
SweepRun run_sweep_level(const SceneSpec& spec, const SweepLevel& level, int threads,
                         GeneratorListener* listener = nullptr);

}  // namespace pcsg::app
