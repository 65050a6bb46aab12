#pragma once
// Every geometric tolerance of pcsg, in one place. All are derived from one length scale per
// scene (`length_scale`, the larger bounding-box diagonal of the two objects), so that a scene
// scaled by s gives the same results scaled by s. No algorithm code uses a bare epsilon: it
// takes the named value from here. Each field says why it has its size.
//
// Relative factors are chosen against machine epsilon (2.2e-16) and against the sizes of the
// things they must separate: solver round-off (~1e-14 L) below, mesh and motion-step features
// (~1e-3 L) above.
#include <cmath>

namespace pcsg {

struct Tolerances {
  // The scene's length unit: larger bounding-box diagonal of A and B.
  double length_scale = 1.0;

  // --- exact solves on the smooth surfaces ---------------------------------------------------
  // Newton stops when a point's distance residual is below this: ~100x the round-off of
  // evaluating a quartic at coordinates of size L (|x|^4 * eps, normalised by the gradient).
  double solve_residual = 1e-12;
  // Newton iteration cap: quadratic convergence needs < 10 from a mesh-quality start; 50 leaves
  // room for damped steps from poor starts without hiding divergence.
  int solve_max_iterations = 50;

  // --- contact classification ----------------------------------------------------------------
  // |gap| below this counts as touching. Witnesses are projected to ~1e-12 L; 1e-9 L leaves
  // three orders for motion-step drift and stays far below mesh and step sizes (~1e-3 L).
  double contact_gap = 1e-9;
  // A gap below -penetration is penetration. Same size as contact_gap so that no pose is
  // both "touching" and "penetrating".
  double penetration = 1e-9;
  // A contact point is on an element's boundary (an edge of a face, a vertex of an edge) when
  // its distance to it is below this. Same reasoning as contact_gap.
  double on_boundary = 1e-9;
  // Two contact points of the same element pair are distinct contacts when farther apart than
  // this: two separate local minima of the distance are at least a curvature radius apart,
  // while one minimum found twice coincides to solve_residual.
  double distinct_points = 1e-6;
  // Edge tangents are collinear (e-e-touch rather than e-e-cross) when the sine of their angle
  // is below this (dimensionless): round-off on unit tangents is ~1e-15, motion drift ~1e-9.
  double collinear_sine = 1e-7;

  // --- meshes (collision checks and rendering only) ------------------------------------------
  // Default chordal error of the meshes: 1e-3 L keeps a 1280-pixel image within one pixel and
  // FCL queries on ~10^4 triangles per object.
  double mesh_chordal_error = 1e-3;

  // --- transition motions ----------------------------------------------------------------------
  // Default length of one small motion step along a face or edge: 1e-2 L resolves the paper's
  // examples' features (smallest radius of curvature ~0.1 L) with ~10 steps per radian.
  double motion_step = 1e-2;

  // Builds the tolerances of a scene whose length scale is L (> 0): every length above is the
  // relative factor times L; dimensionless values and counts are kept.
  static Tolerances for_length_scale(double L) {
    Tolerances t;
    t.length_scale = L;
    t.solve_residual *= L;
    t.contact_gap *= L;
    t.penetration *= L;
    t.on_boundary *= L;
    t.distinct_points *= L;
    t.mesh_chordal_error *= L;
    t.motion_step *= L;
    return t;
  }
};

}  // namespace pcsg
