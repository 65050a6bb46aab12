#include "engine/geometry/brep_builder.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/geometry/curve_fit.h"
#include "engine/geometry/solid_extent.h"
#include "tests/engine/geometry/test_objects.h"

namespace pcsg {
namespace {

// Extremes are refined onto exact critical points by Newton with residual 1e-12 L; samples lie
// on the surfaces to the same residual: 1e-9 leaves margin for L ~ 10.
constexpr double kExact = 1e-9;
// Edge lengths sum chord-to-arc corrected segments: exact on circles up to round-off.
constexpr double kLength = 1e-9;

// The dish meets the sphere at z where 4(16 - z^2) - 10.07047 z = 15.75982.
const double kRimZ = (-10.07047 + std::sqrt(10.07047 * 10.07047 + 16 * 48.24018)) / 8;

ObjectSpec example_B_named() {
  ObjectSpec B = test::example_B();
  B.edges.push_back({"e1", "f1", "f2", {"test.yaml", 5, 3}});
  B.edges.push_back({"e2", "f2", "f3", {"test.yaml", 6, 3}});
  return B;
}

TEST(BrepBuilder, ExampleBHasThreeFacesTwoCircularEdgesNoVertices) {
  std::vector<std::string> warnings;
  const Solid B = build_solid(example_B_named(), &warnings);
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(B.faces.size(), 3u);
  ASSERT_EQ(B.edges.size(), 2u);
  EXPECT_TRUE(B.vertices.empty());
  EXPECT_EQ(B.faces[0].name, "f1");
  EXPECT_EQ(B.faces[2].name, "f3");
  // the paper's ranges: f1 z in [-1.56495, 2.43505], f2 [0, 2.43505], f3 [-4, 0]
  EXPECT_NEAR(B.faces[0].bbox.min().z(), -15.75982 / 10.07047, kExact);
  EXPECT_NEAR(B.faces[0].bbox.max().z(), kRimZ, kExact);
  EXPECT_NEAR(B.faces[1].bbox.min().z(), 0, kExact);
  EXPECT_NEAR(B.faces[1].bbox.max().z(), kRimZ, kExact);
  EXPECT_NEAR(B.faces[2].bbox.min().z(), -4, kExact);
  EXPECT_NEAR(B.faces[2].bbox.max().z(), 0, 1e-10 * 13);  // cut points: solve_residual
  EXPECT_NEAR(B.bbox.max().x(), 4, kExact);
  // e1: circle of radius sqrt(16 - z^2) at the rim; e2: radius 4 at z = 0
  const Edge& e1 = B.edges[0];
  const Edge& e2 = B.edges[1];
  EXPECT_EQ(e1.name, "e1");
  EXPECT_EQ(e2.name, "e2");
  EXPECT_TRUE(e1.closed && e2.closed);
  EXPECT_EQ(B.element_name({ElementKind::Face, e1.face1}), "f1");
  EXPECT_EQ(B.element_name({ElementKind::Face, e1.face2}), "f2");
  const double r1 = std::sqrt(16 - kRimZ * kRimZ);
  EXPECT_NEAR(e1.length, 2 * M_PI * r1, kLength);
  EXPECT_NEAR(e2.length, 8 * M_PI, kLength);
  EXPECT_NEAR(fit_circle(e1).radius, r1, kExact);
  EXPECT_NEAR(fit_circle(e1).centre.z(), kRimZ, kExact);
  EXPECT_NEAR(fit_circle(e2).radius, 4, kExact);
  // samples: exact, tangents unit and along increasing s
  for (std::size_t k = 0; k + 1 < e1.samples.size(); ++k) {
    EXPECT_GT(e1.samples[k + 1].s, e1.samples[k].s);
    EXPECT_GT(e1.samples[k].tangent.dot(e1.samples[k + 1].point - e1.samples[k].point), 0);
  }
  // adjacency and lookups
  EXPECT_EQ(B.adjacent({ElementKind::Face, 1}),
            (std::vector<ElementId>{{ElementKind::Edge, 0}, {ElementKind::Edge, 1}}));
  EXPECT_EQ(B.adjacent({ElementKind::Edge, 1}),
            (std::vector<ElementId>{{ElementKind::Face, 1}, {ElementKind::Face, 2}}));
  EXPECT_EQ(B.find("e2").kind, ElementKind::Edge);
  EXPECT_EQ(B.find("e2").index, 1);
  EXPECT_EQ(B.find("nope").index, -1);
  EXPECT_EQ(B.face_at(1, Eigen::Vector3d(0, 4, 0.5).normalized() * 4, kExact), 1);
  EXPECT_EQ(B.face_at(1, Eigen::Vector3d(0, 0, 4), kExact), -1);  // above the dish: off f2's patch
  EXPECT_EQ(B.edge_at(1, 2, Eigen::Vector3d(4, 0, 0), kExact), 1);
  EXPECT_EQ(B.edge_at(0, 2, Eigen::Vector3d(4, 0, 0), kExact), -1);
  EXPECT_LT(B.inside_measure({0, 0, -2}), 0);  // between the dish's tip and the bottom
  EXPECT_GT(B.inside_measure({0, 0, 3}), 0);
  // interior points lie on their patches, away from the edges
  for (const auto& f : B.faces) EXPECT_LT(B.inside_measure(f.interior_point), kExact);
}

TEST(BrepBuilder, UnnamedElementsGetGeneratedNames) {
  const Solid B = build_solid(test::example_B(), nullptr);
  ASSERT_EQ(B.edges.size(), 2u);
  EXPECT_EQ(B.edges[0].name, "e_f1_f2");
  EXPECT_EQ(B.edges[1].name, "e_f2_f3");
}

TEST(BrepBuilder, LensHasTwoCapsMeetingOnACircle) {
  const Solid A = build_solid(test::lens_A(), nullptr);
  ASSERT_EQ(A.faces.size(), 2u);
  ASSERT_EQ(A.edges.size(), 1u);
  EXPECT_NEAR(A.edges[0].length, 3 * M_PI, kLength);
  EXPECT_NEAR(fit_circle(A.edges[0]).radius, 1.5, kExact);
  EXPECT_NEAR(A.faces[0].bbox.min().z(), -2, kExact);
  EXPECT_NEAR(A.faces[1].bbox.max().z(), 2, kExact);
}

TEST(BrepBuilder, TorusIsOneFaceWithoutEdges) {
  const Solid T = build_solid(test::torus(), nullptr);
  EXPECT_EQ(T.faces.size(), 1u);
  EXPECT_TRUE(T.edges.empty());
  EXPECT_TRUE(T.vertices.empty());
  EXPECT_NEAR(T.bbox.max().x(), 3, kExact);
  EXPECT_NEAR(T.bbox.max().z(), 1, kExact);
  // the inner equator is saddle-shaped: curvatures of both signs
  EXPECT_NEAR(T.faces[0].max_curvature, 1, 1e-3);
}

TEST(BrepBuilder, ThreeSpheresMeetAtTwoVertices) {
  const Solid S = build_solid(test::three_spheres(), nullptr);
  ASSERT_EQ(S.faces.size(), 3u);
  ASSERT_EQ(S.edges.size(), 3u);
  ASSERT_EQ(S.vertices.size(), 2u);
  EXPECT_EQ(S.vertices[0].name, "v_s1_s2_s3");
  EXPECT_EQ(S.vertices[1].name, "v_s1_s2_s3#2");
  const double zv = std::sqrt(2.0 / 3);
  EXPECT_NEAR(S.vertices[0].point.z(), -zv, kExact);
  EXPECT_NEAR(S.vertices[1].point.z(), zv, kExact);
  for (const auto& v : S.vertices) {
    EXPECT_EQ(v.surfaces, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(v.faces.size(), 3u);
    EXPECT_EQ(v.edges.size(), 3u);
  }
  for (const auto& e : S.edges) {
    EXPECT_FALSE(e.closed);
    ASSERT_EQ(e.vertices.size(), 2u);
    // each edge is an arc of a circle of radius sqrt(3)/2 spanning 2 asin(zv / r)
    const double r = std::sqrt(3.0) / 2;
    EXPECT_NEAR(e.length, 2 * r * std::asin(zv / r), kLength);
    EXPECT_TRUE(e.samples.front().point.isApprox(S.vertices[e.vertices[0]].point, kExact));
  }
  EXPECT_EQ(S.edges[0].name, "e_s1_s2");
  EXPECT_EQ(S.faces[0].vertices, (std::vector<int>{0, 1}));
}

TEST(BrepBuilder, OneSurfaceCanGiveSeveralFaces) {
  // a ball inside both sheets of a two-sheet hyperboloid: two separate caps of each surface
  const Solid S = build_solid(
      test::object("A", {{"s", "x^2 + y^2 + z^2 <= 4"}, {"h", "x^2 + y^2 - z^2 <= -1"}}), nullptr);
  ASSERT_EQ(S.faces.size(), 4u);
  EXPECT_EQ(S.faces[0].name, "s");
  EXPECT_EQ(S.faces[1].name, "s#2");
  EXPECT_EQ(S.faces[2].name, "h");
  EXPECT_EQ(S.faces[3].name, "h#2");
  ASSERT_EQ(S.edges.size(), 2u);
  EXPECT_EQ(S.edges[0].name, "e_s_h");
  EXPECT_EQ(S.edges[1].name, "e_s_h#2");
  // each edge joins the cap and the sheet on the same side
  for (const auto& e : S.edges)
    EXPECT_GT(S.faces[e.face1].interior_point.z() * S.faces[e.face2].interior_point.z(), 0);
}

}  // namespace
}  // namespace pcsg

namespace pcsg {
namespace {

// A needle 1:1:100 (scenes/stress/needle_in_dish.yaml), 0.05 thick and 5 long: thinner than
// a cell of the grid of Tolerances::discovery_cells across its box (5 / 24 = 0.21), it used
// to give "object A is empty". The grid now also has discovery_cells_across cells across its
// thickness.
TEST(BrepBuilder, NeedleThinnerThanTheCoarseGridIsFound) {
  const ObjectSpec needle = test::object("A", {{"fA", "10000x^2 + 10000y^2 + z^2 <= 6.25"}});
  const SolidExtent extent = solid_extent(needle);
  // the shortest exit from the centre is the radius, to the 626 directions' spacing (0.14
  // rad: the nearest direction to the equator is within 0.07 rad, 1 / cos 0.07 = 1.0025)
  EXPECT_NEAR(extent.thickness, 0.05, 0.05 * 3e-3);
  const Solid A = build_solid(needle, nullptr);
  ASSERT_EQ(A.faces.size(), 1u);
  EXPECT_TRUE(A.edges.empty());
  EXPECT_NEAR(A.bbox.max().x(), 0.025, kExact);
  EXPECT_NEAR(A.bbox.min().y(), -0.025, kExact);
  EXPECT_NEAR(A.bbox.max().z(), 2.5, kExact);
  // and one 1:1:10^5 is refused with a message naming its thickness
  try {
    build_solid(test::object("A", {{"fA", "1e10x^2 + 1e10y^2 + z^2 <= 6.25"}}), nullptr);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("object A is too thin to discover: 5e-05 thick"),
              std::string::npos)
        << e.what();
  }
}

TEST(BrepBuilder, ScaledSceneGivesScaledElements) {
  // every tolerance and grid derives from the length scale: the same elements at any unit
  const Solid ref = build_solid(test::three_spheres(), nullptr);
  for (double s : {1e-3, 1e3}) {
    SceneSpec scene;
    scene.A = test::three_spheres();
    scene.B = test::example_B();
    const SceneSpec scaled = scaled_scene(scene, s);
    const Solid S = build_solid(scaled.A, nullptr);
    ASSERT_EQ(S.faces.size(), ref.faces.size()) << s;
    ASSERT_EQ(S.edges.size(), ref.edges.size()) << s;
    ASSERT_EQ(S.vertices.size(), ref.vertices.size()) << s;
    for (std::size_t e = 0; e < S.edges.size(); ++e)
      EXPECT_NEAR(S.edges[e].length, s * ref.edges[e].length, 1e-9 * s) << s;
    EXPECT_TRUE(S.bbox.max().isApprox(s * ref.bbox.max(), 1e-9)) << s;
  }
}

}  // namespace
}  // namespace pcsg
