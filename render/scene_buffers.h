#pragma once
// The GPU copy of both solids, uploaded once: triangles split by face (each face gets its own
// vertices, so that it has its own colour and, along the edges it shares, its own exact
// normal) and edge polylines as line segments. Every frame the triangles are re-ordered from
// farthest to nearest, which makes the transparency order-correct (render/README.md).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "engine/core/pose.h"
#include "engine/geometry/mesh.h"
#include "engine/geometry/solid.h"
#include "render/camera.h"
#include "render/gl_handle.h"
#include "render/scene_element.h"

namespace pcsg::render {

// Per-object limit of the shaders' uniform arrays: shaders/ index u_face_colors[128] and
// u_edge_styles[128] as object * 64 + element (change both together).
inline constexpr int kMaxShaderElements = 64;

struct SurfaceVertex {
  float position[3];     // solid's own frame
  float normal[3];       // unit, outward
  std::int32_t element;  // face index
  std::int32_t object;   // 0: A, 1: B
};
struct EdgeVertex {
  float position[3];
  std::int32_t element;  // edge index
  std::int32_t object;
};

// The vertex data of one solid, built on the CPU (testable without GL).
struct ObjectGeometry {
  std::vector<SurfaceVertex> surface_vertices;
  std::vector<std::uint32_t> surface_indices;  // triangles, counter-clockwise from outside
  std::vector<EdgeVertex> edge_vertices;       // pairs: one segment each
};

// Splits the mesh by face. A vertex used by several faces (on an edge) gets, per face, that
// face's own normal: SolidMesh::corner_normals when the mesher filled them, else the gradient
// of the face's surface from Solid::surfaces (SolidMesh::normals holds one normal per vertex,
// which on an edge is right for neither face); other vertices keep the mesh's exact normal.
// Throws pcsg::Error naming the solid and the offending index when the mesh is inconsistent
// or has more than kMaxShaderElements faces or edges.
ObjectGeometry prepare_object_geometry(const Solid& solid, const SolidMesh& mesh, Object object);

// Order of the points from farthest to nearest along `back` (ties by index), world coordinates.
std::vector<std::uint32_t> back_to_front(const std::vector<Eigen::Vector3f>& centroids,
                                         const Eigen::Vector3f& eye, const Eigen::Vector3f& back);

class SceneBuffers {
 public:
  void upload(const ObjectGeometry& a, const ObjectGeometry& b);
  // Orders the triangles of both solids (A at X_WA) farthest first for the view.
  void sort_back_to_front(const CameraView& view, const Pose& X_WA);
  // The triangles in the last sorted order (for the shaded, blended pass).
  void draw_surfaces() const;
  // The triangles indexed in their static order: faster where order does not matter (ids).
  void draw_surfaces_unsorted() const;
  void draw_edges() const;

 private:
  // Triangles as three vertices each (no index buffer): a sorted index buffer would make
  // llvmpipe fetch vertices in random order, which tripled the surface pass (measured 40 ->
  // 118 ms at 1280x960); a vertex stream rewritten in sorted order is read linearly.
  std::vector<SurfaceVertex> corners_;          // 3 per triangle, static order
  std::vector<Eigen::Vector3f> centroids_own_;  // per triangle, in its solid's frame
  std::size_t triangles_A_ = 0;                 // A's triangles come first
  std::vector<Eigen::Vector3f> centroids_W_;    // scratch, per frame
  std::vector<SurfaceVertex> sorted_;           // scratch, per frame
  GlHandle surface_vao_, surface_vbo_;
  GlHandle indexed_vao_, indexed_vbo_, indexed_ibo_;
  GLsizei indexed_count_ = 0;
  GlHandle edge_vao_, edge_vbo_;
  GLsizei edge_vertex_count_ = 0;
};

}  // namespace pcsg::render
