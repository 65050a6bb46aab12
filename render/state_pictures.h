#pragma once
// Pictures of the states of a graph: each state alone (A at its witness pose, its contacts
// marked), and thumbnails of all states framed alike for diagrams and grids (paper Fig. 6, 8).
#include <string>
#include <vector>

#include "engine/generator/graph.h"
#include "render/camera.h"
#include "render/scene_renderer.h"

namespace pcsg::render {

struct StatePictureOptions {
  int width = 300, height = 240;  // for thumbnails: about, after cropping to the content
  Camera camera;
  bool labels = false;  // element labels (readable from ~480 px high)
  bool header = false;  // the scene name and the state's CF above the objects
};

// The request that draws a state: A at its witness pose, its contacts marked.
FrameRequest state_frame_request(const SceneGeometry& scene, const State& state,
                                 const StatePictureOptions& options);

// Thumbnails of `states`, all of one size and framing: rendered with one camera framed on B
// and A at every state's pose (render/framed_scene.h), each contact ringed so that it shows
// at this size, then cropped alike to the union of their drawn content.
std::vector<Image> draw_state_thumbnails(const SceneGeometry& scene,
                                         const std::vector<State>& states,
                                         const StatePictureOptions& options);

// "state 3 (seed)" and the CF, the caption of a state under its picture.
std::vector<std::string> state_caption(const State& state, const SceneGeometry& scene);

}  // namespace pcsg::render
