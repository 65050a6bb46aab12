#pragma once
// Objects for the geometry tests, written as the inequalities of a scene file.
#include <initializer_list>
#include <string>
#include <utility>

#include "engine/poly/parser.h"
#include "engine/scene/scene.h"

namespace pcsg::test {

// An object from (name, inequality) pairs; each face's place is "test.yaml:<k+1>:1".
inline ObjectSpec object(const std::string& name,
                         std::initializer_list<std::pair<std::string, std::string>> faces) {
  ObjectSpec o;
  o.name = name;
  o.where = {"test.yaml", 1, 1};
  int line = 1;
  for (const auto& [fname, text] : faces) {
    FaceSpec f;
    f.name = fname;
    f.text = text;
    f.where = {"test.yaml", ++line, 1};
    f.g = parse_inequality(text, locate_from(f.where)).g;
    o.faces.push_back(f);
  }
  return o;
}

// The paper's object B (Examples 1 and 2): dish, sphere band, convex bottom.
inline ObjectSpec example_B() {
  return object("B", {{"f1", "4x^2 + 4y^2 - 10.07047z >= 15.75982"},
                      {"f2", "x^2 + y^2 + z^2 <= 16"},
                      {"f3", "x^2 + y^2 - 4z <= 16"}});
}

// Example 2's object A: two paraboloid caps meeting on the circle r = 1.5, z = 0.
inline ObjectSpec lens_A() {
  return object("A", {{"fA1", "8x^2 + 8y^2 - 9z <= 18"}, {"fA2", "8x^2 + 8y^2 + 9z <= 18"}});
}

// Three unit spheres centred on a triangle of side 1: three faces, three edges, two vertices.
inline ObjectSpec three_spheres() {
  return object("A", {{"s1", "x^2 + y^2 + z^2 <= 1"},
                      {"s2", "(x - 1)^2 + y^2 + z^2 <= 1"},
                      {"s3", "(x - 0.5)^2 + (y - 0.8660254037844386)^2 + z^2 <= 1"}});
}

// A torus: tube radius 1 around a circle of radius 2 in the xy plane.
inline ObjectSpec torus() {
  return object("A", {{"t", "(x^2 + y^2 + z^2 + 3)^2 - 16(x^2 + y^2) <= 0"}});
}

}  // namespace pcsg::test
