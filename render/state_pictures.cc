#include "render/state_pictures.h"

#include <algorithm>
#include <cmath>

#include "render/canvas.h"
#include "render/frame_camera.h"
#include "render/framed_scene.h"

namespace pcsg::render {

namespace {

// Thumbnails are rendered this much larger than asked, then cropped: the renderer keeps ~1/4
// of the width and ~1/5 of the height free for labels, which thumbnails do not draw.
constexpr double kOversize = 1.3;
// White kept around the union of the thumbnails' content, in pixels.
constexpr int kCropPadding = 6;
// Contact rings in thumbnails, in pixels: the renderer's markers are ~7 px wide at this size.
constexpr double kRingRadius = 7, kRingWidth = 2;

}  // namespace

FrameRequest state_frame_request(const SceneGeometry& scene, const State& state,
                                 const StatePictureOptions& o) {
  FrameRequest f;
  f.width = o.width;
  f.height = o.height;
  f.camera = o.camera;
  f.X_BA = state.pose;
  f.contacts = state.contacts;
  f.show_labels = o.labels;
  if (o.header) {
    f.title = scene.spec.name;
    f.subtitle = "state " + std::to_string(state.id) + (state.seed ? " (seed): " : ": ") +
                 state.cf.str(scene);
  }
  return f;
}

std::vector<std::string> state_caption(const State& state, const SceneGeometry& scene) {
  return {"state " + std::to_string(state.id) + (state.seed ? " (seed)" : ""),
          state.cf.str(scene)};
}

std::vector<Image> draw_state_thumbnails(const SceneGeometry& scene,
                                         const std::vector<State>& states,
                                         const StatePictureOptions& o) {
  if (states.empty()) return {};
  std::vector<Pose> poses;
  for (const State& s : states) poses.push_back(s.pose);
  const SceneGeometry framed = framed_scene(scene, extent_of_A(scene, poses));
  SceneRenderer renderer(framed);
  StatePictureOptions big = o;
  big.width = static_cast<int>(std::lround(o.width * kOversize));
  big.height = static_cast<int>(std::lround(o.height * kOversize));
  big.header = false;
  std::vector<Image> pictures;
  PixelBounds all{big.width, big.height, 0, 0};
  for (const State& s : states) {
    const FrameRequest request = state_frame_request(framed, s, big);
    Image picture = renderer.render(request);
    const CameraView view = frame_camera_view(framed, request);
    Canvas canvas(picture);
    for (const PointContact& c : s.contacts)
      canvas.stroke_circle(view.project(c.point_B), kRingRadius, palette::kContact, kRingWidth);
    const PixelBounds b = content_bounds(picture, palette::kBackground);
    if (!b.empty()) {
      all.x0 = std::min(all.x0, b.x0), all.y0 = std::min(all.y0, b.y0);
      all.x1 = std::max(all.x1, b.x1), all.y1 = std::max(all.y1, b.y1);
    }
    pictures.push_back(std::move(picture));
  }
  if (all.empty()) return pictures;
  for (Image& p : pictures)
    p = cropped(p, all.x0 - kCropPadding, all.y0 - kCropPadding,
                all.x1 - all.x0 + 2 * kCropPadding, all.y1 - all.y0 + 2 * kCropPadding);
  return pictures;
}

}  // namespace pcsg::render
