#include "engine/geometry/edge_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "engine/geometry/surface.h"

namespace pcsg {
namespace {

// The step may shrink to this fraction of tol.edge_sample_step before the curve is declared
// impossible to follow (2^-20: a singular point of the curve, not a sharp bend).
constexpr double kMinStepFraction = 1e-6;
// Samples per curve before giving up: 10^6 steps of the smallest regular size would cover far
// more than any bounded solid's edges; hitting it means the curve did not close.
constexpr int kMaxSamples = 1000000;

std::string point_str(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return buf;
}

// The most violated other inequality at p: (index, g / |grad g|), index -1 when none.
std::pair<int, double> worst_other(const std::vector<Polynomial>& gs, int a, int b,
                                   const Eigen::Vector3d& p) {
  std::pair<int, double> w{-1, -std::numeric_limits<double>::infinity()};
  for (int k = 0; k < static_cast<int>(gs.size()); ++k) {
    if (k == a || k == b) continue;
    double v = 0;
    Eigen::Vector3d grad;
    gs[k].evaluate(p, &v, &grad, nullptr);
    const double m = v / std::max(grad.norm(), std::numeric_limits<double>::min());
    if (m > w.second) w = {k, m};
  }
  return w;
}

struct Tracer {
  const std::vector<Polynomial>& gs;
  int a, b;
  const Tolerances& tol;
  std::string* reason;
  Eigen::Vector3d* tangential_at;

  bool tangential(const Eigen::Vector3d& p) const {
    if (normals_sine(gs[a], gs[b], p) >= tol.tangential_sine) return false;
    *tangential_at = p;
    return true;
  }

  // Follows the curve from `seed` in direction `dir` (+1 along grad a x grad b). Appends the
  // points after the seed; returns the end surface (-1 when the curve closed back on the seed).
  bool walk(const Eigen::Vector3d& seed, int dir, std::vector<Eigen::Vector3d>* pts,
            int* end_surface, bool* closed) const {
    const double h_max = tol.edge_sample_step, h_min = kMinStepFraction * h_max;
    const double cos_turn = std::cos(tol.edge_sample_turn);
    Eigen::Vector3d p = seed, t = dir * curve_tangent(gs[a], gs[b], seed);
    double h = h_max, travelled = 0;
    *closed = false;
    *end_surface = -1;
    for (int n = 0; n < kMaxSamples; ++n) {
      const Projection pr = project_onto_curve(gs[a], gs[b], p + h * t, tol);
      const Eigen::Vector3d q = pr.point;
      const Eigen::Vector3d tq = dir * curve_tangent(gs[a], gs[b], q);
      const double chord = (q - p).norm();
      // reject steps that did not converge, jumped to another branch or turned too far
      if (!pr.converged || chord > 2 * h || chord < 0.25 * h || t.dot(tq) < cos_turn ||
          (q - p).dot(t) <= 0) {
        h *= 0.5;
        if (h < h_min) {
          if (tangential(p)) return false;
          *reason = "the curve cannot be followed past " + point_str(p);
          return false;
        }
        continue;
      }
      if (tangential(q)) return false;
      // leaving the solid through a third surface: the curve ends at a vertex
      const auto [k, m] = worst_other(gs, a, b, q);
      if (k >= 0 && m > tol.solve_residual) {
        const double vp = gs[k].value(p), vq = gs[k].value(q);
        const double f = vp < vq ? std::clamp(vp / (vp - vq), 0.0, 1.0) : 0.5;
        const Projection v = solve_three_surfaces(gs[a], gs[b], gs[k], p + f * (q - p), tol);
        if (v.converged && (v.point - p).norm() <= 2 * chord &&
            worst_other(gs, a, b, v.point).second <= tol.on_boundary) {
          if ((v.point - p).norm() > 0) pts->push_back(v.point);
          *end_surface = k;
          return true;
        }
        h *= 0.5;  // approach the vertex with smaller steps until Newton finds it
        if (h < h_min) {
          *reason = "the curve's end on surface " + std::to_string(k) + " near " +
                    point_str(p) + " cannot be located";
          return false;
        }
        continue;
      }
      // back at the seed: the curve is closed
      const Eigen::Vector3d d = q - p;
      const double u = std::clamp((seed - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
      if (travelled > 2 * h_max && (p + u * d - seed).norm() < 0.5 * h) {
        *closed = true;
        return true;
      }
      pts->push_back(q);
      travelled += chord;
      p = q;
      // grow the step again on gentle stretches
      if (t.dot(tq) > std::cos(0.5 * tol.edge_sample_turn)) h = std::min(h_max, 1.5 * h);
      t = tq;
    }
    *reason = "the curve through " + point_str(seed) + " does not close";
    return false;
  }
};

}  // namespace

double arc_length(const Eigen::Vector3d& p0, const Eigen::Vector3d& t0,
                  const Eigen::Vector3d& p1, const Eigen::Vector3d& t1) {
  const double chord = (p1 - p0).norm();
  const double theta = std::atan2(t0.cross(t1).norm(), t0.dot(t1));
  const double half = 0.5 * theta;
  return half > 0 ? chord * half / std::sin(half) : chord;
}

double distance_to_samples(const std::vector<CurveSample>& samples, bool closed,
                           const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = samples.size();
  if (n == 1) return (samples[0].point - p).norm();
  const std::size_t segs = closed ? n : n - 1;
  for (std::size_t k = 0; k < segs; ++k) {
    const Eigen::Vector3d& x = samples[k].point;
    const Eigen::Vector3d d = samples[(k + 1) % n].point - x;
    const double u = std::clamp((p - x).dot(d) / std::max(d.squaredNorm(), std::numeric_limits<double>::min()), 0.0, 1.0);
    best = std::min(best, (x + u * d - p).norm());
  }
  return best;
}

bool trace_curve(const std::vector<Polynomial>& surfaces, int a, int b,
                 const Eigen::Vector3d& seed, const Tolerances& tol, TracedCurve* out,
                 std::string* reason, Eigen::Vector3d* tangential_at) {
  Tracer tr{surfaces, a, b, tol, reason, tangential_at};
  *tangential_at = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  if (tr.tangential(seed)) return false;
  std::vector<Eigen::Vector3d> fwd, bwd;
  bool closed = false, closed_back = false;
  int end_fwd = -1, end_bwd = -1;
  if (!tr.walk(seed, +1, &fwd, &end_fwd, &closed)) return false;
  if (!closed && !tr.walk(seed, -1, &bwd, &end_bwd, &closed_back)) return false;
  std::vector<Eigen::Vector3d> pts(bwd.rbegin(), bwd.rend());
  pts.push_back(seed);
  pts.insert(pts.end(), fwd.begin(), fwd.end());
  *out = TracedCurve{};
  out->closed = closed;
  out->end_surface[0] = end_bwd;
  out->end_surface[1] = end_fwd;
  out->samples.resize(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    CurveSample& s = out->samples[k];
    s.point = pts[k];
    s.tangent = curve_tangent(surfaces[a], surfaces[b], pts[k]);
    s.s = k == 0 ? 0.0
                 : out->samples[k - 1].s + arc_length(out->samples[k - 1].point,
                                                       out->samples[k - 1].tangent, s.point,
                                                       s.tangent);
  }
  out->length = out->samples.back().s;
  if (closed)
    out->length += arc_length(out->samples.back().point, out->samples.back().tangent,
                              out->samples.front().point, out->samples.front().tangent);
  return true;
}

}  // namespace pcsg
