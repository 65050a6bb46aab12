#pragma once
// One state of a generated graph (DIR/graph.json, written by `pcsg generate`), as the renderer
// needs it: the witness pose X_BA, its contacts and the contact formation's text.
#include <string>
#include <vector>

#include "engine/contact/contact.h"
#include "engine/core/pose.h"
#include "engine/geometry/scene_geometry.h"

namespace pcsg::app {

struct GraphStateView {
  int id = -1;
  std::string cf_text;                 // e.g. "{(fA-f1, 2)}"
  Pose pose;                           // X_BA
  std::vector<PointContact> contacts;  // a, b, type, point_B and normal_B filled
};

// Reads the state whose "id" is `state` from <dir>/graph.json:
//   {"states": [{"id": 0, "cf": [...], "cf_text": "...",
//                "pose": {"position": [x,y,z], "quaternion": [w,x,y,z]},
//                "contacts": [{"a": "fA", "b": "f1", "type": "f-f",
//                              "point": [..], "normal": [..]}]}]}
// Element names are resolved against `scene`. Throws Error naming the file, the state and the
// offending value when the file is missing or malformed, and UsageError when no state has
// that id (listing the ids there are).
GraphStateView read_graph_state(const std::string& dir, int state, const SceneGeometry& scene);

}  // namespace pcsg::app
