#pragma once
// The boundary representation of one strictly curved solid, derived from its inequalities:
// faces (connected patches of one surface on the solid's boundary), edges (connected curves
// where two faces meet) and vertices (points where three or more faces meet), with adjacency.
// Everything is exact: the surfaces are the polynomials; the curves are traced with Newton
// projection onto both surfaces. Meshes are derived separately (geometry/mesher.h).
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "engine/poly/polynomial.h"

namespace pcsg {

enum class ElementKind { Face, Edge, Vertex };

// A sample of an edge curve: an exact point on both surfaces with its arc length.
struct CurveSample {
  double s = 0;              // arc length from the first sample
  Eigen::Vector3d point;     // on both surfaces to the solve tolerance
  Eigen::Vector3d tangent;   // unit, along increasing s
};

struct Face {
  std::string name;
  int surface = -1;                  // index into Solid::surfaces (the inequality)
  std::vector<int> edges;            // bounding edges
  std::vector<int> vertices;         // vertices on its boundary
  Eigen::Vector3d interior_point;    // a point of the patch, away from its boundary
  Eigen::AlignedBox3d bbox;
  double area = 0;
  // Exact points of the patch (a coarse mesh's vertices, projected onto the surface): they
  // tell the patches of one surface apart (face_at) and feed the straight-segment check.
  std::vector<Eigen::Vector3d> samples;
  // Largest |principal curvature| found on the patch (1/length): sets the mesh spacing.
  double max_curvature = 0;
};

struct Edge {
  std::string name;
  int surface1 = -1, surface2 = -1;  // the two surfaces it lies on
  int face1 = -1, face2 = -1;        // the two faces it bounds
  std::vector<int> vertices;         // end vertices; empty for a closed curve
  bool closed = false;
  std::vector<CurveSample> samples;  // exact points, spaced by at most the sampling step
  double length = 0;
  Eigen::AlignedBox3d bbox;
};

struct Vertex {
  std::string name;
  Eigen::Vector3d point;
  std::vector<int> surfaces;  // the surfaces through it (3 or more)
  std::vector<int> faces;
  std::vector<int> edges;
};

// An element of one solid, by kind and index.
struct ElementId {
  ElementKind kind = ElementKind::Face;
  int index = -1;
  bool operator==(const ElementId& o) const { return kind == o.kind && index == o.index; }
  bool operator<(const ElementId& o) const {
    return kind != o.kind ? kind < o.kind : index < o.index;
  }
};

class Solid {
 public:
  std::string name;                       // "A" or "B"
  std::vector<Polynomial> surfaces;       // solid = { p : surfaces[i](p) <= 0 for all i }
  std::vector<std::string> surface_names; // the face names of the scene file
  std::vector<Face> faces;
  std::vector<Edge> edges;
  std::vector<Vertex> vertices;
  Eigen::AlignedBox3d bbox;

  // max_i g_i(p) / |grad g_i(p)|: a signed distance estimate, <= 0 inside (first order).
  double inside_measure(const Eigen::Vector3d& p) const;
  bool contains(const Eigen::Vector3d& p, double tol) const { return inside_measure(p) <= tol; }

  // The face of surface `surface` whose patch holds the point p (on that surface); -1 when p
  // is outside every patch of it (some other inequality violated by more than tol).
  int face_at(int surface, const Eigen::Vector3d& p, double tol) const;
  // The edge on surfaces (s1, s2) that holds the point p; -1 when none.
  int edge_at(int s1, int s2, const Eigen::Vector3d& p, double tol) const;

  const std::string& element_name(ElementId id) const;
  // Elements adjacent to `id` in the paper's sense (Section II-D): a face's edges and vertices,
  // an edge's faces and vertices, a vertex's edges and faces.
  std::vector<ElementId> adjacent(ElementId id) const;
  // Finds an element by name; index -1 when there is none.
  ElementId find(const std::string& element_name) const;
};

}  // namespace pcsg
