#pragma once
// A scene as written in a scene file (YAML, see README "Scene format"): two objects given by
// polynomial inequalities, optional names for edges and vertices, and the seeds.
// Object B's frame is the world frame; A's faces are written in A's own frame.
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/pose.h"
#include "engine/poly/polynomial.h"

namespace pcsg {

// One inequality of an object. The solid lies where g(p) <= 0; the face lies on g(p) = 0.
struct FaceSpec {
  std::string name;  // "fA", "f1", ...
  std::string text;  // the inequality as written
  Polynomial g;      // normalised so that the solid side is g <= 0
  SourceLocation where;
};

// A user-given name for the curve where two faces meet.
struct EdgeNameSpec {
  std::string name;
  std::string face1, face2;
  SourceLocation where;
};

// A user-given name for the point where three or more faces meet.
struct VertexNameSpec {
  std::string name;
  std::vector<std::string> faces;
  SourceLocation where;
};

struct ObjectSpec {
  std::string name;  // "A" or "B"
  std::vector<FaceSpec> faces;
  std::vector<EdgeNameSpec> edges;
  std::vector<VertexNameSpec> vertices;
  SourceLocation where;
};

struct SeedSpec {
  Pose pose;
  SourceLocation where;
};

struct SceneSpec {
  std::string name;
  std::string path;  // the file it came from ("" for in-memory text)
  ObjectSpec A, B;
  bool auto_seeds = true;        // `seeds: auto` (the default)
  std::vector<SeedSpec> seeds;   // listed seed poses (X_BA), when not auto
};

// Reads and parses a scene file. Throws SceneError (file, line, column, value) for a missing
// file, YAML or polynomial syntax errors, unknown keys, duplicate or unknown names.
SceneSpec load_scene_file(const std::string& path);
// The same from text; `path` is used in messages only.
SceneSpec parse_scene(const std::string& yaml_text, const std::string& path);

// The same scene with both objects scaled by s about B's origin (A's frame scaled likewise,
// seed positions scaled): used by the invariance tests and the stress scenes.
SceneSpec scaled_scene(const SceneSpec& scene, double s);
// The same scene with B's frame moved: B's faces are rewritten in a frame where B has been
// moved by X (p_new = X p_old); seeds are moved with it, A's faces are unchanged.
SceneSpec moved_scene(const SceneSpec& scene, const Pose& X);

}  // namespace pcsg
