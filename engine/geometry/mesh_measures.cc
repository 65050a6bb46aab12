#include "engine/geometry/mesh_measures.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <unordered_map>


namespace pcsg {
namespace {

std::uint64_t key(std::uint64_t a, std::uint64_t b) { return a < b ? a << 32 | b : b << 32 | a; }

double tri_area(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

// The solid edge both mesh vertices lie on (an edge's vertex counts as on it), or -1.
int common_edge(const Solid& solid, const SolidMesh& mesh, int a, int b) {
  auto on = [&](int v, int e) {
    if (mesh.vertex_edge[v] == e) return true;
    const int V = mesh.vertex_vertex[v];
    if (V < 0) return false;
    const auto& ev = solid.edges[e].vertices;
    return std::find(ev.begin(), ev.end(), V) != ev.end();
  };
  for (int e : {mesh.vertex_edge[a], mesh.vertex_edge[b]})
    if (e >= 0 && on(a, e) && on(b, e)) return e;
  return -1;
}

}  // namespace

MeshTopology mesh_topology(const SolidMesh& mesh) {
  std::unordered_map<std::uint64_t, std::pair<int, int>> uses;  // (forward, backward) counts
  for (const auto& t : mesh.triangles)
    for (int q = 0; q < 3; ++q) {
      const std::uint64_t a = t[q], b = t[(q + 1) % 3];
      auto& u = uses[key(a, b)];
      (a < b ? u.first : u.second)++;
    }
  MeshTopology topo;
  for (const auto& [k, u] : uses) {
    ++topo.edges;
    const int n = u.first + u.second;
    if (n == 1) ++topo.boundary_edges;
    else if (n > 2) ++topo.nonmanifold_edges;
    else if (u.first != 1) ++topo.misoriented_edges;
  }
  return topo;
}

double mesh_volume(const SolidMesh& mesh) {
  double v = 0;
  for (const auto& t : mesh.triangles)
    v += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]])) / 6;
  return v;
}

std::vector<double> face_areas(const Solid& solid, const SolidMesh& mesh) {
  std::vector<double> coarse(solid.faces.size(), 0.0), fine(solid.faces.size(), 0.0);
  // a side lies along an edge curve exactly when the triangles on its two sides belong to
  // different faces (a chord between two edge points across a face does not)
  std::unordered_map<std::uint64_t, int> side_face;  // first face seen; -1 once two differ
  side_face.reserve(2 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int q = 0; q < 3; ++q) {
      const auto& T = mesh.triangles[t];
      auto [it, fresh] = side_face.try_emplace(key(T[q], T[(q + 1) % 3]), mesh.triangle_face[t]);
      if (!fresh && it->second != mesh.triangle_face[t]) it->second = -1;
    }
  std::unordered_map<std::uint64_t, Eigen::Vector3d> mids;
  mids.reserve(2 * mesh.triangles.size());
  auto midpoint = [&](int a, int b, int f) -> const Eigen::Vector3d& {
    auto [it, fresh] = mids.try_emplace(key(a, b));
    if (!fresh) return it->second;
    // Two minimum-norm Newton steps: the midpoint is d ~ kappa e^2 / 8 off the surface and
    // each step squares the relative error (d -> kappa d^2), leaving ~1e-12 L: exact for areas.
    Eigen::Vector3d m = 0.5 * (mesh.positions[a] + mesh.positions[b]);
    const int e = side_face.at(key(a, b)) < 0 ? common_edge(solid, mesh, a, b) : -1;
    for (int step = 0; step < 2; ++step) {
      if (e >= 0) {
        Eigen::Matrix<double, 2, 3> J;
        Eigen::Vector2d r;
        Eigen::Vector3d grad;
        // rows divided by the gradients' norms: J J^T stays ~1 whatever the inequalities'
        // scales (surface.h, project_onto_curve)
        for (int k = 0; k < 2; ++k) {
          solid.surfaces[k ? solid.edges[e].surface2 : solid.edges[e].surface1].evaluate(
              m, &r[k], &grad, nullptr);
          const double n = grad.norm();
          r[k] /= n;
          J.row(k) = grad.transpose() / n;
        }
        m -= J.transpose() * (J * J.transpose()).ldlt().solve(r);
      } else {
        double v = 0;
        Eigen::Vector3d grad;
        solid.surfaces[solid.faces[f].surface].evaluate(m, &v, &grad, nullptr);
        m -= v / grad.squaredNorm() * grad;
      }
    }
    it->second = m;
    return it->second;
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& T = mesh.triangles[t];
    const int f = mesh.triangle_face[t];
    const Eigen::Vector3d &a = mesh.positions[T[0]], &b = mesh.positions[T[1]],
                          &c = mesh.positions[T[2]];
    coarse[f] += tri_area(a, b, c);
    const Eigen::Vector3d ab = midpoint(T[0], T[1], f), bc = midpoint(T[1], T[2], f),
                          ca = midpoint(T[2], T[0], f);
    fine[f] += tri_area(a, ab, ca) + tri_area(ab, b, bc) + tri_area(ca, bc, c) +
               tri_area(ab, bc, ca);
  }
  std::vector<double> area(solid.faces.size());
  for (std::size_t f = 0; f < area.size(); ++f) area[f] = (4 * fine[f] - coarse[f]) / 3;
  return area;
}

}  // namespace pcsg
