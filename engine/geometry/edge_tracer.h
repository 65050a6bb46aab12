#pragma once
// Follows the curve where two surfaces of a solid meet, inside the solid, from one exact point
// of it: predictor steps along the curve's tangent, each corrected by Newton projection onto
// both surfaces, until the curve closes or leaves the solid through a third surface (a vertex).
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "engine/core/tolerances.h"
#include "engine/geometry/solid.h"
#include "engine/poly/polynomial.h"

namespace pcsg {

struct TracedCurve {
  // Exact samples ordered along grad g_a x grad g_b, with arc lengths; an open curve starts and
  // ends on its vertices. Spacing: at most tol.edge_sample_step, and at most
  // tol.edge_sample_turn radians of tangent turn.
  std::vector<CurveSample> samples;
  bool closed = false;
  // For an open curve, the surface through which it leaves the solid at its first and last
  // sample (the third surface of each end vertex).
  int end_surface[2] = {-1, -1};
  double length = 0;  // for a closed curve, including the closing segment
};

// Traces the component of g_a = g_b = 0 (a < b) inside the solid { g_i <= 0 } through `seed`.
// Returns false with a reason (naming the point) when the curve cannot be followed; sets
// *tangential_at when the two surfaces turn out to meet tangentially (their normals' sine below
// tol.tangential_sine), which is a scene error for the caller to report.
bool trace_curve(const std::vector<Polynomial>& surfaces, int a, int b,
                 const Eigen::Vector3d& seed, const Tolerances& tol, TracedCurve* out,
                 std::string* reason, Eigen::Vector3d* tangential_at);

// Arc length between two curve samples from their chord and tangents: chord * (theta/2) /
// sin(theta/2), exact on circular arcs and accurate to O(h^4) on smooth curves.
double arc_length(const Eigen::Vector3d& p0, const Eigen::Vector3d& t0,
                  const Eigen::Vector3d& p1, const Eigen::Vector3d& t1);

// Distance from p to the polyline of a curve's samples (closing segment included when closed).
double distance_to_samples(const std::vector<CurveSample>& samples, bool closed,
                           const Eigen::Vector3d& p);

}  // namespace pcsg
