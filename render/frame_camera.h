#pragma once
// The camera view SceneRenderer::render frames a request with (it calls this), also used for
// drawing over its images on the CPU (contact-role rings on transition frames): B's mesh and
// A's at its displayed pose fitted into the image below the header, with room for the labels
// at the sides and below. tests/render/frame_camera_test.cc checks that a contact the renderer
// marks lands where this view projects it.
#include "engine/geometry/scene_geometry.h"
#include "render/camera.h"
#include "render/scene_renderer.h"

namespace pcsg::render {

CameraView frame_camera_view(const SceneGeometry& scene, const FrameRequest& frame);

}  // namespace pcsg::render
