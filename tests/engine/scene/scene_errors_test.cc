// Invalid scene files: each must be rejected with a SceneError whose message names the file,
// the place (line:column in the file) and the offending value, and says what was expected.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/scene/scene.h"

namespace pcsg {
namespace {

const std::string kDataDir = std::string(PCSG_SOURCE_DIR) + "/tests/data/scenes/";

struct BadScene {
  std::string file;  // under tests/data/scenes/
  int line, column;  // 1-based, in that file
  std::vector<std::string> words;
};

// Loads `file` expecting a SceneError at line:column whose message contains `words`.
void expect_rejected(const BadScene& c) {
  const std::string path = kDataDir + c.file;
  try {
    load_scene_file(path);
    ADD_FAILURE() << c.file << " was accepted";
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    const std::string place = path + ":" + std::to_string(c.line) + ":" + std::to_string(c.column);
    EXPECT_EQ(msg.rfind(place + ": ", 0), 0u) << "expected to start with " << place << ": " << msg;
    EXPECT_EQ(e.where().file, path);
    EXPECT_EQ(e.where().line, c.line) << msg;
    EXPECT_EQ(e.where().column, c.column) << msg;
    for (const std::string& w : c.words)
      EXPECT_NE(msg.find(w), std::string::npos) << "'" << w << "' missing from: " << msg;
  }
}

TEST(SceneErrors, StructureOfTheFile) {
  const std::vector<BadScene> cases = {
      {"yaml_syntax_error.yaml", 8, 4, {"YAML syntax error", "end of sequence flow not found"}},
      {"unknown_top_key.yaml", 9, 1, {"unknown key 'seed'", "expected name, objects, seeds"}},
      {"unknown_object_key.yaml", 4, 5,
       {"unknown key 'face' in object A", "expected faces, edges, vertices"}},
      {"missing_b.yaml", 2, 1, {"missing object 'B'", "expected both A and B"}},
      {"no_faces.yaml", 7, 5, {"object B has no faces", "at least one inequality"}},
      {"duplicate_name.yaml", 11, 7,
       {"duplicate name 'f1' in object B (edge)", "already used at", "duplicate_name.yaml:8:7"}},
  };
  for (const BadScene& c : cases) expect_rejected(c);
}

TEST(SceneErrors, InequalitiesPointIntoTheString) {
  // columns count the opening quote and the raw escape sequences of the file
  const std::vector<BadScene> cases = {
      {"bad_character.yaml", 5, 24,
       {"face 'fA' of object A: unexpected character '$'", "\"x^2 + y^2 + $z^2 <= 1\""}},
      {"unbalanced_parenthesis.yaml", 5, 12, {"unbalanced parenthesis", "never closed"}},
      {"degree_five.yaml", 9, 34, {"product has degree 5", "maximum degree is 4"}},
      {"no_operator.yaml", 5, 12, {"no inequality operator", "'<=' or '>='"}},
      {"strict_inequality.yaml", 5, 28, {"'<' is not supported", "write '<='"}},
      {"quoted_escape.yaml", 8, 24, {"unexpected character '$'"}},
      {"constant_face.yaml", 8, 12,
       {"face 'f1' of object B", "\"x^2 - x^2 <= 4\" is constant", "degree 2 to 4"}},
      {"plane_face.yaml", 9, 12,
       {"face 'f2' of object B", "\"z >= -1\" is a plane: not strictly curved"}},
  };
  for (const BadScene& c : cases) expect_rejected(c);
}

TEST(SceneErrors, EdgesAndVerticesNameKnownDistinctFaces) {
  const std::vector<BadScene> cases = {
      {"edge_unknown_face.yaml", 11, 16,
       {"edge 'e1' of object B names unknown face 'f3'", "faces of object B are f1, f2"}},
      {"edge_same_face.yaml", 11, 16, {"edge 'e1' of object B names face 'f2' twice"}},
      {"vertex_two_faces.yaml", 11, 11,
       {"vertex 'v1' of object B", "three or more face names", "got 2 entries"}},
  };
  for (const BadScene& c : cases) expect_rejected(c);
}

TEST(SceneErrors, MalformedSeeds) {
  const std::vector<BadScene> cases = {
      {"seed_wrong_arity.yaml", 11, 16,
       {"seed 2 position", "expected 3 numbers [x, y, z]", "got 2 entries"}},
      {"seed_zero_quaternion.yaml", 11, 17,
       {"seed 1 quaternion [0, 0, 0, 0] is zero", "non-zero rotation [w, x, y, z]"}},
      {"seed_not_a_number.yaml", 10, 20,
       {"seed 1 position[1]", "expected a finite number", "got 'zero'"}},
  };
  for (const BadScene& c : cases) expect_rejected(c);
}

TEST(SceneErrors, MissingFileNamesThePath) {
  const std::string path = kDataDir + "no_such_scene.yaml";
  try {
    load_scene_file(path);
    ADD_FAILURE() << "a missing file was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": cannot open the scene file", 0), 0u)
        << e.what();
  }
}

// In-memory texts for the cases that need no file of their own.
std::string rejected_text(const std::string& yaml) {
  try {
    parse_scene(yaml, "inline.yaml");
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << yaml;
  return "";
}

const char* kFacesAB =
    "objects:\n"
    "  A: {faces: {fA: \"x^2 + y^2 + z^2 <= 1\"}}\n"
    "  B: {faces: {f1: \"x^2 + y^2 + z^2 <= 16\", f2: \"x^2 + y^2 - 4z <= 16\"}}\n";

TEST(SceneErrors, MoreStructureErrors) {
  EXPECT_NE(rejected_text("").find("inline.yaml:1:1: the scene is empty"), std::string::npos);
  EXPECT_NE(rejected_text("- a\n- b\n").find("inline.yaml:1:1: expected a map"),
            std::string::npos);
  EXPECT_NE(rejected_text("name: x\n").find("inline.yaml:1:1: missing 'objects'"),
            std::string::npos);
  EXPECT_NE(rejected_text(std::string(kFacesAB) + "  C: {faces: {fC: \"x^2 <= 1\"}}\n")
                .find("inline.yaml:4:3: unknown key 'C' in objects; expected A, B"),
            std::string::npos);
  EXPECT_NE(rejected_text(std::string(kFacesAB) + "seeds: manual\n")
                .find("inline.yaml:4:8: seeds: expected 'auto' or a list of {position: "
                      "[x, y, z], quaternion: [w, x, y, z]}, got 'manual'"),
            std::string::npos);
  EXPECT_NE(rejected_text(std::string(kFacesAB) + "seeds: []\n").find("got an empty list"),
            std::string::npos);
  EXPECT_NE(rejected_text(std::string(kFacesAB) + "seeds:\n  - {position: [0, 0, 1]}\n")
                .find("inline.yaml:5:5: seed 1: missing 'quaternion: [w, x, y, z]'"),
            std::string::npos);
  EXPECT_NE(rejected_text(std::string(kFacesAB) +
                          "seeds:\n  - {position: [0, 0, .nan], quaternion: [1, 0, 0, 0]}\n")
                .find("seed 1 position[2]: expected a finite number, got '.nan'"),
            std::string::npos);
  EXPECT_NE(rejected_text("objects:\n  A: {faces: {fA: [x, y]}}\n  B: {faces: {f: \"x^2<=1\"}}\n")
                .find("inline.yaml:2:19: face 'fA' of object A: expected an inequality"),
            std::string::npos);
  EXPECT_NE(rejected_text("objects:\n  A:\n  B: {faces: {f: \"x^2<=1\"}}\n")
                .find("inline.yaml:2:3: object A has no faces"),
            std::string::npos);
  EXPECT_NE(rejected_text(std::string(kFacesAB) + "name: x\nname: y\n")
                .find("inline.yaml:5:1: duplicate key 'name' in the top level"),
            std::string::npos);
}

TEST(SceneErrors, FoldedPlainScalarPointsAtTheRightLine) {
  // "x^2 + y^2 + $ <= 1" written over two lines: the '$' is on the second one
  const std::string msg = rejected_text(
      "objects:\n  A:\n    faces:\n      fA: x^2 + y^2\n        + $ <= 1\n"
      "  B: {faces: {f1: \"x^2 <= 1\"}}\n");
  EXPECT_NE(msg.find("inline.yaml:5:11: face 'fA' of object A: unexpected character '$'"),
            std::string::npos)
      << msg;
}

TEST(SceneErrors, DuplicateNamesAcrossFacesEdgesVertices) {
  const std::string msg = rejected_text(
      "objects:\n"
      "  A: {faces: {fA: \"x^2 + y^2 + z^2 <= 1\"}}\n"
      "  B:\n"
      "    faces: {f1: \"x^2 + y^2 + z^2 <= 16\", f2: \"x^2 + y^2 - 4z <= 16\",\n"
      "            f3: \"x^2 + z^2 <= 9\"}\n"
      "    edges: {e1: [f1, f2]}\n"
      "    vertices: {e1: [f1, f2, f3]}\n");
  EXPECT_NE(msg.find("inline.yaml:7:16: duplicate name 'e1' in object B (vertex); it is "
                     "already used at inline.yaml:6:13"),
            std::string::npos)
      << msg;
  // two faces with one name (yaml-cpp keeps repeated keys, so the loader must catch them)
  EXPECT_NE(rejected_text("objects:\n  A:\n    faces:\n      f: \"x^2 + y^2 <= 1 + z^2\"\n"
                          "      f: \"x^2 + y^2 + z^2 <= 4\"\n  B: {faces: {g: \"x^2 <= 1\"}}\n")
                .find("inline.yaml:5:7: duplicate name 'f' in object A (face)"),
            std::string::npos);
}

}  // namespace
}  // namespace pcsg
