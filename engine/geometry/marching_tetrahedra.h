#pragma once
// A triangle mesh of the zero set of one polynomial over a box: the polynomial is sampled on a
// regular grid, each cube is split into six tetrahedra sharing its main diagonal (the same
// split in every cube, so neighbours agree on their shared faces), and each tetrahedron's
// linear interpolant is cut at zero. The mesh is closed wherever the surface stays inside the
// grid, consistently oriented with normals toward g > 0 (outward for a solid g <= 0), and its
// vertices are keyed by grid edge so that neighbouring tetrahedra share them.
#include <Eigen/Geometry>
#include <vector>

#include "engine/poly/polynomial.h"

namespace pcsg {

// A regular grid of cubic cells: vertex (i, j, k) is at origin + h (i, j, k), 0 <= i <= cells.x().
struct Grid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double h = 1;
  Eigen::Vector3i cells = Eigen::Vector3i::Zero();

  // Cells of size h covering `box` plus `margin_cells` on every side. The origin is shifted by an
  // irrational fraction of a cell so that symmetric surfaces do not pass exactly through grid
  // vertices (which would give zero-area triangles).
  static Grid covering(const Eigen::AlignedBox3d& box, double h, int margin_cells);
  int vertex_count() const { return (cells.x() + 1) * (cells.y() + 1) * (cells.z() + 1); }
  int index(int i, int j, int k) const {
    return i + (cells.x() + 1) * (j + (cells.y() + 1) * k);
  }
  Eigen::Vector3d point(int i, int j, int k) const {
    return origin + h * Eigen::Vector3d(i, j, k);
  }
};

// g at every grid vertex (Grid::index order), by Horner along z after collapsing x and y per
// column: ~6 multiplications per vertex instead of a 35-term evaluation.
std::vector<double> sample_on_grid(const Polynomial& g, const Grid& grid);

struct IsoMesh {
  std::vector<Eigen::Vector3d> positions;   // on the linear interpolants (not yet projected)
  std::vector<Eigen::Vector3i> triangles;   // counter-clockwise seen from g > 0
};

// The zero set of the sampled values (<= 0 counts as inside). Only cubes whose corners change
// sign are visited.
IsoMesh marching_tetrahedra(const Grid& grid, const std::vector<double>& values);

}  // namespace pcsg
