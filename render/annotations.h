#pragma once
// The 2D layer drawn over the rendered objects with Dear ImGui draw lists: the header (scene
// name and state text), contact markers and normals, and the labels of every face, edge and
// vertex placed by the greedy layout with leader lines to anchors where the element shows.
#include <vector>

#include "engine/geometry/scene_geometry.h"
#include "render/camera.h"
#include "render/id_target.h"
#include "render/label_anchors.h"
#include "render/overlay.h"
#include "render/scene_renderer.h"

namespace pcsg::render {

struct AnnotationInput {
  const SceneGeometry* scene = nullptr;
  const FrameRequest* frame = nullptr;
  const CameraView* view = nullptr;
  Pose X_WA;                                             // where A is drawn
  const IdImage* ids = nullptr;                          // the element-id pass (null: no labels)
  const std::vector<ElementSamples>* samples = nullptr;  // world points of every element
};

// Height in pixels the header takes at the top of an image of the given height (0 without
// header text); the camera keeps the objects below it.
double header_height(const FrameRequest& frame);

// Draws everything into the overlay's current frame (inside Overlay::draw).
void draw_annotations(Overlay& overlay, const AnnotationInput& in);

}  // namespace pcsg::render
