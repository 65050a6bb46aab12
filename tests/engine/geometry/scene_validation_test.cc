// Every scene error and warning of the geometry kernel, with its message.
#include <gtest/gtest.h>

#include "engine/geometry/scene_geometry.h"
#include "tests/engine/geometry/test_objects.h"

namespace pcsg {
namespace {

SceneSpec scene_with_A(const ObjectSpec& A) {
  SceneSpec s;
  s.A = A;
  s.B = test::example_B();
  return s;
}

// The message of the SceneError that building `scene` throws ("" when none).
std::string error_of(const SceneSpec& scene) {
  try {
    build_scene_geometry(scene);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << text

TEST(SceneValidation, StraightSegmentsAreRejected) {
  struct Case {
    const char* what;
    const char* inequality;
  };
  for (const Case c : {Case{"plane", "z <= 0.5"}, Case{"cylinder", "x^2 + y^2 <= 1"},
                       Case{"cone", "x^2 + y^2 <= (z + 0.5)^2"},
                       Case{"one-sheet hyperboloid", "x^2 + y^2 - z^2 <= 1"},
                       Case{"hyperbolic paraboloid", "z <= x y + 0.5"}}) {
    const std::string msg =
        error_of(scene_with_A(test::object("A", {{"ball", "x^2 + y^2 + z^2 <= 4"},
                                                 {"ruled", c.inequality}})));
    EXPECT_HAS(msg, "test.yaml:3:1: face ruled") << c.what;
    EXPECT_HAS(msg, "contains a straight segment") << c.what;
    EXPECT_HAS(msg, c.inequality) << c.what;
  }
}

TEST(SceneValidation, EmptySolidIsRejected) {
  const std::string msg = error_of(scene_with_A(test::object(
      "A", {{"a", "x^2 + y^2 + z^2 <= 1"}, {"b", "(x - 5)^2 + y^2 + z^2 <= 1"}})));
  EXPECT_HAS(msg, "test.yaml:1:1: object A is empty");
}

TEST(SceneValidation, UnboundedSolidsAreRejected) {
  // a paraboloid (top-degree part zero along its axis), a cylinder, and a two-sheet
  // hyperboloid's inside (top-degree part negative around the axis)
  for (const char* ineq : {"x^2 + y^2 <= z", "x^2 + (y - 3)^2 <= 1", "z^2 >= x^2 + y^2 + 1",
                           "(x - 0.3)^2 + y^2 <= 2(z - 0.1x) + 7"}) {
    const std::string msg = error_of(scene_with_A(test::object("A", {{"u", ineq}})));
    EXPECT_HAS(msg, "test.yaml:1:1: object A is unbounded: it extends to infinity along");
  }
  // the same shapes scaled by 1000: the decision does not depend on the unit
  const std::string big = error_of(scene_with_A(test::object("A", {{"u", "x^2 + y^2 <= 1000z"}})));
  EXPECT_HAS(big, "is unbounded");
}

TEST(SceneValidation, RedundantInequalityIsAWarning) {
  const SceneGeometry g = build_scene_geometry(scene_with_A(
      test::object("A", {{"inner", "x^2 + y^2 + z^2 <= 1"}, {"outer", "x^2 + y^2 + z^2 <= 4"}})));
  ASSERT_EQ(g.warnings.size(), 1u);
  EXPECT_HAS(g.warnings[0], "test.yaml:3:1: object A: inequality outer");
  EXPECT_HAS(g.warnings[0], "contributes no face");
  EXPECT_EQ(g.A.faces.size(), 1u);
}

TEST(SceneValidation, TangentialFacesAreRejected) {
  // the quadratic Taylor polynomial (in r^2) of the lower hemisphere z = -sqrt(4 - r^2) at
  // r^2 = 3 crosses the sphere with third-order contact on the circle r = sqrt(3), z = -1:
  // the solid's boundary switches surfaces there, with parallel normals
  const std::string msg = error_of(scene_with_A(test::object(
      "A", {{"ball", "x^2 + y^2 + z^2 <= 4"},
            {"cup", "z >= -1 + 0.5(x^2 + y^2 - 3) + 0.125(x^2 + y^2 - 3)^2"}})));
  EXPECT_HAS(msg, "test.yaml:2:1: faces ball and cup meet tangentially at");
  EXPECT_HAS(msg, "no proper edge");
}

TEST(SceneValidation, NamedEdgeWhoseFacesNeverMeetIsRejected) {
  SceneSpec s = scene_with_A(test::object("A", {{"fA", "x^2 + y^2 + z^2 <= 1"}}));
  s.B.edges.push_back({"e3", "f1", "f3", {"test.yaml", 9, 7}});
  const std::string msg = error_of(s);
  EXPECT_HAS(msg, "test.yaml:9:7: edge 'e3': faces f1 and f3 never meet on the boundary of "
                  "object B");
}

TEST(SceneValidation, NamedVertexWhereFacesNeverMeetIsRejected) {
  SceneSpec s = scene_with_A(test::object("A", {{"fA", "x^2 + y^2 + z^2 <= 1"}}));
  s.B.vertices.push_back({"v1", {"f1", "f2", "f3"}, {"test.yaml", 10, 7}});
  EXPECT_HAS(error_of(s), "test.yaml:10:7: vertex 'v1': faces f1, f2, f3 never meet");
}

}  // namespace
}  // namespace pcsg
