#include "engine/geometry/surface_patch.h"

#include <bit>
#include <numeric>
#include <unordered_map>

#include "engine/geometry/marching_tetrahedra.h"
#include "engine/geometry/surface.h"

namespace pcsg {
namespace {

// Grid cells kept around the box so the patch never reaches the grid's boundary.
constexpr int kMarginCells = 2;

struct Clipper {
  const std::vector<Polynomial>& gs;
  int i;
  const Tolerances& tol;
  SurfacePatch& out;
  std::vector<double> values;  // values[v * n + j] = g_j at vertex v (0 on its own curves)
  std::unordered_map<std::uint64_t, int> cuts;

  int n() const { return static_cast<int>(gs.size()); }

  int add_vertex(const Eigen::Vector3d& p, std::uint64_t on) {
    out.positions.push_back(p);
    out.on.push_back(on);
    for (int j = 0; j < n(); ++j)
      values.push_back(j == i || (on >> j & 1) ? 0.0 : gs[j].value(p));
    return static_cast<int>(out.positions.size()) - 1;
  }
  double value(int v, int j) const { return values[static_cast<std::size_t>(v) * n() + j]; }

  // The point where polygon edge (a, b) crosses g_j = 0, shared by both triangles of the edge.
  int cut(int a, int b, int j) {
    if (a > b) std::swap(a, b);
    const std::uint64_t key = (static_cast<std::uint64_t>(a) << 38) |
                              (static_cast<std::uint64_t>(b) << 8) | static_cast<std::uint64_t>(j);
    if (auto it = cuts.find(key); it != cuts.end()) return it->second;
    const double va = value(a, j), vb = value(b, j);
    const Eigen::Vector3d& pa = out.positions[a];
    const Eigen::Vector3d& pb = out.positions[b];
    const Eigen::Vector3d start = pa + va / (va - vb) * (pb - pa);
    // the cut lies on every surface both ends lie on, and on g_j
    const std::uint64_t on = (out.on[a] & out.on[b]) | (std::uint64_t{1} << j);
    Eigen::Vector3d p = start;
    if (std::popcount(on) == 1) {
      const Projection pr = project_onto_curve(gs[i], gs[j], start, tol);
      p = pr.point;
    } else {
      // a corner of the patch: the vertex where surface i meets two others
      int k[2], m = 0;
      for (int s = 0; s < n() && m < 2; ++s)
        if ((on >> s & 1) && s != j) k[m++] = s;
      const Projection pr = solve_three_surfaces(gs[i], gs[j], gs[k[0]], start, tol);
      if (pr.converged) p = pr.point;
    }
    const int id = add_vertex(p, on);
    cuts.emplace(key, id);
    return id;
  }

  // Sutherland-Hodgman against g_j <= 0; a vertex on g_j (value exactly 0) is kept and never cut.
  void clip(std::vector<int>& poly, int j) {
    std::vector<int> next;
    const std::size_t m = poly.size();
    for (std::size_t q = 0; q < m; ++q) {
      const int a = poly[q], b = poly[(q + 1) % m];
      const double va = value(a, j), vb = value(b, j);
      if (va <= 0) next.push_back(a);
      if ((va < 0 && vb > 0) || (va > 0 && vb < 0)) next.push_back(cut(a, b, j));
    }
    poly.swap(next);
  }

  void run(const IsoMesh& iso) {
    // vertices of the surface's own mesh, projected exactly onto it
    out.positions.reserve(iso.positions.size() * 5 / 4);
    for (const auto& p : iso.positions) {
      const Projection pr = project_onto_surface(gs[i], p, tol);
      add_vertex(pr.point, 0);
    }
    std::vector<int> poly;
    for (const auto& t : iso.triangles) {
      poly.assign({t[0], t[1], t[2]});
      for (int j = 0; j < n() && poly.size() >= 3; ++j) {
        if (j == i) continue;
        bool any_out = false;
        for (int v : poly) any_out = any_out || value(v, j) > 0;
        if (any_out) clip(poly, j);
      }
      // the clipped polygon is convex in the interpolants: a fan triangulates it
      for (std::size_t q = 1; q + 1 < poly.size(); ++q)
        out.triangles.emplace_back(poly[0], poly[q], poly[q + 1]);
    }
  }
};

}  // namespace

SurfacePatch surface_patch(const std::vector<Polynomial>& surfaces, int i,
                           const Eigen::AlignedBox3d& box, double h, const Tolerances& tol) {
  const Grid grid = Grid::covering(box, h, kMarginCells);
  const IsoMesh iso = marching_tetrahedra(grid, sample_on_grid(surfaces[i], grid));
  SurfacePatch patch;
  patch.surface = i;
  Clipper c{surfaces, i, tol, patch, {}, {}};
  c.run(iso);
  // drop the vertices no kept triangle uses, renumbering the rest in order
  std::vector<int> remap(patch.positions.size(), -1);
  for (const auto& t : patch.triangles)
    for (int q = 0; q < 3; ++q) remap[t[q]] = 0;
  int next = 0;
  for (std::size_t v = 0; v < remap.size(); ++v)
    if (remap[v] == 0) {
      remap[v] = next;
      patch.positions[next] = patch.positions[v];
      patch.on[next] = patch.on[v];
      ++next;
    }
  patch.positions.resize(next);
  patch.on.resize(next);
  for (auto& t : patch.triangles)
    for (int q = 0; q < 3; ++q) t[q] = remap[t[q]];
  return patch;
}

std::vector<int> triangle_components(const SurfacePatch& patch, int* count) {
  const int nt = static_cast<int>(patch.triangles.size());
  std::vector<int> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  std::unordered_map<std::uint64_t, int> first_user;
  for (int t = 0; t < nt; ++t)
    for (int q = 0; q < 3; ++q) {
      std::uint64_t a = patch.triangles[t][q], b = patch.triangles[t][(q + 1) % 3];
      if (a > b) std::swap(a, b);
      auto [it, fresh] = first_user.try_emplace((a << 32) | b, t);
      if (!fresh) parent[find(t)] = find(it->second);
    }
  std::vector<int> label(nt, -1), root_label(nt, -1);
  int n = 0;
  for (int t = 0; t < nt; ++t) {
    const int r = find(t);
    if (root_label[r] < 0) root_label[r] = n++;
    label[t] = root_label[r];
  }
  *count = n;
  return label;
}

}  // namespace pcsg
