#pragma once
// Every geometric tolerance of pcsg, in one place. All are derived from one length scale per
// scene (`length_scale`, the larger bounding-box diagonal of the two objects), so that a scene
// scaled by s gives the same results scaled by s. No algorithm code uses a bare epsilon: it
// takes the named value from here. Each field says why it has its size.
//
// Relative factors are chosen against machine epsilon (2.2e-16) and against the sizes of the
// things they must separate: solver round-off (~1e-14 L) below, mesh and motion-step features
// (~1e-3 L) above.
#include <algorithm>
#include <cmath>
#include <limits>

namespace pcsg {

struct Tolerances {
  // The scene's length unit: larger bounding-box diagonal of A and B.
  double length_scale = 1.0;

  // --- exact solves on the smooth surfaces ---------------------------------------------------
  // Newton stops when a point's distance residual is below this: ~100x the round-off of
  // evaluating a quartic at coordinates of size L (|x|^4 * eps, normalised by the gradient).
  double solve_residual = 1e-12;
  // The residual a solve can reach where its points have coordinates of size |x|: evaluating
  // a contact's residuals (R p_A + t - p_B; a polynomial about its origin) rounds by a few
  // units in the last place of |x|, ~eps |x|. Far from B's origin that exceeds solve_residual
  // (the needle with B's frame 1.3e5 away, L = 13.2: the residual stalls at 1.3e-11 to
  // 1.6e-11 against 1.3e-11, and whether a solve converged was decided by round-off), so the
  // solves stop at this many units of eps |x| instead: 8 covers the 0.5 eps |x| measured
  // there with room, and near the origin (|x| ~ L) it is 2e-3 of solve_residual, which it
  // leaves in charge.
  static constexpr double kRoundOffUnits = 8;
  double residual_at(double coordinate_size) const {
    return std::max(solve_residual,
                    kRoundOffUnits * std::numeric_limits<double>::epsilon() * coordinate_size);
  }
  // Newton iteration cap: quadratic convergence needs < 10 from a mesh-quality start; 50 leaves
  // room for damped steps from poor starts without hiding divergence.
  int solve_max_iterations = 50;
  // ... and for detection's solves from mesh starts (resolve_contact): converged ones take 4.85
  // iterations on average, 393 of a million 30 or more (Example 1), and the ones that never
  // converge cost 25% of Example 2's CPU; a failed start is retried (normal cone, other starts of
  // the region). Measured with 30: Example 1's graph unchanged bit for bit, Example 2's states
  // and linked pairs unchanged, the torus's graph unchanged although 5.8% of its converged
  // solves need 30 or more (nearly conformal rings); 20 lost the torus's 3 ring-contact states
  // before ring_curvature took them out, and after it still reads a touching pose of the torus
  // tipped in the dish (two f-f contacts, relative curvature 2.3e-4 / L, whose solves converge
  // linearly and need 23 and 24 iterations) as free (docs/where-the-time-goes.md, sessions 63-66).
  int detection_solve_max_iterations = 30;
  // Two faces meet tangentially (no proper edge) when the sine of their normals' angle on the
  // common curve is below this (dimensionless): an edge point is then located only to
  // solve_residual / sine = 1e-9 L, the size of contact_gap.
  double tangential_sine = 1e-3;
  // Spacing of the exact samples along an edge curve: 5e-3 L gives >= 20 samples per radian on
  // curvature radii >= 0.1 L, so lookups along the polyline are within ~1e-5 L of the curve.
  double edge_sample_step = 5e-3;
  // Largest turn of the tangent between two edge samples (radians): keeps the chord-to-arc
  // length correction (exact on circles) accurate to ~1e-10 relative on general curves.
  double edge_sample_turn = 0.05;
  // Cells of the grid (along the longest side of a solid's box) on which faces, edges and
  // vertices are discovered before being traced exactly: resolves features >= L / 24, while the
  // smallest the paper's objects have is ~L / 10.
  int discovery_cells = 24;
  // ... and at least this many cells across the solid's thickness (SolidExtent::thickness),
  // so that a needle or a thin disc, thinner than L / 24, still has grid vertices inside it
  // on both sides of each surface (two would do exactly across the middle; four leave room
  // for the ends, which taper). The paper's objects are thick: L / 24 already gives > 4.
  int discovery_cells_across = 4;
  // A discovery grid above this many cells is refused with an error naming the thickness
  // (~1 s and ~100 MB of samples per surface): a solid thinner than its box by > ~1e3.
  double discovery_max_cells = 1.6e7;

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
  // e-e solutions whose tangents' sine is below this are re-solved as e-e-touch: the
  // common-perpendicular solve locates a touch only to sine ~sqrt(solve_residual / L) ~ 1e-6,
  // while ordinary crossings (sines ~0.1-1) skip the extra solve.
  double near_collinear_sine = 1e-3;
  // A contact direction is in an edge's (vertex's) normal cone when its distance to the cone
  // of the unit face normals is below this (dimensionless): same reasoning as on_boundary.
  double normal_cone = 1e-9;
  // A stationary point is a distance minimum when the relative curvature along its sliding
  // directions is above -curvature (1/length): round-off ~1e-14 / L below, the examples'
  // relative curvatures (>= 1e-2 / L) far above.
  double curvature = 1e-9;
  // Contact detection finds every local distance minimum up to this gap: meshes are inflated
  // by their chordal error plus half this band. 1e-3 L (one default chordal error) holds a
  // contact's neighbourhood in a few triangles while covering near-contacts of motion steps.
  double candidate_band = 1e-3;
  // A contact whose smallest relative curvature along its sliding directions is below this
  // (1/length) may have a second distance minimum of the same pair in its overlap region
  // (next to a bifurcation the two merge, and the curvature at each tends to zero), so
  // detection solves again from the region's far end. Two minima 0.8% of L apart with a
  // saddle 3.8e-8 L high (scenes/stress/near_matching_curvature.yaml) have 0.021 / L; 0.1 / L
  // keeps margin, while most contacts are far more curved (the extra solves cost time).
  // Measured: Example 1 generated and swapped, 52.4 s of CPU without the extra solves,
  // 55.0 s with them. (Detection also solves again, after minima, saddles and failed solves,
  // from witnesses farther than seed_separation from every start: contact_detection.cc.)
  double bifurcation_curvature = 0.1;
  // A face contact (f-f, f-e, e-f) whose relative curvature along a sliding direction is
  // below this (1/length) in magnitude touches along a curve, not at a point (a ring contact:
  // a torus against a sphere centred on its axis), and its pose is no point-contact state's
  // witness. Measured (session 65, sliding_curvature times L): the torus's ring contacts
  // 7.6e-11 to 1.2e-10 (round-off), the least genuine contact 2.3e-4 (the torus nearly coaxial
  // in the dish), Example 1 >= 0.158, Example 2 >= 3.6; 1e-6 lies 4 decades from both.
  double ring_curvature = 1e-6;
  // Projection onto a contact formation: largest translation (and rotation times L) of one
  // Gauss-Newton step, 0.05 L, inside the basin of the pair solves; and an iteration cap
  // (quadratic convergence needs < 10 from a motion step away).
  double projection_step = 5e-2;
  int projection_max_iterations = 60;
  // Starting points of one element pair's solves closer than this are one (projection seeds,
  // and detection's further starts in one overlap region): two separate distance minima of a
  // pair lie a curvature radius apart, >= 0.1 L here.
  double seed_separation = 5e-2;
  // A surface holds a straight segment when g(p + t d), t in units of L, has all its t-terms
  // below this times |grad g| L + |Hess g| L^2 (dimensionless): it then departs from the line
  // by ~1e-9 L over a length L, like contact_gap, while round-off is ~1e-14.
  double straight_line_relative = 1e-9;
  // A solid is a solid of revolution about an axis when each of its polynomials, rotated by a
  // radian about the axis, changes by less than this times its largest value on a grid over
  // the solid's box (dimensionless): evaluation round-off is ~1e-15 of that, while a real
  // asymmetry of 1e-9 moves the surface by ~1e-9 L, the size of contact_gap.
  double symmetry_relative = 1e-9;

  // --- meshes (collision checks and rendering only) ------------------------------------------
  // Default chordal error of the meshes: 1e-3 L keeps a 1280-pixel image within one pixel and
  // FCL queries on ~10^4 triangles per object.
  double mesh_chordal_error = 1e-3;

  // --- transition motions ----------------------------------------------------------------------
  // Default length of one small motion step along a face or edge: 1e-2 L resolves the paper's
  // examples' features (smallest radius of curvature ~0.1 L) with ~10 steps per radian.
  double motion_step = 1e-2;

  // Kept contacts are re-projected after every motion step until their residual is below
  // this: 100x below contact_gap, so drift never accumulates into a classification change.
  double keep_residual = 1e-11;
  // Finite-difference displacement for contact-point rates (drive directions only, never for
  // exactness): sqrt(eps) * L balances truncation against round-off.
  double rate_step = 1e-7;

  // Builds the tolerances of a scene whose length scale is L (> 0): every length above is the
  // relative factor times L; dimensionless values and counts are kept.
  static Tolerances for_length_scale(double L) {
    Tolerances t;
    t.length_scale = L;
    t.solve_residual *= L;
    t.edge_sample_step *= L;
    t.contact_gap *= L;
    t.penetration *= L;
    t.on_boundary *= L;
    t.distinct_points *= L;
    t.mesh_chordal_error *= L;
    t.motion_step *= L;
    t.keep_residual *= L;
    t.rate_step *= L;
    t.curvature /= L;  // a curvature: 1/length
    t.bifurcation_curvature /= L;
    t.ring_curvature /= L;
    t.candidate_band *= L;
    t.projection_step *= L;
    t.seed_separation *= L;
    return t;
  }
};

}  // namespace pcsg
