#pragma once
// Test kit: solids built by hand with closed-form edges and vertices, and two small meshers
// (ray casting for convex solids, revolution for solids of revolution), so that the contact
// tests do not depend on the geometry kernel. Meshes only feed the candidate search; contacts
// are decided on the exact polynomials, like with the kernel's meshes.
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "engine/geometry/scene_geometry.h"

namespace pcsg::testkit {

inline Polynomial var(int a) { return Polynomial::variable(a); }
inline Polynomial cst(double c) { return Polynomial::constant(c); }

// |p - c|^2 - r^2 <= 0: a ball.
inline Polynomial ball(const Eigen::Vector3d& c, double r) {
  Polynomial g = cst(-r * r);
  for (int a = 0; a < 3; ++a) g = g + (var(a) - cst(c[a])).pow(2);
  return g;
}

// (x/a)^2 + (y/b)^2 + (z/c)^2 - 1 <= 0, centred at o.
inline Polynomial ellipsoid(double a, double b, double c,
                            const Eigen::Vector3d& o = Eigen::Vector3d::Zero()) {
  return ((var(0) - cst(o.x())) * (1 / a)).pow(2) + ((var(1) - cst(o.y())) * (1 / b)).pow(2) +
         ((var(2) - cst(o.z())) * (1 / c)).pow(2) - cst(1);
}

// A solid with one face per inequality (each inequality's patch is connected).
inline Solid make_solid(const std::string& name,
                        const std::vector<std::pair<std::string, Polynomial>>& faces) {
  Solid s;
  s.name = name;
  for (const auto& [fname, g] : faces) {
    s.surfaces.push_back(g);
    s.surface_names.push_back(fname);
    Face f;
    f.name = fname;
    f.surface = static_cast<int>(s.surfaces.size()) - 1;
    s.faces.push_back(f);
  }
  return s;
}

// Adds an edge through the given exact points (closed: the curve returns to the first point).
inline void add_edge(Solid& s, const std::string& name, int s1, int s2,
                     const std::vector<Eigen::Vector3d>& points, bool closed,
                     std::vector<int> vertices = {}) {
  Edge e;
  e.name = name;
  e.surface1 = s1;
  e.surface2 = s2;
  e.face1 = s1;  // make_solid: face i is on surface i
  e.face2 = s2;
  e.closed = closed;
  e.vertices = std::move(vertices);
  double arc = 0;
  for (size_t k = 0; k < points.size(); ++k) {
    if (k) arc += (points[k] - points[k - 1]).norm();
    const Eigen::Vector3d t =
        s.surfaces[s1].gradient(points[k]).cross(s.surfaces[s2].gradient(points[k])).normalized();
    e.samples.push_back({arc, points[k], t});
    e.bbox.extend(points[k]);
  }
  e.length = arc;
  const int id = static_cast<int>(s.edges.size());
  s.faces[s1].edges.push_back(id);
  s.faces[s2].edges.push_back(id);
  s.edges.push_back(e);
}

// The circle of centre c, unit axis n and radius r, as n_samples exact points.
inline std::vector<Eigen::Vector3d> circle(const Eigen::Vector3d& c, const Eigen::Vector3d& n,
                                           double r, int n_samples = 720) {
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < n_samples; ++k) {
    const double a = 2 * M_PI * k / n_samples;
    pts.push_back(c + r * (std::cos(a) * u + std::sin(a) * v));
  }
  return pts;
}

inline void add_vertex(Solid& s, const std::string& name, const Eigen::Vector3d& p,
                       const std::vector<int>& surfaces, const std::vector<int>& edges) {
  Vertex v;
  v.name = name;
  v.point = p;
  v.surfaces = surfaces;
  v.faces = surfaces;
  v.edges = edges;
  const int id = static_cast<int>(s.vertices.size());
  for (int f : surfaces) s.faces[f].vertices.push_back(id);
  s.vertices.push_back(v);
}

// |max_i g_i / |grad g_i|| at p: the first-order distance from p to the solid's boundary.
inline double boundary_distance(const Solid& s, const Eigen::Vector3d& p) {
  double m = -INFINITY;
  for (const Polynomial& g : s.surfaces) m = std::max(m, g.value(p) / g.gradient(p).norm());
  return std::abs(m);
}

// The surface whose boundary p is on (the largest g_i / |grad g_i|).
inline int active_surface(const Solid& s, const Eigen::Vector3d& p) {
  int best = 0;
  double m = -INFINITY;
  for (int i = 0; i < static_cast<int>(s.surfaces.size()); ++i) {
    const double d = s.surfaces[i].value(p) / s.surfaces[i].gradient(p).norm();
    if (d > m) m = d, best = i;
  }
  return best;
}

// Fills normals, the chordal error (1.5 x the largest centroid deviation) and the boxes.
inline void finish_mesh(Solid& s, SolidMesh& m) {
  m.normals.clear();
  s.bbox.setEmpty();
  for (const Eigen::Vector3d& p : m.positions) {
    m.normals.push_back(s.surfaces[active_surface(s, p)].gradient(p).normalized());
    s.bbox.extend(p);
  }
  double dev = 0;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    const Eigen::Vector3d c = (m.positions[tri[0]] + m.positions[tri[1]] + m.positions[tri[2]]) / 3;
    dev = std::max(dev, boundary_distance(s, c));
    for (int k = 0; k < 3; ++k) s.faces[m.triangle_face[t]].bbox.extend(m.positions[tri[k]]);
  }
  m.chordal_error = 1.5 * dev;
  m.edge_polylines.clear();
  for (const Edge& e : s.edges) {
    std::vector<Eigen::Vector3d> line;
    for (const CurveSample& c : e.samples) line.push_back(c.point);
    if (e.closed && !line.empty()) line.push_back(line.front());
    m.edge_polylines.push_back(line);
  }
  for (Face& f : s.faces) f.interior_point = f.bbox.center();
}

// Mesh of a convex solid by casting rays from an interior point c along the vertices of a
// subdivided icosahedron; each vertex is put on the boundary to round-off by bisection.
inline SolidMesh mesh_convex(Solid& s, const Eigen::Vector3d& c, int subdivisions = 4) {
  const double t0 = (1 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::Vector3d> dirs = {{-1, t0, 0}, {1, t0, 0}, {-1, -t0, 0}, {1, -t0, 0},
                                       {0, -1, t0}, {0, 1, t0}, {0, -1, -t0}, {0, 1, -t0},
                                       {t0, 0, -1}, {t0, 0, 1}, {-t0, 0, -1}, {-t0, 0, 1}};
  std::vector<Eigen::Vector3i> tris = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& d : dirs) d.normalize();
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      dirs.push_back((dirs[a] + dirs[b]).normalized());
      return mid[key] = static_cast<int>(dirs.size()) - 1;
    };
    std::vector<Eigen::Vector3i> next;
    for (const auto& t : tris) {
      const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), d = midpoint(t[2], t[0]);
      next.push_back({t[0], a, d});
      next.push_back({t[1], b, a});
      next.push_back({t[2], d, b});
      next.push_back({a, b, d});
    }
    tris = next;
  }
  SolidMesh m;
  double far = 1;
  for (const Polynomial& g : s.surfaces) far = std::max(far, g.max_abs_coeff());
  for (const Eigen::Vector3d& d : dirs) {
    // March out to the first exit from the solid, then bisect.
    auto inside = [&](double t) {
      for (const Polynomial& g : s.surfaces)
        if (g.value(c + t * d) > 0) return false;
      return true;
    };
    double lo = 0, hi = 1e-3;
    while (inside(hi)) lo = hi, hi *= 1.25;
    for (int k = 0; k < 200 && hi - lo > 0; ++k) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (inside(mid) ? lo : hi) = mid;
    }
    m.positions.push_back(c + lo * d);
  }
  m.triangles = tris;
  for (const auto& t : tris) {
    const Eigen::Vector3d ctr = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3;
    m.triangle_face.push_back(active_surface(s, ctr));  // face i is on surface i
  }
  finish_mesh(s, m);
  return m;
}

// Mesh of a solid of revolution about z: `profile` lists (r, z) points from the top of the axis
// to its bottom (both with r = 0), exactly on the boundary; each ring has n_phi vertices.
inline SolidMesh mesh_revolution(Solid& s, const std::vector<Eigen::Vector2d>& profile,
                                 int n_phi = 96) {
  SolidMesh m;
  std::vector<std::vector<int>> ring(profile.size());
  for (size_t k = 0; k < profile.size(); ++k) {
    const double r = profile[k].x(), z = profile[k].y();
    const int count = r == 0 ? 1 : n_phi;
    for (int j = 0; j < count; ++j) {
      const double a = 2 * M_PI * j / n_phi;
      ring[k].push_back(static_cast<int>(m.positions.size()));
      m.positions.push_back({r * std::cos(a), r * std::sin(a), z});
    }
  }
  auto at = [&](size_t k, int j) { return ring[k][ring[k].size() == 1 ? 0 : j % n_phi]; };
  for (size_t k = 0; k + 1 < profile.size(); ++k)
    for (int j = 0; j < n_phi; ++j) {
      const int a = at(k, j), b = at(k, j + 1), c = at(k + 1, j), d = at(k + 1, j + 1);
      if (a != b) m.triangles.push_back({a, c, b});
      if (c != d) m.triangles.push_back({b, c, d});
    }
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d ctr = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3;
    m.triangle_face.push_back(active_surface(s, ctr));
  }
  finish_mesh(s, m);
  return m;
}

// Two solids with their meshes, as a scene. tol from the larger bounding-box diagonal.
inline SceneGeometry make_scene(Solid A, SolidMesh mesh_A, Solid B, SolidMesh mesh_B) {
  SceneGeometry g;
  g.spec.name = "hand-built";
  g.A = std::move(A);
  g.B = std::move(B);
  g.A.name = "A";
  g.B.name = "B";
  g.mesh_A = std::move(mesh_A);
  g.mesh_B = std::move(mesh_B);
  const double L = std::max(g.A.bbox.diagonal().norm(), g.B.bbox.diagonal().norm());
  g.tol = Tolerances::for_length_scale(L);
  return g;
}

}  // namespace pcsg::testkit
