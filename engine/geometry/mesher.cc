#include "engine/geometry/mesher.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include "engine/geometry/edge_tracer.h"
#include "engine/geometry/mesh_extremes.h"
#include "engine/geometry/surface.h"
#include "engine/geometry/surface_patch.h"

namespace pcsg {
namespace {

// Grid cells across a face's box, at least (so that small faces are resolved and their
// boundaries meet their neighbours') and at most (bounding the cost of very curved faces).
constexpr int kMinCellsPerFace = 8;
constexpr int kMaxCellsPerFace = 160;
// Grid spacing per longest admissible triangle edge. Marching-tetrahedra triangle edges reach
// the cell's diagonal (sqrt 3 h) but are mostly near sqrt 2 h; 1.5 keeps the measured deviation
// of triangle centres from the surface below the chordal error on the paper's objects.
constexpr double kCellDiagonal = 1.5;
// Boundary points of the two faces of an edge closer than this fraction of the finer grid
// spacing become one point: splitting at both would only make slivers.
constexpr double kUnifyFraction = 0.3;

struct BoundaryEdge {
  int face, triangle, slot;  // the triangle's side slot -> slot + 1
  int edge;                  // Solid::edges index
};

struct Mesher {
  const Solid& solid;
  const Tolerances& tol;
  std::vector<SurfacePatch> patches;
  std::vector<std::vector<int>> kept;  // per face: its triangles (patch indices)
  std::vector<double> spacing;
  std::vector<int> offset;             // global id of face f's vertex v: offset[f] + v
  std::vector<Eigen::Vector3d> pos;
  std::vector<int> parent, on_edge, on_vertex;
  std::vector<BoundaryEdge> boundary;
  std::vector<std::vector<std::pair<double, int>>> edge_points;  // per edge: (s, rep), sorted
  std::vector<std::unordered_map<int, double>> edge_s;           // per edge: rep -> s

  int find(int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  int gid(int f, int v) const { return offset[f] + v; }

  void mesh_faces(double chordal_error) {
    const int nf = static_cast<int>(solid.faces.size());
    patches.resize(nf);
    kept.resize(nf);
    spacing.resize(nf);
    for (int f = 0; f < nf; ++f) {
      const Face& face = solid.faces[f];
      const double extent = face.bbox.sizes().maxCoeff();
      double h = face.max_curvature > 0
                     ? std::sqrt(8 * chordal_error / face.max_curvature) / kCellDiagonal
                     : extent;
      // (the finest cell bounded along the box's longest side, or across its thinnest when
      // the face is slender: a needle's face 1:1:100, scenes/stress/needle_in_dish.yaml, was
      // otherwise meshed with cells as wide as the needle)
      const double finest =
          std::min(extent / kMaxCellsPerFace, face.bbox.sizes().minCoeff() / kMinCellsPerFace);
      h = std::clamp(h, finest, extent / kMinCellsPerFace);
      spacing[f] = h;
      patches[f] = surface_patch(solid.surfaces, face.surface, face.bbox, h, tol);
      // a surface with several patches: keep the triangles of this one
      bool shared = false;
      for (int g = 0; g < nf; ++g) shared = shared || (g != f && solid.faces[g].surface == face.surface);
      const auto& P = patches[f];
      for (int t = 0; t < static_cast<int>(P.triangles.size()); ++t) {
        const auto& T = P.triangles[t];
        const Eigen::Vector3d c = (P.positions[T[0]] + P.positions[T[1]] + P.positions[T[2]]) / 3;
        if (!shared || solid.face_at(face.surface, c, std::numeric_limits<double>::infinity()) == f)
          kept[f].push_back(t);
      }
    }
    for (int f = 0; f < nf; ++f) {
      offset.push_back(static_cast<int>(pos.size()));
      pos.insert(pos.end(), patches[f].positions.begin(), patches[f].positions.end());
    }
    parent.resize(pos.size());
    for (std::size_t k = 0; k < pos.size(); ++k) parent[k] = static_cast<int>(k);
    on_edge.assign(pos.size(), -1);
    on_vertex.assign(pos.size(), -1);
  }

  // Patch corners (on two other surfaces) are the solid's vertices: one shared point each.
  void snap_vertices() {
    std::vector<int> first(solid.vertices.size(), -1);
    for (int f = 0; f < static_cast<int>(patches.size()); ++f)
      for (int v = 0; v < static_cast<int>(patches[f].on.size()); ++v) {
        if (std::popcount(patches[f].on[v]) < 2) continue;
        int best = -1;
        double best_d = std::numeric_limits<double>::infinity();
        for (int k = 0; k < static_cast<int>(solid.vertices.size()); ++k) {
          const double d = (solid.vertices[k].point - patches[f].positions[v]).norm();
          if (d < best_d) best_d = d, best = k;
        }
        if (best < 0) continue;
        const int g = gid(f, v);
        pos[g] = solid.vertices[best].point;
        on_vertex[g] = best;
        if (first[best] < 0) first[best] = g;
        else parent[find(g)] = find(first[best]);
      }
  }

  // The edge a boundary side lies on: an edge of this face on a surface both ends lie on.
  int edge_of_side(int f, int a, int b) const {
    const auto& P = patches[f];
    const std::uint64_t common = P.on[a] & P.on[b];
    const Eigen::Vector3d mid = 0.5 * (P.positions[a] + P.positions[b]);
    std::vector<int> candidates;
    for (int e : solid.faces[f].edges) {
      const Edge& E = solid.edges[e];
      const int other = E.surface1 == solid.faces[f].surface ? E.surface2 : E.surface1;
      if (common >> other & 1) candidates.push_back(e);
    }
    if (candidates.size() <= 1) return candidates.empty() ? -1 : candidates[0];
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (int e : candidates) {
      const Edge& E = solid.edges[e];
      const double d = distance_to_samples(E.samples, E.closed, mid);
      if (d < best_d) best_d = d, best = e;
    }
    return best;
  }

  void find_boundary() {
    for (int f = 0; f < static_cast<int>(patches.size()); ++f) {
      std::unordered_map<std::uint64_t, int> uses;
      uses.reserve(3 * kept[f].size());
      const auto& T = patches[f].triangles;
      auto key = [](std::uint64_t a, std::uint64_t b) { return a < b ? a << 32 | b : b << 32 | a; };
      for (int t : kept[f])
        for (int q = 0; q < 3; ++q) ++uses[key(T[t][q], T[t][(q + 1) % 3])];
      for (int t : kept[f])
        for (int q = 0; q < 3; ++q) {
          const int a = T[t][q], b = T[t][(q + 1) % 3];
          if (uses[key(a, b)] != 1) continue;
          const int e = edge_of_side(f, a, b);
          if (e >= 0) boundary.push_back({f, t, q, e});
        }
    }
  }

  double param(const Edge& E, const Eigen::Vector3d& p) const {
    const auto& S = E.samples;
    const std::size_t n = S.size(), segs = E.closed ? n : n - 1;
    double best = std::numeric_limits<double>::infinity(), s = 0;
    for (std::size_t k = 0; k < segs; ++k) {
      const Eigen::Vector3d d = S[(k + 1) % n].point - S[k].point;
      const double u =
          std::clamp((p - S[k].point).dot(d) / std::max(d.squaredNorm(), std::numeric_limits<double>::min()), 0.0, 1.0);
      const double dist = (S[k].point + u * d - p).squaredNorm();
      if (dist < best) {
        best = dist;
        const double s1 = k + 1 < n ? S[k + 1].s : E.length;
        s = S[k].s + u * (s1 - S[k].s);
      }
    }
    return s;
  }

  double wrap(const Edge& E, double d) const {
    return E.closed ? d - E.length * std::round(d / E.length) : d;
  }

  // One ordered set of exact points per edge, shared by both of its faces.
  void merge_edge_points() {
    const int ne = static_cast<int>(solid.edges.size());
    edge_points.assign(ne, {});
    edge_s.assign(ne, {});
    for (int e = 0; e < ne; ++e) {
      const Edge& E = solid.edges[e];
      std::vector<std::pair<double, int>> side[2];  // (s, gid) from face1 and face2
      for (const auto& be : boundary) {
        if (be.edge != e) continue;
        const auto& T = patches[be.face].triangles[be.triangle];
        const int k = be.face == E.face1 ? 0 : 1;
        for (int v : {T[be.slot], T[(be.slot + 1) % 3]}) {
          const int g = gid(be.face, v);
          double s;
          if (on_vertex[g] >= 0 && !E.vertices.empty() && on_vertex[g] == E.vertices.front())
            s = 0.0;
          else if (on_vertex[g] >= 0 && !E.vertices.empty() && on_vertex[g] == E.vertices.back())
            s = E.length;
          else
            s = param(E, pos[g]);
          side[k].emplace_back(s, g);
        }
      }
      for (auto& sd : side) {
        std::sort(sd.begin(), sd.end());
        sd.erase(std::unique(sd.begin(), sd.end()), sd.end());
      }
      const double delta = kUnifyFraction * std::min(spacing[E.face1], spacing[E.face2]);
      auto& M = edge_points[e];
      for (const auto& [s, g] : side[0]) M.emplace_back(s, find(g));
      for (const auto& [s, g] : side[1]) {
        const int r = find(g);
        int near = -1;
        double near_d = std::numeric_limits<double>::infinity();
        for (int m = 0; m < static_cast<int>(M.size()); ++m) {
          if (M[m].second == r) { near = -2; break; }
          const double d = std::abs(wrap(E, M[m].first - s));
          if (d < near_d) near_d = d, near = m;
        }
        if (near == -2) continue;
        if (near >= 0 && (pos[M[near].second] - pos[r]).norm() < delta &&
            on_vertex[r] < 0)
          parent[r] = M[near].second;  // unify into the first face's point
        else
          M.emplace_back(s, r);
      }
      std::sort(M.begin(), M.end());
      M.erase(std::unique(M.begin(), M.end()), M.end());
      for (const auto& [s, r] : M) {
        edge_s[e][r] = s;
        if (on_vertex[r] < 0) on_edge[r] = e;
      }
    }
  }

  // The edge points strictly between the ends of a boundary side, ordered from a to b.
  std::vector<int> between(int e, int ra, int rb) const {
    const Edge& E = solid.edges[e];
    const double sa = edge_s[e].at(ra), sb = edge_s[e].at(rb);
    const double span = wrap(E, sb - sa);
    std::vector<std::pair<double, int>> in;
    for (const auto& [s, r] : edge_points[e]) {
      if (r == ra || r == rb) continue;
      const double d = wrap(E, s - sa);
      if ((span > 0 && d > 0 && d < span) || (span < 0 && d < 0 && d > span))
        in.emplace_back(std::abs(d), r);
    }
    std::sort(in.begin(), in.end());
    std::vector<int> out;
    for (const auto& x : in) out.push_back(x.second);
    return out;
  }

  SolidMesh assemble(double chordal_error) {
    // the points each boundary side must pass through
    std::map<std::pair<int, int>, std::array<std::vector<int>, 3>> inserts;  // (face, tri)
    for (const auto& be : boundary) {
      const auto& T = patches[be.face].triangles[be.triangle];
      const int ra = find(gid(be.face, T[be.slot])), rb = find(gid(be.face, T[(be.slot + 1) % 3]));
      inserts[{be.face, be.triangle}][be.slot] = between(be.edge, ra, rb);
    }
    std::vector<Eigen::Vector3i> tris;
    std::vector<int> tri_face;
    auto emit = [&](int a, int b, int c, int f) {
      if (a == b || b == c || c == a) return;  // collapsed by a merge
      tris.emplace_back(a, b, c);
      tri_face.push_back(f);
    };
    for (int f = 0; f < static_cast<int>(patches.size()); ++f)
      for (int t : kept[f]) {
        const auto& T = patches[f].triangles[t];
        const int r[3] = {find(gid(f, T[0])), find(gid(f, T[1])), find(gid(f, T[2]))};
        const auto it = inserts.find({f, t});
        int sides = 0, side = -1;
        if (it != inserts.end())
          for (int q = 0; q < 3; ++q)
            if (!it->second[q].empty()) ++sides, side = q;
        if (sides == 0) {
          emit(r[0], r[1], r[2], f);
        } else if (sides == 1) {
          // fan from the corner opposite the split side
          std::vector<int> chain{r[side]};
          for (int p : it->second[side]) chain.push_back(p);
          chain.push_back(r[(side + 1) % 3]);
          for (std::size_t k = 0; k + 1 < chain.size(); ++k)
            emit(chain[k], chain[k + 1], r[(side + 2) % 3], f);
        } else {
          // several split sides: fan from the triangle's centre, projected onto the face
          std::vector<int> ring;
          for (int q = 0; q < 3; ++q) {
            ring.push_back(r[q]);
            for (int p : it->second[q]) ring.push_back(p);
          }
          const Eigen::Vector3d c = (pos[r[0]] + pos[r[1]] + pos[r[2]]) / 3;
          const int centre = static_cast<int>(pos.size());
          pos.push_back(project_onto_surface(solid.surfaces[solid.faces[f].surface], c, tol).point);
          parent.push_back(centre);
          on_edge.push_back(-1);
          on_vertex.push_back(-1);
          for (std::size_t k = 0; k < ring.size(); ++k)
            emit(ring[k], ring[(k + 1) % ring.size()], centre, f);
        }
      }
    // keep only the vertices in use, in order of global id
    std::vector<int> index(pos.size(), -1);
    for (const auto& t : tris)
      for (int q = 0; q < 3; ++q) index[t[q]] = 0;
    SolidMesh mesh;
    mesh.chordal_error = chordal_error;
    std::vector<std::uint64_t> surfaces_at;
    for (std::size_t g = 0; g < pos.size(); ++g) {
      if (index[g] < 0) continue;
      index[g] = static_cast<int>(mesh.positions.size());
      mesh.positions.push_back(pos[g]);
      mesh.vertex_edge.push_back(on_edge[g]);
      mesh.vertex_vertex.push_back(on_vertex[g]);
      surfaces_at.push_back(0);
    }
    for (std::size_t t = 0; t < tris.size(); ++t) {
      const Eigen::Vector3i T(index[tris[t][0]], index[tris[t][1]], index[tris[t][2]]);
      mesh.triangles.push_back(T);
      mesh.triangle_face.push_back(tri_face[t]);
      for (int q = 0; q < 3; ++q)
        surfaces_at[T[q]] |= std::uint64_t{1} << solid.faces[tri_face[t]].surface;
    }
    // vertex normals: exact inside faces, the mean of the meeting faces' normals on edges
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      for (int s = 0; s < static_cast<int>(solid.surfaces.size()); ++s)
        if (surfaces_at[v] >> s & 1) n += unit_normal(solid.surfaces[s], mesh.positions[v]);
      mesh.normals.push_back(n.normalized());
    }
    // corner normals: the triangle's own face's, which differs from the vertex's on edges only
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const int s = solid.faces[mesh.triangle_face[t]].surface;
      for (int q = 0; q < 3; ++q) {
        const int v = mesh.triangles[t][q];
        mesh.corner_normals.push_back(std::popcount(surfaces_at[v]) == 1
                                          ? mesh.normals[v]
                                          : unit_normal(solid.surfaces[s], mesh.positions[v]));
      }
    }
    for (int e = 0; e < static_cast<int>(solid.edges.size()); ++e) {
      std::vector<Eigen::Vector3d> line;
      for (const auto& [s, r] : edge_points[e])
        if (index[r] >= 0) line.push_back(pos[r]);
      if (solid.edges[e].closed && !line.empty()) line.push_back(line.front());
      mesh.edge_polylines.push_back(std::move(line));
    }
    return mesh;
  }
};

}  // namespace

SolidMesh mesh_solid(const Solid& solid, double chordal_error, const Tolerances& tol) {
  Mesher m{solid, tol, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  m.mesh_faces(chordal_error);
  m.snap_vertices();
  m.find_boundary();
  m.merge_edge_points();
  SolidMesh mesh = m.assemble(chordal_error);
  cover_extremes(solid, mesh, tol);
  return mesh;
}

}  // namespace pcsg
