#pragma once
// Hand-built solids and meshes for the renderer's tests and benchmark, independent of the
// geometry kernel: an ellipsoid (one face, no edge) and a lens (two spherical caps meeting on
// one circular edge), with exact normals and the surfaces' polynomials.
#include <cmath>
#include <string>

#include "engine/geometry/scene_geometry.h"

namespace pcsg::render::testing {

inline constexpr double kPi = 3.14159265358979323846;

inline Polynomial coordinate(int axis) { return Polynomial::variable(axis); }

// Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1 as a UV mesh (poles on the z axis).
inline SolidMesh ellipsoid_mesh(double a, double b, double c, int rings = 48, int segments = 96) {
  SolidMesh m;
  auto add = [&](double theta, double phi) {
    const Eigen::Vector3d p(a * std::sin(theta) * std::cos(phi),
                            b * std::sin(theta) * std::sin(phi), c * std::cos(theta));
    m.positions.push_back(p);
    m.normals.push_back(
        Eigen::Vector3d(p.x() / (a * a), p.y() / (b * b), p.z() / (c * c)).normalized());
  };
  add(0, 0);  // north pole: vertex 0
  for (int i = 1; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) add(kPi * i / rings, 2 * kPi * j / segments);
  }
  add(kPi, 0);  // south pole: last vertex
  const int south = static_cast<int>(m.positions.size()) - 1;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) m.triangles.emplace_back(0, ring(1, j), ring(1, j + 1));
  for (int i = 1; i + 1 < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      m.triangles.emplace_back(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      m.triangles.emplace_back(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
  }
  for (int j = 0; j < segments; ++j) {
    m.triangles.emplace_back(ring(rings - 1, j), south, ring(rings - 1, j + 1));
  }
  m.triangle_face.assign(m.triangles.size(), 0);
  return m;
}

inline Solid ellipsoid_solid(const std::string& name, const std::string& face, double a, double b,
                             double c) {
  Solid s;
  s.name = name;
  const Polynomial x = coordinate(0), y = coordinate(1), z = coordinate(2);
  s.surfaces.push_back(x * x * (1 / (a * a)) + y * y * (1 / (b * b)) + z * z * (1 / (c * c)) -
                       Polynomial::constant(1));
  s.surface_names.push_back(face);
  Face f;
  f.name = face;
  f.surface = 0;
  f.interior_point = Eigen::Vector3d(a, 0, 0);
  s.faces.push_back(f);
  s.bbox = Eigen::AlignedBox3d(Eigen::Vector3d(-a, -b, -c), Eigen::Vector3d(a, b, c));
  return s;
}

// The lens |p - (0,0,-h)| <= R and |p - (0,0,h)| <= R (h < R): face `upper` (z >= 0, on the
// sphere centred below), face `lower` (z <= 0) and the circular edge where they meet at z = 0.
struct Lens {
  Solid solid;
  SolidMesh mesh;
};

inline Lens lens(const std::string& name, const std::string& upper, const std::string& lower,
                 const std::string& edge, double R, double h, int rings = 32, int segments = 128) {
  Lens out;
  SolidMesh& m = out.mesh;
  const double theta_max = std::acos(h / R);
  // the shared rim first (indices 0..segments-1), then each cap's rings and pole
  for (int j = 0; j < segments; ++j) {
    const double phi = 2 * kPi * j / segments;
    const Eigen::Vector3d p(R * std::sin(theta_max) * std::cos(phi),
                            R * std::sin(theta_max) * std::sin(phi), 0);
    m.positions.push_back(p);
    m.normals.push_back((p + Eigen::Vector3d(0, 0, h)).normalized());  // upper cap's normal
  }
  for (int cap = 0; cap < 2; ++cap) {
    const double sign = cap == 0 ? 1 : -1;  // 0: upper cap (centre at -h), 1: lower (centre +h)
    const Eigen::Vector3d centre(0, 0, -sign * h);
    const int first = static_cast<int>(m.positions.size());
    for (int i = 1; i < rings; ++i) {  // ring i at polar angle theta_max * (rings - i) / rings
      const double theta = theta_max * (rings - i) / rings;
      for (int j = 0; j < segments; ++j) {
        const double phi = 2 * kPi * j / segments;
        const Eigen::Vector3d n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                sign * std::cos(theta));
        m.positions.push_back(centre + R * n);
        m.normals.push_back(n);
      }
    }
    m.positions.push_back(centre + Eigen::Vector3d(0, 0, sign * R));
    m.normals.push_back(Eigen::Vector3d(0, 0, sign));
    const int pole = static_cast<int>(m.positions.size()) - 1;
    auto at = [&](int i, int j) {
      j %= segments;
      return i == 0 ? j : first + (i - 1) * segments + j;
    };
    for (int i = 0; i + 1 < rings; ++i) {
      for (int j = 0; j < segments; ++j) {
        // counter-clockwise seen from outside: the winding flips with the cap
        if (cap == 0) {
          m.triangles.emplace_back(at(i, j), at(i, j + 1), at(i + 1, j + 1));
          m.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i + 1, j));
        } else {
          m.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
          m.triangles.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        }
        m.triangle_face.push_back(cap);
        m.triangle_face.push_back(cap);
      }
    }
    for (int j = 0; j < segments; ++j) {
      if (cap == 0)
        m.triangles.emplace_back(at(rings - 1, j), at(rings - 1, j + 1), pole);
      else
        m.triangles.emplace_back(at(rings - 1, j), pole, at(rings - 1, j + 1));
      m.triangle_face.push_back(cap);
    }
  }
  std::vector<Eigen::Vector3d> rim(m.positions.begin(), m.positions.begin() + segments);
  rim.push_back(rim.front());  // closed curve: first point repeated
  m.edge_polylines.push_back(rim);

  Solid& s = out.solid;
  s.name = name;
  const Polynomial x = coordinate(0), y = coordinate(1), z = coordinate(2);
  const Polynomial zu = z + Polynomial::constant(h), zl = z - Polynomial::constant(h);
  s.surfaces = {x * x + y * y + zu * zu - Polynomial::constant(R * R),
                x * x + y * y + zl * zl - Polynomial::constant(R * R)};
  s.surface_names = {upper, lower};
  Face fu, fl;
  fu.name = upper;
  fu.surface = 0;
  fu.edges = {0};
  fu.interior_point = Eigen::Vector3d(0, 0, R - h);
  fl.name = lower;
  fl.surface = 1;
  fl.edges = {0};
  fl.interior_point = Eigen::Vector3d(0, 0, h - R);
  s.faces = {fu, fl};
  Edge e;
  e.name = edge;
  e.surface1 = 0;
  e.surface2 = 1;
  e.face1 = 0;
  e.face2 = 1;
  e.closed = true;
  e.length = 2 * kPi * R * std::sin(theta_max);
  s.edges = {e};
  const double r = R * std::sin(theta_max);
  s.bbox = Eigen::AlignedBox3d(Eigen::Vector3d(-r, -r, h - R), Eigen::Vector3d(r, r, R - h));
  return out;
}

// A: ellipsoid "fA" (semi-axes 1, 0.7, 1.5); B: lens "f1"/"f2" with edge "e1" (radius ~2.6).
inline SceneGeometry synthetic_scene() {
  SceneGeometry g;
  g.spec.name = "Synthetic: ellipsoid and lens";
  g.A = ellipsoid_solid("A", "fA", 1.0, 0.7, 1.5);
  g.mesh_A = ellipsoid_mesh(1.0, 0.7, 1.5);
  Lens b = lens("B", "f1", "f2", "e1", 3.0, 1.6);
  g.B = b.solid;
  g.mesh_B = b.mesh;
  const double diag = std::max(g.A.bbox.diagonal().norm(), g.B.bbox.diagonal().norm());
  g.tol = Tolerances::for_length_scale(diag);
  return g;
}

// A pose of the synthetic A lying on B's top: long axis along y, touching at (0, 0, top).
inline Pose synthetic_resting_pose() {
  Pose X;
  X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()));
  X.position = Eigen::Vector3d(0, 0, (3.0 - 1.6) + 0.7);
  return X;
}

}  // namespace pcsg::render::testing
