#include "engine/geometry/mesh_measures.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/geometry/scene_geometry.h"
#include "tests/engine/geometry/test_objects.h"

namespace pcsg {
namespace {

// Face areas are the mesh's, refined once with exact midpoints and Richardson-extrapolated:
// measured errors are ~1e-7 relative on closed faces and ~3e-5 on faces cut by edges (the
// sliver fans along edges spoil the h^2 error expansion); 1e-4 relative bounds both.
constexpr double kAreaRelative = 1e-4;

// Area of the paraboloid cap z = a r^2 + c over 0 <= r <= R.
double paraboloid_cap_area(double a, double R) {
  return M_PI / (6 * a * a) * (std::pow(1 + 4 * a * a * R * R, 1.5) - 1);
}

SceneGeometry scene_with_A(const ObjectSpec& A) {
  SceneSpec s;
  s.A = A;
  s.B = test::example_B();
  return build_scene_geometry(s);
}

TEST(MeshMeasures, SphereArea) {
  const SceneGeometry g = scene_with_A(test::object("A", {{"s", "x^2 + y^2 + z^2 <= 2.25"}}));
  EXPECT_NEAR(g.A.faces[0].area, 4 * M_PI * 2.25, kAreaRelative * 4 * M_PI * 2.25);
}

TEST(MeshMeasures, ParaboloidCapAndSphereBandAreas) {
  const SceneGeometry g = scene_with_A(test::lens_A());
  const double cap = paraboloid_cap_area(8.0 / 9, 1.5);
  EXPECT_NEAR(g.A.faces[0].area, cap, kAreaRelative * cap);
  EXPECT_NEAR(g.A.faces[1].area, cap, kAreaRelative * cap);
  // object B: the dish up to the rim, the sphere band 2 pi R h, the bottom cap
  const double rim_z = (-10.07047 + std::sqrt(10.07047 * 10.07047 + 16 * 48.24018)) / 8;
  const double dish = paraboloid_cap_area(4 / 10.07047, std::sqrt(16 - rim_z * rim_z));
  EXPECT_NEAR(g.B.faces[0].area, dish, kAreaRelative * dish);
  EXPECT_NEAR(g.B.faces[1].area, 8 * M_PI * rim_z, kAreaRelative * 8 * M_PI * rim_z);
  const double bottom = paraboloid_cap_area(0.25, 4);
  EXPECT_NEAR(g.B.faces[2].area, bottom, kAreaRelative * bottom);
}

TEST(MeshMeasures, TopologyCountsHoles) {
  SolidMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  EXPECT_TRUE(mesh_topology(m).watertight());
  EXPECT_NEAR(mesh_volume(m), 1.0 / 6, 1e-15);
  m.triangles.pop_back();
  EXPECT_EQ(mesh_topology(m).boundary_edges, 3);
  m.triangles.push_back({0, 2, 3});  // the same face, flipped
  EXPECT_EQ(mesh_topology(m).misoriented_edges, 3);
}

}  // namespace
}  // namespace pcsg
