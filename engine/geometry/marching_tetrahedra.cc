#include "engine/geometry/marching_tetrahedra.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace pcsg {
namespace {

// Fraction of a cell by which grids are shifted: 1/pi is irrational, so no rational symmetry
// plane of a scene falls on grid vertices.
constexpr double kGridShift = 0.3183098861837907;

// The six tetrahedra of a cube around its main diagonal 0-7; corner b is at offset
// (b & 1, (b >> 1) & 1, (b >> 2) & 1). Each walks 0 -> one axis -> two axes -> 7.
constexpr int kTets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                             {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

}  // namespace

Grid Grid::covering(const Eigen::AlignedBox3d& box, double h, int margin_cells) {
  Grid g;
  g.h = h;
  g.origin = box.min() - Eigen::Vector3d::Constant((margin_cells + kGridShift) * h);
  for (int a = 0; a < 3; ++a)
    g.cells[a] = static_cast<int>(std::ceil(box.sizes()[a] / h)) + 2 * margin_cells + 1;
  return g;
}

std::vector<double> sample_on_grid(const Polynomial& g, const Grid& grid) {
  std::vector<double> out(grid.vertex_count());
  const int d = Polynomial::kMaxDegree;
  for (int j = 0; j <= grid.cells.y(); ++j)
    for (int i = 0; i <= grid.cells.x(); ++i) {
      // in the polynomial's own expansion coordinates (Polynomial::origin)
      const Eigen::Vector3d p = grid.point(i, j, 0) - g.origin();
      // collapse x and y: g(x, y, z) = sum_k c_k z^k on this column
      std::array<double, Polynomial::kMaxDegree + 1> c{};
      double xp[d + 1], yp[d + 1];
      xp[0] = yp[0] = 1;
      for (int e = 1; e <= d; ++e) {
        xp[e] = xp[e - 1] * p.x();
        yp[e] = yp[e - 1] * p.y();
      }
      for (int n = 0; n < Polynomial::kNumCoeffs; ++n) {
        const double coef = g.coeffs()[n];
        if (coef == 0.0) continue;
        const auto e = Polynomial::exponents(n);
        c[e[2]] += coef * xp[e[0]] * yp[e[1]];
      }
      for (int k = 0; k <= grid.cells.z(); ++k) {
        const double z = grid.origin.z() + grid.h * k - g.origin().z();
        double v = 0;
        for (int e = d; e >= 0; --e) v = v * z + c[e];
        out[grid.index(i, j, k)] = v;
      }
    }
  return out;
}

IsoMesh marching_tetrahedra(const Grid& grid, const std::vector<double>& values) {
  IsoMesh mesh;
  std::unordered_map<std::uint64_t, int> cut_index;
  const std::uint64_t nv = static_cast<std::uint64_t>(grid.vertex_count());

  // the cut point on grid edge (ga, gb), created once and shared by every tetrahedron using it
  auto cut_point = [&](int ga, int gb, const Eigen::Vector3d& pa, const Eigen::Vector3d& pb) {
    // called with ga < gb: the point does not depend on the order tetrahedra visit the edge
    const std::uint64_t key = static_cast<std::uint64_t>(ga) * nv + static_cast<std::uint64_t>(gb);
    auto [it, fresh] = cut_index.try_emplace(key, static_cast<int>(mesh.positions.size()));
    if (fresh) {
      const double va = values[ga], vb = values[gb];
      const double t = va / (va - vb);
      mesh.positions.push_back(pa + t * (pb - pa));
    }
    return it->second;
  };
  auto edge_vertex = [&](int ga, int gb, const Eigen::Vector3d& pa, const Eigen::Vector3d& pb) {
    return ga < gb ? cut_point(ga, gb, pa, pb) : cut_point(gb, ga, pb, pa);
  };

  for (int k = 0; k < grid.cells.z(); ++k)
    for (int j = 0; j < grid.cells.y(); ++j)
      for (int i = 0; i < grid.cells.x(); ++i) {
        int gid[8];
        bool in[8];
        int n_in = 0;
        for (int b = 0; b < 8; ++b) {
          gid[b] = grid.index(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
          in[b] = values[gid[b]] <= 0;
          n_in += in[b];
        }
        if (n_in == 0 || n_in == 8) continue;
        Eigen::Vector3d P[8];
        for (int b = 0; b < 8; ++b)
          P[b] = grid.point(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        for (const auto& tet : kTets) {
          int neg[4], pos[4], nn = 0, np = 0;
          for (int c : tet) (in[c] ? neg[nn++] : pos[np++]) = c;
          if (nn == 0 || np == 0) continue;
          // outward direction: from the inside corners toward the outside ones
          Eigen::Vector3d cn = Eigen::Vector3d::Zero(), cp = Eigen::Vector3d::Zero();
          for (int q = 0; q < nn; ++q) cn += P[neg[q]] / nn;
          for (int q = 0; q < np; ++q) cp += P[pos[q]] / np;
          const Eigen::Vector3d out_dir = cp - cn;
          // the polygon's corners as grid edges, in cyclic order
          std::array<std::pair<int, int>, 4> poly;
          int m = 0;
          if (nn == 1 || np == 1) {
            const int lone = nn == 1 ? neg[0] : pos[0];
            const int* others = nn == 1 ? pos : neg;
            for (int q = 0; q < 3; ++q) poly[m++] = {lone, others[q]};
          } else {
            poly = {{{neg[0], pos[0]}, {neg[0], pos[1]}, {neg[1], pos[1]}, {neg[1], pos[0]}}};
            m = 4;
          }
          // orientation from the edge midpoints (never degenerate, unlike the cut points)
          Eigen::Vector3d mid[4];
          for (int q = 0; q < m; ++q) mid[q] = 0.5 * (P[poly[q].first] + P[poly[q].second]);
          const Eigen::Vector3d nrm = m == 3 ? (mid[1] - mid[0]).cross(mid[2] - mid[0])
                                             : (mid[2] - mid[0]).cross(mid[3] - mid[1]);
          if (nrm.dot(out_dir) < 0) std::reverse(poly.begin(), poly.begin() + m);
          int v[4];
          for (int q = 0; q < m; ++q)
            v[q] = edge_vertex(gid[poly[q].first], gid[poly[q].second], P[poly[q].first],
                               P[poly[q].second]);
          if (m == 3) {
            mesh.triangles.emplace_back(v[0], v[1], v[2]);
          } else {
            // split the quad along its shorter diagonal: better-shaped triangles
            const auto& X = mesh.positions;
            if ((X[v[0]] - X[v[2]]).squaredNorm() <= (X[v[1]] - X[v[3]]).squaredNorm()) {
              mesh.triangles.emplace_back(v[0], v[1], v[2]);
              mesh.triangles.emplace_back(v[0], v[2], v[3]);
            } else {
              mesh.triangles.emplace_back(v[0], v[1], v[3]);
              mesh.triangles.emplace_back(v[1], v[2], v[3]);
            }
          }
        }
      }
  return mesh;
}

}  // namespace pcsg
