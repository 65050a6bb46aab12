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
  // Exact outward unit normal of each triangle's face at each of its corners (3 per triangle,
  // corner k of triangle t at 3t + k): at vertices on an edge `normals` holds the mean of the
  // meeting faces' normals, while each corner here keeps its own face's normal.
  std::vector<Eigen::Vector3d> corner_normals;
  // The Solid::edges index of the edge each vertex lies on (-1 inside a face or at a vertex),
  // and the Solid::vertices index of the vertex it is (-1 otherwise).
  std::vector<int> vertex_edge;
  std::vector<int> vertex_vertex;
};

}  // namespace pcsg
