#include "engine/geometry/mesh_extremes.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "engine/geometry/surface.h"

namespace pcsg {
namespace {

// An extreme point lying beyond the mesh by more than this fraction of the chordal error is
// added: the inflation of the collision meshes covers one chordal error, and every mesh of the
// repository's scenes other than the needle's stays within 0.34 of it along each axis
// (measured), so only a grid-cut tip crosses one half.
constexpr double kCoverFraction = 0.5;
// The exact extreme must lie within this many chordal errors of the mesh's extreme vertex (a
// cut tip is a few grid cells long; a farther critical point is another one of the surface).
constexpr double kSearchChordal = 50;
// A tip's visible rim holds a few dozen triangles; a region larger than this is not a cut tip
// (a flat-ish face seen from a point barely above it) and is left alone.
constexpr size_t kMaxVisible = 4096;

struct Adjacency {
  std::vector<std::vector<int>> vertex_triangles;
  std::map<std::pair<int, int>, int> directed;  // (a, b) -> triangle with side a -> b
};

Adjacency adjacency(const SolidMesh& mesh) {
  Adjacency adj;
  adj.vertex_triangles.resize(mesh.positions.size());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int q = 0; q < 3; ++q) {
      adj.vertex_triangles[mesh.triangles[t][q]].push_back(t);
      adj.directed[{mesh.triangles[t][q], mesh.triangles[t][(q + 1) % 3]}] = t;
    }
  return adj;
}

// Inserts p (on face f) in place of the triangles it sees around vertex v. False (mesh
// untouched) when the seen region is not a disc of face-f triangles with free interior vertices.
bool insert_tip(const Solid& solid, SolidMesh& mesh, int v, int f, const Eigen::Vector3d& p) {
  const Adjacency adj = adjacency(mesh);
  auto sees = [&](int t) {
    const Eigen::Vector3d a = mesh.positions[mesh.triangles[t][0]],
                          b = mesh.positions[mesh.triangles[t][1]],
                          c = mesh.positions[mesh.triangles[t][2]];
    return (p - a).dot((b - a).cross(c - a)) > 0;
  };
  std::vector<char> visible(mesh.triangles.size(), 0);
  std::vector<int> stack, region;
  for (int t : adj.vertex_triangles[v])
    if (sees(t)) visible[t] = 1, stack.push_back(t);
  while (!stack.empty()) {
    const int t = stack.back();
    stack.pop_back();
    region.push_back(t);
    if (region.size() > kMaxVisible || mesh.triangle_face[t] != f) return false;
    for (int q = 0; q < 3; ++q) {
      const auto twin = adj.directed.find({mesh.triangles[t][(q + 1) % 3], mesh.triangles[t][q]});
      if (twin == adj.directed.end()) return false;  // not watertight here
      const int u = twin->second;
      if (!visible[u] && sees(u)) visible[u] = 1, stack.push_back(u);
    }
  }
  if (region.empty()) return false;
  // The rim: sides of seen triangles whose twin is unseen, a single cycle.
  std::map<int, int> next;
  for (int t : region)
    for (int q = 0; q < 3; ++q) {
      const int a = mesh.triangles[t][q], b = mesh.triangles[t][(q + 1) % 3];
      if (visible[adj.directed.at({b, a})]) continue;
      if (!next.emplace(a, b).second) return false;
    }
  if (next.size() < 3) return false;
  {
    std::map<int, char> seen;
    int a = next.begin()->first;
    for (size_t k = 0; k < next.size(); ++k) {
      if (!seen.emplace(a, 1).second) return false;  // a shorter cycle: several rims
      const auto it = next.find(a);
      if (it == next.end()) return false;
      a = it->second;
    }
    if (a != next.begin()->first) return false;
  }
  // Vertices inside the region (not on the rim) disappear: they must be plain face vertices.
  std::vector<char> used(mesh.positions.size(), 0);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    if (!visible[t])
      for (int q = 0; q < 3; ++q) used[mesh.triangles[t][q]] = 1;
  for (int t : region)
    for (int q = 0; q < 3; ++q) {
      const int w = mesh.triangles[t][q];
      if (!used[w] && (mesh.vertex_edge[w] >= 0 || mesh.vertex_vertex[w] >= 0)) return false;
    }

  const Polynomial& g = solid.surfaces[solid.faces[f].surface];
  SolidMesh out;
  out.chordal_error = mesh.chordal_error;
  out.edge_polylines = mesh.edge_polylines;
  std::vector<int> index(mesh.positions.size(), -1);
  for (size_t w = 0; w < mesh.positions.size(); ++w) {
    if (!used[w] && !next.count(static_cast<int>(w))) continue;
    index[w] = static_cast<int>(out.positions.size());
    out.positions.push_back(mesh.positions[w]);
    out.normals.push_back(mesh.normals[w]);
    out.vertex_edge.push_back(mesh.vertex_edge[w]);
    out.vertex_vertex.push_back(mesh.vertex_vertex[w]);
  }
  const int tip = static_cast<int>(out.positions.size());
  out.positions.push_back(p);
  out.normals.push_back(unit_normal(g, p));
  out.vertex_edge.push_back(-1);
  out.vertex_vertex.push_back(-1);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    if (visible[t]) continue;
    const Eigen::Vector3i& T = mesh.triangles[t];
    out.triangles.emplace_back(index[T[0]], index[T[1]], index[T[2]]);
    out.triangle_face.push_back(mesh.triangle_face[t]);
    for (int q = 0; q < 3; ++q) out.corner_normals.push_back(mesh.corner_normals[3 * t + q]);
  }
  // The fan, in rim order from the rim's first vertex (deterministic).
  int a = next.begin()->first;
  for (size_t k = 0; k < next.size(); ++k) {
    const int b = next.at(a);
    out.triangles.emplace_back(index[a], index[b], tip);
    out.triangle_face.push_back(f);
    for (const Eigen::Vector3d& x : {mesh.positions[a], mesh.positions[b], p})
      out.corner_normals.push_back(unit_normal(g, x));
    a = b;
  }
  mesh = std::move(out);
  return true;
}

}  // namespace

int cover_extremes(const Solid& solid, SolidMesh& mesh, const Tolerances& tol) {
  if (mesh.positions.empty()) return 0;
  std::vector<Eigen::Vector3d> dirs;
  for (int k = 0; k < 3; ++k) dirs.push_back(Eigen::Vector3d::Unit(k));
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& x : mesh.positions) centre += x;
  centre /= static_cast<double>(mesh.positions.size());
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& x : mesh.positions) C += (x - centre) * (x - centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
  for (int k = 0; k < 3; ++k) dirs.push_back(eig.eigenvectors().col(k).normalized());
  int added = 0;
  for (const Eigen::Vector3d& axis : dirs)
    for (double sign : {1.0, -1.0}) {
      const Eigen::Vector3d u = sign * axis;
      int v = 0;
      for (int w = 1; w < static_cast<int>(mesh.positions.size()); ++w)
        if (u.dot(mesh.positions[w]) > u.dot(mesh.positions[v])) v = w;
      if (mesh.vertex_edge[v] >= 0 || mesh.vertex_vertex[v] >= 0) continue;
      int f = -1;
      for (int t = 0; t < static_cast<int>(mesh.triangles.size()) && f < 0; ++t)
        for (int q = 0; q < 3; ++q)
          if (mesh.triangles[t][q] == v) f = mesh.triangle_face[t];
      if (f < 0) continue;
      const int surface = solid.faces[f].surface;
      const std::optional<Eigen::Vector3d> extreme =
          point_with_normal(solid.surfaces[surface], u, mesh.positions[v], tol);
      if (!extreme) continue;
      const Eigen::Vector3d p = *extreme;
      if ((p - mesh.positions[v]).norm() > kSearchChordal * mesh.chordal_error) continue;
      if (u.dot(p - mesh.positions[v]) <= kCoverFraction * mesh.chordal_error) continue;
      if (solid.face_at(surface, p, tol.on_boundary) != f) continue;
      if (insert_tip(solid, mesh, v, f, p)) ++added;
    }
  return added;
}

}  // namespace pcsg
