#pragma once
// The contact tests' solids, with closed-form faces, edges and vertices (hand_built_solids.h),
// scaled by `s` for the scale-invariance tests.
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"
#include "tests/engine/contact/hand_built_solids.h"

namespace pcsg::testkit {

struct MeshedSolid {
  Solid solid;
  SolidMesh mesh;
};

// A ball of radius r centred at the origin; its face is named `face`.
inline MeshedSolid sphere_solid(double r, const std::string& face = "fS") {
  MeshedSolid m{make_solid("S", {{face, ball(Eigen::Vector3d::Zero(), r)}}), {}};
  m.mesh = mesh_convex(m.solid, Eigen::Vector3d::Zero());
  return m;
}

inline MeshedSolid ellipsoid_solid(double a, double b, double c, const std::string& face = "fA") {
  MeshedSolid m{make_solid("E", {{face, ellipsoid(a, b, c)}}), {}};
  m.mesh = mesh_convex(m.solid, Eigen::Vector3d::Zero());
  return m;
}

// The intersection of the balls of radius rho centred at (0, 0, -h) (upper face fU) and
// (0, 0, h) (lower face fL): a lens whose edge eL is the circle z = 0 of radius
// sqrt(rho^2 - h^2).
inline MeshedSolid lens_solid(double rho, double h) {
  MeshedSolid m{make_solid("L", {{"fU", ball({0, 0, -h}, rho)}, {"fL", ball({0, 0, h}, rho)}}), {}};
  add_edge(m.solid, "eL", 0, 1,
           circle(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), std::sqrt(rho * rho - h * h)),
           true);
  m.mesh = mesh_convex(m.solid, Eigen::Vector3d::Zero());
  return m;
}

// Paper Example 2's A scaled by s: 8x^2 + 8y^2 - 9z <= 18 (fA1, lower cap) and
// 8x^2 + 8y^2 + 9z <= 18 (fA2, upper cap), meeting on the circle eA: z = 0, r = 1.5.
inline MeshedSolid double_paraboloid_solid(double s = 1) {
  const Polynomial r2 = (var(0) * (1 / s)).pow(2) + (var(1) * (1 / s)).pow(2);
  const Polynomial z = var(2) * (1 / s);
  MeshedSolid m{
      make_solid("D", {{"fA1", r2 * 8 - z * 9 - cst(18)}, {"fA2", r2 * 8 + z * 9 - cst(18)}}), {}};
  add_edge(m.solid, "eA", 0, 1, circle(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 1.5 * s),
           true);
  m.mesh = mesh_convex(m.solid, Eigen::Vector3d::Zero());
  return m;
}

// Paper Example 1's B scaled by s: f1 the concave dish 4x^2 + 4y^2 - 10.07047z >= 15.75982,
// f2 the sphere band x^2 + y^2 + z^2 <= 16, f3 the convex bottom x^2 + y^2 - 4z <= 16; e1 is
// the dish's rim on the sphere, e2 the circle z = 0, r = 4.
struct BowlConstants {
  static constexpr double a = 4 / 10.07047;  // dish: z = a r^2 - b
  static constexpr double b = 15.75982 / 10.07047;
  // Rim: a r^2 - b = z and r^2 + z^2 = 16  =>  z^2 + z / a + b / a - 16 = 0.
  static double rim_z() { return 0.5 * (-1 / a + std::sqrt(1 / (a * a) - 4 * (b / a - 16))); }
};

// The ellipsoid (1, 1.5, 2.5) lying in the dish (paper Fig. 5b), resting on its two f-f
// contacts: the closed-form height of bowl_contacts_test.cc.
inline Pose lying_ellipsoid_pose() {
  using K = BowlConstants;
  Pose X;
  X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  X.position = {0, 0, 6.25 * K::a + 1 / (25 * K::a) - K::b};
  return X;
}

inline MeshedSolid bowl_solid(double s = 1) {
  using K = BowlConstants;
  const Polynomial x = var(0) * (1 / s), y = var(1) * (1 / s), z = var(2) * (1 / s);
  const Polynomial r2 = x.pow(2) + y.pow(2);
  MeshedSolid m{make_solid("B", {{"f1", cst(15.75982) - r2 * 4 + z * 10.07047},
                                 {"f2", r2 + z.pow(2) - cst(16)},
                                 {"f3", r2 - z * 4 - cst(16)}}),
                {}};
  const double zr = K::rim_z(), rr = std::sqrt(16 - zr * zr);
  add_edge(m.solid, "e1", 0, 1, circle({0, 0, zr * s}, Eigen::Vector3d::UnitZ(), rr * s), true);
  add_edge(m.solid, "e2", 1, 2, circle(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 4 * s),
           true);
  // Profile: dish from its bottom to the rim, band down to z = 0, bottom back to the axis.
  std::vector<Eigen::Vector2d> profile;
  const int n = 48;
  for (int k = 0; k < n; ++k) {
    const double r = rr * k / n;
    profile.push_back(Eigen::Vector2d(r, K::a * r * r - K::b) * s);
  }
  const double a0 = std::atan2(zr, rr);
  for (int k = 0; k < n; ++k) {
    const double a = a0 * (1 - static_cast<double>(k) / n);
    profile.push_back(Eigen::Vector2d(4 * std::cos(a), 4 * std::sin(a)) * s);
  }
  for (int k = 0; k <= n; ++k) {
    const double r = 4.0 * (n - k) / n;
    profile.push_back(Eigen::Vector2d(r, (r * r - 16) / 4) * s);
  }
  m.mesh = mesh_revolution(m.solid, profile, 128);
  return m;
}

// The intersection of three balls of radius rho centred at distance d from the z axis, 120
// degrees apart: faces f0, f1, f2; edges e01, e12, e20 (arcs); vertices vB = (0, 0, -h) and
// vT = (0, 0, h), h = sqrt(rho^2 - d^2).
inline MeshedSolid three_ball_solid(double rho, double d) {
  Eigen::Vector3d c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = d * Eigen::Vector3d(std::cos(2 * M_PI * k / 3), std::sin(2 * M_PI * k / 3), 0);
  MeshedSolid m{
      make_solid("T", {{"f0", ball(c[0], rho)}, {"f1", ball(c[1], rho)}, {"f2", ball(c[2], rho)}}),
      {}};
  const double h = std::sqrt(rho * rho - d * d);
  const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  const char* names[3] = {"e01", "e12", "e20"};
  for (int e = 0; e < 3; ++e) {
    const int i = pairs[e][0], j = pairs[e][1];
    // The circle of balls i and j lies in their bisector plane, which holds the z axis; its
    // arc inside the third ball runs between the vertices through the side facing the axis.
    const Eigen::Vector3d mid = 0.5 * (c[i] + c[j]);
    const double rc = std::sqrt(rho * rho - (c[i] - c[j]).squaredNorm() / 4);
    const Eigen::Vector3d u = -mid.normalized(), v = Eigen::Vector3d::UnitZ();
    const double a0 = std::atan2(h, mid.norm());
    std::vector<Eigen::Vector3d> pts;
    const int n = 400;
    for (int k = 0; k <= n; ++k) {
      const double a = -a0 + 2 * a0 * k / n;
      pts.push_back(mid + rc * (std::cos(a) * u + std::sin(a) * v));
    }
    add_edge(m.solid, names[e], i, j, pts, false, {0, 1});
  }
  add_vertex(m.solid, "vB", {0, 0, -h}, {0, 1, 2}, {0, 1, 2});
  add_vertex(m.solid, "vT", {0, 0, h}, {0, 1, 2}, {0, 1, 2});
  m.mesh = mesh_convex(m.solid, Eigen::Vector3d::Zero());
  return m;
}

inline SceneGeometry scene_of(MeshedSolid A, MeshedSolid B) {
  return make_scene(std::move(A.solid), std::move(A.mesh), std::move(B.solid), std::move(B.mesh));
}

// A ball of radius 1 (A, face fA) and a ball of radius 4 (B, face fB) centred at
// kFarBallsCentre, 1.3e6 from B's origin: 1e5 of the scene's sizes (L = 13.9).
inline const Eigen::Vector3d kFarBallsCentre(1200000, -500000, 200000);
inline SceneGeometry far_balls_scene() {
  return build_scene_geometry(
      parse_scene("objects:\n"
                  "  A:\n    faces:\n      fA: \"x^2 + y^2 + z^2 <= 1\"\n"
                  "  B:\n    faces:\n"
                  "      fB: \"(x - 1200000)^2 + (y + 500000)^2 + (z - 200000)^2 <= 16\"\n",
                  "far_balls.yaml"));
}

}  // namespace pcsg::testkit
