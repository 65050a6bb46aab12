#pragma once
// Triangle meshes of a solid, for collision checks and rendering only: contacts are decided on
// the exact surfaces. Vertices lie on the exact surfaces; faces' meshes share their vertices
// along edges; every triangle is tagged with the face it belongs to.
#include <Eigen/Core>
#include <vector>

namespace pcsg {

class Solid;

struct SolidMesh {
  std::vector<Eigen::Vector3d> positions;  // in the solid's own frame
  std::vector<Eigen::Vector3d> normals;    // exact outward unit normals at the vertices
  std::vector<Eigen::Vector3i> triangles;  // counter-clockwise seen from outside
  std::vector<int> triangle_face;          // Solid::faces index of each triangle
  // One polyline per Solid::edges entry (closed curves repeat their first point at the end).
  std::vector<std::vector<Eigen::Vector3d>> edge_polylines;
  double chordal_error = 0;                // the bound it was built for
};

}  // namespace pcsg
