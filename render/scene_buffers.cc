#include "render/scene_buffers.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <string>

#include "engine/core/error.h"

namespace pcsg::render {

namespace {

void check_mesh(const Solid& solid, const SolidMesh& mesh) {
  const std::string who = "mesh of solid '" + solid.name + "'";
  if (mesh.normals.size() != mesh.positions.size()) {
    throw Error(who + ": " + std::to_string(mesh.normals.size()) + " normals for " +
                std::to_string(mesh.positions.size()) + " positions");
  }
  if (mesh.triangle_face.size() != mesh.triangles.size()) {
    throw Error(who + ": " + std::to_string(mesh.triangle_face.size()) + " face tags for " +
                std::to_string(mesh.triangles.size()) + " triangles");
  }
  if (solid.faces.size() > kMaxShaderElements || solid.edges.size() > kMaxShaderElements) {
    throw Error("solid '" + solid.name + "' has " + std::to_string(solid.faces.size()) +
                " faces and " + std::to_string(solid.edges.size()) +
                " edges; the renderer draws at most " + std::to_string(kMaxShaderElements) +
                " of each");
  }
  if (mesh.edge_polylines.size() > solid.edges.size()) {
    throw Error(who + ": " + std::to_string(mesh.edge_polylines.size()) + " edge polylines for " +
                std::to_string(solid.edges.size()) + " edges");
  }
  const int n = static_cast<int>(mesh.positions.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      if (tri[k] < 0 || tri[k] >= n) {
        throw Error(who + ": triangle " + std::to_string(t) + " uses vertex " +
                    std::to_string(tri[k]) + " of " + std::to_string(n));
      }
    }
    const int f = mesh.triangle_face[t];
    if (f < 0 || f >= static_cast<int>(solid.faces.size())) {
      throw Error(who + ": triangle " + std::to_string(t) + " is tagged with face " +
                  std::to_string(f) + " of " + std::to_string(solid.faces.size()));
    }
  }
}

void to_floats(const Eigen::Vector3d& v, float out[3]) {
  out[0] = static_cast<float>(v.x());
  out[1] = static_cast<float>(v.y());
  out[2] = static_cast<float>(v.z());
}

Eigen::Vector3f position_of(const SurfaceVertex& v) {
  return {v.position[0], v.position[1], v.position[2]};
}

}  // namespace

ObjectGeometry prepare_object_geometry(const Solid& solid, const SolidMesh& mesh, Object object) {
  check_mesh(solid, mesh);
  ObjectGeometry g;
  const std::size_t n = mesh.positions.size();
  const std::int32_t object_index = object == Object::A ? 0 : 1;

  // vertices used by more than one face lie on edges
  std::vector<int> first_face(n, -1);
  std::vector<char> shared(n, 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (first_face[v] < 0) {
        first_face[v] = mesh.triangle_face[t];
      } else if (first_face[v] != mesh.triangle_face[t]) {
        shared[v] = 1;
      }
    }
  }

  // triangles grouped by face (stable, so the order inside a face is the mesh's)
  std::vector<std::size_t> order(mesh.triangles.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return mesh.triangle_face[a] < mesh.triangle_face[b];
  });

  // the mesher's per-corner normals are the face's own at edge vertices, when it provides them
  const bool has_corner_normals = mesh.corner_normals.size() == 3 * mesh.triangles.size();
  std::vector<std::int32_t> remap(n, -1);
  std::vector<int> touched;
  int current_face = -1;
  for (std::size_t t : order) {
    const int f = mesh.triangle_face[t];
    if (f != current_face) {  // a new face: its vertices are new copies
      for (int v : touched) remap[v] = -1;
      touched.clear();
      current_face = f;
    }
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (remap[v] < 0) {
        remap[v] = static_cast<std::int32_t>(g.surface_vertices.size());
        touched.push_back(v);
        Eigen::Vector3d normal = mesh.normals[v];
        const int surface = solid.faces[f].surface;
        if (shared[v] && has_corner_normals) {
          normal = mesh.corner_normals[3 * t + static_cast<std::size_t>(k)];
        } else if (shared[v] && surface >= 0 && surface < static_cast<int>(solid.surfaces.size())) {
          const Eigen::Vector3d grad = solid.surfaces[surface].gradient(mesh.positions[v]);
          if (grad.norm() > 0) normal = grad.normalized();  // solid side is g <= 0: outward
        }
        SurfaceVertex sv;
        to_floats(mesh.positions[v], sv.position);
        to_floats(normal, sv.normal);
        sv.element = f;
        sv.object = object_index;
        g.surface_vertices.push_back(sv);
      }
      g.surface_indices.push_back(static_cast<std::uint32_t>(remap[v]));
    }
  }

  for (std::size_t e = 0; e < mesh.edge_polylines.size(); ++e) {
    const auto& line = mesh.edge_polylines[e];
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
      EdgeVertex a, b;
      to_floats(line[k], a.position);
      to_floats(line[k + 1], b.position);
      a.element = b.element = static_cast<std::int32_t>(e);
      a.object = b.object = object_index;
      g.edge_vertices.push_back(a);
      g.edge_vertices.push_back(b);
    }
  }
  return g;
}

std::vector<std::uint32_t> back_to_front(const std::vector<Eigen::Vector3f>& centroids,
                                         const Eigen::Vector3f& eye, const Eigen::Vector3f& back) {
  // depth along the view direction; the sort key packs it with the index, so that equal
  // depths keep the static order and the result never depends on the sort's internals
  std::vector<std::pair<float, std::uint32_t>> keyed(centroids.size());
  for (std::size_t t = 0; t < centroids.size(); ++t) {
    keyed[t] = {(eye - centroids[t]).dot(back), static_cast<std::uint32_t>(t)};
  }
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  std::vector<std::uint32_t> order(keyed.size());
  for (std::size_t t = 0; t < keyed.size(); ++t) order[t] = keyed[t].second;
  return order;
}

void SceneBuffers::upload(const ObjectGeometry& a, const ObjectGeometry& b) {
  // both solids' triangles as corner triples, A's first
  corners_.clear();
  centroids_own_.clear();
  for (const ObjectGeometry* g : {&a, &b}) {
    for (std::size_t t = 0; t + 2 < g->surface_indices.size(); t += 3) {
      Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
      for (std::size_t k = 0; k < 3; ++k) {
        const SurfaceVertex& v = g->surface_vertices[g->surface_indices[t + k]];
        corners_.push_back(v);
        centroid += position_of(v) / 3.f;
      }
      centroids_own_.push_back(centroid);
    }
  }
  triangles_A_ = a.surface_indices.size() / 3;

  surface_vao_ = GlHandle(GlKind::VertexArray);
  surface_vbo_ = GlHandle(GlKind::Buffer);
  glBindVertexArray(surface_vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, surface_vbo_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners_.size() * sizeof(SurfaceVertex)),
               corners_.data(), GL_DYNAMIC_DRAW);
  const auto stride = static_cast<GLsizei>(sizeof(SurfaceVertex));
  auto at = [](std::size_t offset) { return reinterpret_cast<const void*>(offset); };
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(SurfaceVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(SurfaceVertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribIPointer(2, 1, GL_INT, stride, at(offsetof(SurfaceVertex, element)));
  glEnableVertexAttribArray(3);
  glVertexAttribIPointer(3, 1, GL_INT, stride, at(offsetof(SurfaceVertex, object)));

  // the same triangles indexed, in their static order, for the id pass
  std::vector<SurfaceVertex> vertices = a.surface_vertices;
  vertices.insert(vertices.end(), b.surface_vertices.begin(), b.surface_vertices.end());
  std::vector<std::uint32_t> indices = a.surface_indices;
  const auto offset = static_cast<std::uint32_t>(a.surface_vertices.size());
  for (std::uint32_t i : b.surface_indices) indices.push_back(i + offset);
  indexed_vao_ = GlHandle(GlKind::VertexArray);
  indexed_vbo_ = GlHandle(GlKind::Buffer);
  indexed_ibo_ = GlHandle(GlKind::Buffer);
  glBindVertexArray(indexed_vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, indexed_vbo_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(SurfaceVertex)),
               vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexed_ibo_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(SurfaceVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(SurfaceVertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribIPointer(2, 1, GL_INT, stride, at(offsetof(SurfaceVertex, element)));
  glEnableVertexAttribArray(3);
  glVertexAttribIPointer(3, 1, GL_INT, stride, at(offsetof(SurfaceVertex, object)));
  indexed_count_ = static_cast<GLsizei>(indices.size());

  std::vector<EdgeVertex> edges = a.edge_vertices;
  edges.insert(edges.end(), b.edge_vertices.begin(), b.edge_vertices.end());
  edge_vao_ = GlHandle(GlKind::VertexArray);
  edge_vbo_ = GlHandle(GlKind::Buffer);
  glBindVertexArray(edge_vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, edge_vbo_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(edges.size() * sizeof(EdgeVertex)),
               edges.data(), GL_STATIC_DRAW);
  const auto edge_stride = static_cast<GLsizei>(sizeof(EdgeVertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, edge_stride, at(offsetof(EdgeVertex, position)));
  glEnableVertexAttribArray(2);
  glVertexAttribIPointer(2, 1, GL_INT, edge_stride, at(offsetof(EdgeVertex, element)));
  glEnableVertexAttribArray(3);
  glVertexAttribIPointer(3, 1, GL_INT, edge_stride, at(offsetof(EdgeVertex, object)));
  edge_vertex_count_ = static_cast<GLsizei>(edges.size());
  glBindVertexArray(0);
}

void SceneBuffers::sort_back_to_front(const CameraView& view, const Pose& X_WA) {
  const Eigen::Matrix3f R = X_WA.rotation().cast<float>();
  const Eigen::Vector3f t = X_WA.position.cast<float>();
  const std::size_t n = centroids_own_.size();
  centroids_W_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = centroids_own_[i];
    centroids_W_[i] = i < triangles_A_ ? Eigen::Vector3f(R * p + t) : p;
  }
  const std::vector<std::uint32_t> order =
      back_to_front(centroids_W_, view.eye.cast<float>(), view.back.cast<float>());
  sorted_.resize(corners_.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    std::copy_n(&corners_[3 * static_cast<std::size_t>(order[k])], 3, &sorted_[3 * k]);
  }
  glBindBuffer(GL_ARRAY_BUFFER, surface_vbo_.id());
  glBufferSubData(GL_ARRAY_BUFFER, 0,
                  static_cast<GLsizeiptr>(sorted_.size() * sizeof(SurfaceVertex)), sorted_.data());
}

void SceneBuffers::draw_surfaces() const {
  if (corners_.empty()) return;
  glBindVertexArray(surface_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners_.size()));
}

void SceneBuffers::draw_surfaces_unsorted() const {
  if (indexed_count_ == 0) return;
  glBindVertexArray(indexed_vao_.id());
  glDrawElements(GL_TRIANGLES, indexed_count_, GL_UNSIGNED_INT, nullptr);
}

void SceneBuffers::draw_edges() const {
  if (edge_vertex_count_ == 0) return;
  glBindVertexArray(edge_vao_.id());
  glDrawArrays(GL_LINES, 0, edge_vertex_count_);
}

}  // namespace pcsg::render
