#pragma once
// The renderer the rest of pcsg uses: draws a scene's two objects (transparent, smoothly shaded,
// one colour per face, edges as dark lines of constant width), the contacts of a state as
// markers, every element's name with a leader line, and a header, into an RGBA image.
// One renderer keeps its GL context and the uploaded meshes for many frames. A renderer is
// used by one thread at a time; renderers in different threads may run concurrently (each
// has its own context; the ImGui step is serialised inside).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/contact/contact.h"
#include "engine/core/pose.h"
#include "engine/geometry/scene_geometry.h"
#include "render/camera.h"
#include "render/image.h"
#include "render/scene_element.h"

namespace pcsg::render {

struct RendererOptions {
  // Samples per pixel of the offscreen target (4x MSAA; 1 turns antialiasing off).
  int samples = 4;
};

struct FrameRequest {
  int width = 1280, height = 960;
  Camera camera;
  // A's pose in B's frame; nullopt draws the "objects apart" view: A unrotated, beside B.
  std::optional<Pose> X_BA;
  // Drawn as markers at point_B (B's frame = the world); normals from point_B along normal_B.
  std::vector<PointContact> contacts;
  bool show_normals = false;
  // Elements drawn in the warning colour (e.g. those of a collision).
  std::vector<SceneElement> highlighted;
  // Header: the scene's name and, below it, the state's text (e.g. its contact formation).
  std::string title;
  std::string subtitle;
  bool show_labels = true;
};

class SceneRenderer {
 public:
  // Creates the GL context and uploads both meshes. `scene` must outlive the renderer.
  // Throws pcsg::Error when no GL context can be created or a mesh is inconsistent.
  explicit SceneRenderer(const SceneGeometry& scene, const RendererOptions& options = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Renders one frame; rows top first. The same request gives the same pixels every time.
  Image render(const FrameRequest& frame);
  // The GL implementation in use, e.g. "OSMesa: llvmpipe (LLVM 15.0.6, 256 bits), 4.5 ...".
  std::string gl_description() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Where A is drawn: X_BA itself, or for the apart view (nullopt) a translation that puts A's
// bounding box beside B's, to the right as seen by `camera`, at the height of B's centre.
Pose display_pose_of_A(const SceneGeometry& scene, const std::optional<Pose>& X_BA,
                       const Camera& camera);

}  // namespace pcsg::render
