#include "render/scene_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/core/error.h"
#include "render/annotations.h"
#include "render/frame_camera.h"
#include "render/gl_context.h"
#include "render/gl_program.h"
#include "render/id_target.h"
#include "render/overlay.h"
#include "render/palette.h"
#include "render/scene_buffers.h"

namespace pcsg::render {

namespace {

// Edge width in pixels at the reference height of 960 (scaled with the image, at least 1 px):
// clearly darker and thicker than the shading, thin enough for the labels' leader lines.
constexpr double kEdgeWidthPx = 2.6;
constexpr double kReferenceHeight = 960;
// Collision edges are drawn this much wider than the others.
constexpr float kWarningEdgeWidth = 1.8f;
// Edges are moved this share of the scene's size toward the eye: far more than the depth
// buffer's resolution at the faces they bound, far less than any gap between two surfaces.
constexpr double kEdgeDepthBiasShare = 4e-3;
// The element-id pass runs at 1/kIdDownscale of the image's linear resolution.
constexpr int kIdDownscale = 4;
// In the id image, edges are drawn this wide (id pixels) so that none is missed between pixels.
constexpr float kIdEdgeWidth = 1.5f;
// Gap between B and A in the apart view, as a share of the larger object's bbox diagonal.
constexpr double kApartGapShare = 0.12;
// The context's first target size (resized on the first frame of another size).
constexpr int kInitialWidth = 1280, kInitialHeight = 960;
// Face samples kept per face for label anchors when a face is nowhere visible.
constexpr std::size_t kFaceSamples = 256;

Eigen::Matrix4f model_matrix(const Pose& X) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<3, 3>(0, 0) = X.rotation().cast<float>();
  m.block<3, 1>(0, 3) = X.position.cast<float>();
  return m;
}

double diagonal(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) return 0;
  Eigen::Vector3d lo = points.front(), hi = points.front();
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

}  // namespace

Pose display_pose_of_A(const SceneGeometry& scene, const std::optional<Pose>& X_BA,
                       const Camera& camera) {
  if (X_BA) return *X_BA;
  Eigen::Vector3d right, up, back;
  camera_basis(camera, &right, &up, &back);
  const auto& pa = scene.mesh_A.positions;
  const auto& pb = scene.mesh_B.positions;
  if (pa.empty() || pb.empty()) return Pose::identity();
  // A's extent to the left, B's to the right, along the camera's right direction
  double a_left = pa.front().dot(right), b_right = pb.front().dot(right);
  Eigen::Vector3d a_lo = pa.front(), a_hi = pa.front(), b_lo = pb.front(), b_hi = pb.front();
  for (const auto& p : pa) {
    a_left = std::min(a_left, p.dot(right));
    a_lo = a_lo.cwiseMin(p);
    a_hi = a_hi.cwiseMax(p);
  }
  for (const auto& p : pb) {
    b_right = std::max(b_right, p.dot(right));
    b_lo = b_lo.cwiseMin(p);
    b_hi = b_hi.cwiseMax(p);
  }
  const Eigen::Vector3d a_centre = 0.5 * (a_lo + a_hi), b_centre = 0.5 * (b_lo + b_hi);
  const double gap = kApartGapShare * std::max((a_hi - a_lo).norm(), (b_hi - b_lo).norm());
  // move A's centre onto B's, then slide it right until its left side clears B by the gap
  Pose X;
  X.position = b_centre - a_centre;
  const double a_left_moved = a_left + X.position.dot(right);
  X.position += right * (b_right + gap - a_left_moved);
  return X;
}

struct SceneRenderer::Impl {
  const SceneGeometry& scene;
  std::unique_ptr<GlContext> context;  // declared first: destroyed after every GL object
  GlProgram surface, surface_id, line, line_id;
  SceneBuffers buffers;
  IdTarget id_target;
  std::unique_ptr<Overlay> overlay;
  int width = 0, height = 0;
  double scene_size = 1;
  std::vector<ElementSamples> samples_own;  // element points in each solid's own frame

  Impl(const SceneGeometry& s, const RendererOptions& options) : scene(s) {
    context = create_gl_context(kInitialWidth, kInitialHeight, options.samples);
    width = kInitialWidth;
    height = kInitialHeight;
    surface = GlProgram({"surface.vert", "surface.frag"});
    surface_id = GlProgram({"surface.vert", "surface_id.frag"});
    line = GlProgram({"line.vert", "line.geom", "line.frag"});
    line_id = GlProgram({"line.vert", "line.geom", "line_id.frag"});
    buffers.upload(prepare_object_geometry(scene.A, scene.mesh_A, Object::A),
                   prepare_object_geometry(scene.B, scene.mesh_B, Object::B));
    id_target.allocate(id_size(width), id_size(height));
    overlay = std::make_unique<Overlay>();
    scene_size = std::max(diagonal(scene.mesh_A.positions), diagonal(scene.mesh_B.positions));
    if (!(scene_size > 0)) throw Error("scene '" + scene.spec.name + "' has empty meshes");
    collect_samples(Object::A, scene.A, scene.mesh_A);
    collect_samples(Object::B, scene.B, scene.mesh_B);
  }

  ~Impl() {
    context->make_current();  // the GL objects below are deleted in this context
  }

  static int id_size(int pixels) { return (pixels + kIdDownscale - 1) / kIdDownscale; }

  void collect_samples(Object object, const Solid& solid, const SolidMesh& mesh) {
    // label order: faces, then edges, then vertices; within a kind, the solid's order
    for (std::size_t f = 0; f < solid.faces.size(); ++f) {
      ElementSamples e{{object, {ElementKind::Face, static_cast<int>(f)}}, {}};
      std::vector<Eigen::Vector3d> all;
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.triangle_face[t] == static_cast<int>(f)) {
          all.push_back(mesh.positions[mesh.triangles[t][0]]);
        }
      }
      const std::size_t stride = std::max<std::size_t>(1, all.size() / kFaceSamples);
      for (std::size_t i = 0; i < all.size(); i += stride) e.points_W.push_back(all[i]);
      samples_own.push_back(std::move(e));
    }
    for (std::size_t i = 0; i < solid.edges.size(); ++i) {
      ElementSamples e{{object, {ElementKind::Edge, static_cast<int>(i)}}, {}};
      if (i < mesh.edge_polylines.size()) e.points_W = mesh.edge_polylines[i];
      samples_own.push_back(std::move(e));
    }
    for (std::size_t i = 0; i < solid.vertices.size(); ++i) {
      samples_own.push_back(
          {{object, {ElementKind::Vertex, static_cast<int>(i)}}, {solid.vertices[i].point}});
    }
  }

  void ensure_size(int w, int h) {
    if (w == width && h == height) return;
    context->resize(w, h);
    id_target.allocate(id_size(w), id_size(h));
    width = w;
    height = h;
  }

  // Colour and opacity of every face, colour and width factor of every edge: [object * 64 + i].
  void set_styles(GlProgram& program, const FrameRequest& f) {
    std::vector<float> faces(2 * 4 * kMaxShaderElements, 0.f);
    std::vector<float> edges(2 * 4 * kMaxShaderElements, 0.f);
    for (Object object : {Object::A, Object::B}) {
      const Solid& solid = object == Object::A ? scene.A : scene.B;
      const std::size_t base = object == Object::A ? 0 : 4 * kMaxShaderElements;
      auto highlighted = [&](ElementKind kind, std::size_t i) {
        const SceneElement e{object, {kind, static_cast<int>(i)}};
        return std::find(f.highlighted.begin(), f.highlighted.end(), e) != f.highlighted.end();
      };
      for (std::size_t i = 0; i < solid.faces.size(); ++i) {
        const bool warn = highlighted(ElementKind::Face, i);
        const Rgb c =
            warn ? palette::kWarning : palette::face(object == Object::B, static_cast<int>(i));
        const float alpha = warn ? palette::kWarningFaceAlpha : palette::kFaceAlpha;
        const float rgba[4] = {c.r, c.g, c.b, alpha};
        std::copy(rgba, rgba + 4, faces.begin() + static_cast<std::ptrdiff_t>(base + 4 * i));
      }
      for (std::size_t i = 0; i < solid.edges.size(); ++i) {
        const bool warn = highlighted(ElementKind::Edge, i);
        const Rgb c = warn ? palette::kWarning : palette::kEdge;
        const float rgba[4] = {c.r, c.g, c.b, warn ? kWarningEdgeWidth : 1.f};
        std::copy(rgba, rgba + 4, edges.begin() + static_cast<std::ptrdiff_t>(base + 4 * i));
      }
    }
    glUniform4fv(program.uniform("u_face_colors"), 2 * kMaxShaderElements, faces.data());
    glUniform4fv(program.uniform("u_edge_styles"), 2 * kMaxShaderElements, edges.data());
  }

  void set_camera(GlProgram& program, const CameraView& view, const Pose& X_WA) {
    Eigen::Matrix4f models[2] = {model_matrix(X_WA), Eigen::Matrix4f::Identity()};
    glUniformMatrix4fv(program.uniform("u_model"), 2, GL_FALSE, models[0].data());
    glUniformMatrix4fv(program.uniform("u_view"), 1, GL_FALSE, view.view.data());
    glUniformMatrix4fv(program.uniform("u_projection"), 1, GL_FALSE, view.projection.data());
  }

  void set_id_bases(GlProgram& program, ElementKind kind) {
    const GLint bases[2] = {element_id::base(Object::A, kind), element_id::base(Object::B, kind)};
    glUniform1iv(program.uniform("u_id_base"), 2, bases);
  }

  void draw_edges(GlProgram& program, const CameraView& view, const Pose& X_WA,
                  const FrameRequest& f, float width_px, int viewport_w, int viewport_h) {
    program.use();
    set_camera(program, view, X_WA);
    set_styles(program, f);
    set_id_bases(program, ElementKind::Edge);
    glUniform1f(program.uniform("u_depth_bias"),
                static_cast<float>(kEdgeDepthBiasShare * scene_size));
    glUniform2f(program.uniform("u_viewport"), static_cast<float>(viewport_w),
                static_cast<float>(viewport_h));
    glUniform1f(program.uniform("u_line_width"), width_px);
    buffers.draw_edges();
  }

  void draw_surfaces(GlProgram& program, const CameraView& view, const Pose& X_WA,
                     const FrameRequest& f, bool sorted) {
    program.use();
    set_camera(program, view, X_WA);
    set_styles(program, f);
    set_id_bases(program, ElementKind::Face);
    if (sorted) {
      buffers.draw_surfaces();
    } else {
      buffers.draw_surfaces_unsorted();
    }
  }

  Image render(const FrameRequest& f) {
    if (f.width < 1 || f.height < 1) {
      throw Error("image size " + std::to_string(f.width) + "x" + std::to_string(f.height) +
                  " must be at least 1x1");
    }
    context->make_current();
    ensure_size(f.width, f.height);

    // where A is drawn, and a camera that frames both objects below the header
    const Pose X_WA = display_pose_of_A(scene, f.X_BA, f.camera);
    const CameraView view = frame_camera_view(scene, f);
    const float scale = static_cast<float>(std::max(0.5, f.height / kReferenceHeight));
    const float edge_px = std::max(1.f, static_cast<float>(kEdgeWidthPx) * scale);
    buffers.sort_back_to_front(view, X_WA);

    // 1. opaque: background and edges, with depth
    const GLuint fbo = context->framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    const GLenum color0[] = {GL_COLOR_ATTACHMENT0};
    glDrawBuffers(1, color0);
    glViewport(0, 0, f.width, f.height);
    const GLfloat white[] = {palette::kBackground.r, palette::kBackground.g, palette::kBackground.b,
                             1.f};
    glClearBufferfv(GL_COLOR, 0, white);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);  // both sides of every surface are seen through the others
    glDisable(GL_SCISSOR_TEST);
    draw_edges(line, view, X_WA, f, edge_px, f.width, f.height);

    // 2. transparent faces, farthest first, blended "over" what is behind; the image's alpha
    //    stays 1 (the PNG is opaque)
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    draw_surfaces(surface, view, X_WA, f, true);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);

    // 3. element ids at low resolution, for the label anchors
    IdImage ids;
    if (f.show_labels) {
      id_target.begin();
      glDepthFunc(GL_LESS);
      draw_surfaces(surface_id, view, X_WA, f, false);
      glDepthFunc(GL_LEQUAL);
      draw_edges(line_id, view, X_WA, f, kIdEdgeWidth, id_target.width(), id_target.height());
      glDepthFunc(GL_LESS);
      ids = id_target.read(static_cast<double>(kIdDownscale));
    }

    // 4. header, markers and labels
    std::vector<ElementSamples> samples = samples_own;
    for (auto& e : samples) {
      if (e.element.object == Object::A) {
        for (auto& p : e.points_W) p = X_WA.apply(p);
      }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glDrawBuffers(1, color0);
    glViewport(0, 0, f.width, f.height);
    AnnotationInput in;
    in.scene = &scene;
    in.frame = &f;
    in.view = &view;
    in.X_WA = X_WA;
    in.ids = f.show_labels ? &ids : nullptr;
    in.samples = &samples;
    overlay->draw(f.width, f.height, [&](Overlay& o) { draw_annotations(o, in); });

    return context->read_pixels();
  }
};

SceneRenderer::SceneRenderer(const SceneGeometry& scene, const RendererOptions& options)
    : impl_(std::make_unique<Impl>(scene, options)) {}

SceneRenderer::~SceneRenderer() = default;

Image SceneRenderer::render(const FrameRequest& frame) { return impl_->render(frame); }

std::string SceneRenderer::gl_description() const {
  impl_->context->make_current();
  return impl_->context->description();
}

}  // namespace pcsg::render
