// detect_contacts: candidates from the inflated meshes' overlaps, exact local minima from the
// pair solves, classification by the elements that hold the points (paper Section II-B).
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "engine/contact/contact_classification.h"
#include "engine/contact/contact_context.h"
#include "engine/contact/element_geometry.h"
#include "engine/contact/surface_descent.h"
#include "engine/geometry/surface.h"

namespace pcsg {
namespace {

// Triangle pairs read from one FCL query: a contact's neighbourhood holds tens; a deep
// penetration may hold thousands, and then any of them proves it.
constexpr int kMaxTrianglePairs = 100000;

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) {
    for (int i = 0; i < n; ++i) parent[i] = i;
  }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Marks a set of one mesh's triangles for O(1) membership tests; one per thread, cleared by
// bumping the generation rather than by writing every triangle.
struct TriangleMarks {
  std::vector<unsigned> mark;
  unsigned generation = 0;
  void clear(const MeshIndex& idx) {
    if (mark.size() != static_cast<size_t>(idx.triangle_count())) {
      mark.assign(idx.triangle_count(), 0);
      generation = 0;
    }
    if (++generation == 0) {  // wrapped: start over
      std::fill(mark.begin(), mark.end(), 0);
      generation = 1;
    }
  }
  // Marks t and the triangles sharing a vertex with it.
  void mark_around(const MeshIndex& idx, int t) {
    mark[t] = generation;
    for (int k = idx.neighbor_offsets[t]; k < idx.neighbor_offsets[t + 1]; ++k)
      mark[idx.neighbors[k]] = generation;
  }
  bool marked(int u) const { return mark[u] == generation; }
};

// Groups the overlapping triangle pairs into connected regions: two pairs are connected when
// their A triangles and their B triangles are equal or share a vertex. Splitting one region
// only costs a repeated solve; merging two would lose a minimum, so adjacency is strict.
std::vector<int> group_pairs(const ContactContext& ctx, std::vector<std::pair<int, int>>& pairs) {
  std::sort(pairs.begin(), pairs.end());
  const int n = static_cast<int>(pairs.size());
  UnionFind uf(n);
  const MeshIndex& iA = ctx.index_A();
  const MeshIndex& iB = ctx.index_B();
  // Where each A triangle's pairs start in the sorted list (valid where `first_A` marks it).
  thread_local TriangleMarks first_A, near_B;
  thread_local std::vector<int> start_A;
  first_A.clear(iA);
  start_A.resize(iA.triangle_count());
  for (int i = n - 1; i >= 0; --i) {
    first_A.mark[pairs[i].first] = first_A.generation;
    start_A[pairs[i].first] = i;
  }
  // Connection is symmetric (sharing a vertex is), so each pair looks only at the pairs after
  // it in the sorted list: the rest of its A triangle's run, then the runs of the A triangles
  // after it that share a vertex with it (each neighbour list is sorted). The components,
  // and their roots (each the least index in it), are those of looking at every pair.
  for (int i = 0; i < n; ++i) {
    const auto [tA, tB] = pairs[i];
    near_B.clear(iB);
    near_B.mark_around(iB, tB);  // tB and the B triangles sharing a vertex with it
    for (int j = i + 1; j < n && pairs[j].first == tA; ++j)
      if (near_B.marked(pairs[j].second)) uf.unite(i, j);
    const int* nA = iA.neighbors.data() + iA.neighbor_offsets[tA];
    const int* end = iA.neighbors.data() + iA.neighbor_offsets[tA + 1];
    for (nA = std::upper_bound(nA, end, tA); nA != end; ++nA) {
      if (!first_A.marked(*nA)) continue;
      for (int j = start_A[*nA]; j < n && pairs[j].first == *nA; ++j)
        if (near_B.marked(pairs[j].second)) uf.unite(i, j);
    }
  }
  std::vector<int> group(n);
  for (int i = 0; i < n; ++i) group[i] = uf.find(i);
  return group;
}

// A starting point on an element near a triangle's centroid.
Eigen::Vector3d start_on(const Solid& solid, ElementId id, const Eigen::Vector3d& centroid) {
  if (id.kind == ElementKind::Vertex) return solid.vertices[id.index].point;
  if (id.kind == ElementKind::Edge) {
    const auto& samples = solid.edges[id.index].samples;
    Eigen::Vector3d best = centroid;
    double bd = INFINITY;
    for (const CurveSample& s : samples)
      if ((s.point - centroid).squaredNorm() < bd) {
        bd = (s.point - centroid).squaredNorm();
        best = s.point;
      }
    return best;
  }
  return centroid;
}

// resolve_contact from mesh-derived starts; when a face is involved and that finds no distance
// minimum within `region_gap` (one the overlap region can hold), again from the point of the face
// whose normal is opposite the other element's (the middle of its normal cone) at its start. A
// strongly curved face holds its contact where its normal turns opposite the other's: the needle's
// tips (scenes/stress/needle_in_dish.yaml, radius of curvature 2e-5 L) touch the dish ~1e-5 L from
// their apex, and from a mesh start a cell away the pair's Newton converged to a saddle pairing the
// tip with the dish 0.17 L away (or diverged), so detection saw nothing at touching poses, only the
// penetration past its tolerance; or to a minimum with a gap of 2.3 pairing the tip with the dish
// far away, while the tip poked into the dish (scenes/stress/needle_rotated.yaml). Costs nothing
// where the first solve finds the region's minimum.
ResolvedContact resolve_from_mesh_start(const SceneGeometry& scene, const Pose& X_BA, ElementId a,
                                        ElementId b, const Eigen::Vector3d& start_A,
                                        const Eigen::Vector3d& start_B, double region_gap) {
  // a minimum the region can hold (detect_anew: region_gap)
  auto holds = [&](const ResolvedContact& r) {
    return r.found && r.minimum && r.contact.gap <= region_gap;
  };
  ResolvedContact res = resolve_contact(scene, X_BA, a, b, start_A, start_B);
  if (holds(res) || (a.kind != ElementKind::Face && b.kind != ElementKind::Face)) return res;
  // the middle of an element's normal cone at p: its surfaces' unit normals summed
  auto middle_normal = [](const Solid& S, ElementId el, const Eigen::Vector3d& p) {
    const SurfaceSet set = element_surfaces(S, el);
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (int k = 0; k < set.size; ++k) n += unit_normal(S.surfaces[set.index[k]], p);
    return n.normalized();
  };
  if (a.kind == ElementKind::Face) {
    const Polynomial& gA = scene.A.surfaces[scene.A.faces[a.index].surface];
    const Eigen::Vector3d u = -(X_BA.quaternion.conjugate() * middle_normal(scene.B, b, start_B));
    if (const auto pA =
            u.allFinite() ? point_with_normal(gA, u, start_A, scene.tol) : std::nullopt) {
      ResolvedContact again = resolve_contact(scene, X_BA, a, b, *pA, start_B);
      if (holds(again)) return again;
    }
  }
  if (b.kind == ElementKind::Face) {
    const Polynomial& gB = scene.B.surfaces[scene.B.faces[b.index].surface];
    const Eigen::Vector3d u = -(X_BA.quaternion * middle_normal(scene.A, a, start_A));
    if (const auto pB =
            u.allFinite() ? point_with_normal(gB, u, start_B, scene.tol) : std::nullopt) {
      ResolvedContact again = resolve_contact(scene, X_BA, a, b, start_A, *pB);
      if (holds(again)) return again;
    }
  }
  return res;
}

struct Candidate {
  ElementId a, b;
  int pair = -1;  // index of the closest triangle pair of the region witnessing it
  double distance = INFINITY;
};

// Do the triangles of `pair` belong to the candidate's elements?
bool witnesses_pair(const ContactContext& ctx, std::pair<int, int> pair, const Candidate& c) {
  const MeshIndex& iA = ctx.index_A();
  const MeshIndex& iB = ctx.index_B();
  bool a = false, b = false;
  for (int k = iA.element_offsets[pair.first]; k < iA.element_offsets[pair.first + 1]; ++k)
    a = a || iA.elements[k] == c.a;
  for (int k = iB.element_offsets[pair.second]; k < iB.element_offsets[pair.second + 1]; ++k)
    b = b || iB.elements[k] == c.b;
  return a && b;
}

// Pairs with two sliding directions of one point, or one of each: f-f, f-e, e-f. (Crossing
// edges have one stationary point per crossing; vertices none to slide.)
bool may_bifurcate(const Candidate& c) {
  const bool fa = c.a.kind == ElementKind::Face, fb = c.b.kind == ElementKind::Face;
  return (fa && fb) || (fa && c.b.kind == ElementKind::Edge) ||
         (fb && c.a.kind == ElementKind::Edge);
}

// More starting pairs of a candidate, in the same overlap region: one region of the inflated
// meshes' overlap can hold several local minima of one element pair, and the Newton solve
// from its closest triangle pair reaches one of them, or a saddle between them, or none.
// (1) Apart: where the gap between two contacts of one pair stays within the meshes' reach,
// their overlap rings join into one region: Example 1's ellipsoid lying across the dish's rim
// ({(fA-e1, 2)}, contacts 3.3 apart) or along the dish ({(fA-f1, 2)}, sometimes no contact
// found at all: the first solve ended at a saddle). Measured on Example 1's generation: at 328
// poses where a motion kept such a state, detection missed one contact that the pair solve
// from its tracked points found to be a minimum with gap below 1e-11 L, so the motion saw a
// kept contact vanish; with the starts below, none. Two minima of one pair lie at least
// Tolerances::seed_separation apart, so while a witness of the candidate lies farther than
// that from every start solved from and every minimum found, it is solved from too (the
// farthest first), after a minimum, a saddle or a failed solve alike.
// (2) Next to a bifurcation where two contacts merge (surfaces of nearly matching curvature,
// scenes/stress/near_matching_curvature.yaml) they lie 0.8% of L apart with a saddle
// 3.8e-8 L above them, far below what the meshes resolve. Two minima about to merge are flat
// along the line joining them, so when the first minimum's relative curvature is below
// Tolerances::bifurcation_curvature, the witness farthest from it is solved from whatever its
// distance: the other minimum, if any, lies beyond the first one from there.
// Pairs are placed at the midpoints of their triangles' centroids, so that the choice does not
// depend on which object is A (the metamorphic swap tests). Solutions are deduplicated by
// Tolerances::distinct_points.
// The witness farthest from every point of `centres`, and that distance (-1: no witness).
std::pair<int, double> farthest_witness(const std::vector<Eigen::Vector3d>& centres,
                                        const std::vector<int>& witnesses,
                                        const std::vector<Eigen::Vector3d>& midpoints) {
  int best = -1;
  double bd = -1;
  for (int p : witnesses) {
    double d = INFINITY;
    for (const Eigen::Vector3d& c : centres) d = std::min(d, (midpoints[p] - c).squaredNorm());
    if (d > bd) {
      bd = d;
      best = p;
    }
  }
  return {best, best < 0 ? -1.0 : std::sqrt(bd)};
}

// Solves per candidate and region beyond the first: regions seen hold at most two minima of
// one pair; the cap bounds the cost of a region whose witnesses form a long band.
constexpr int kMaxExtraSolves = 4;

bool same_contact(const PointContact& x, const PointContact& y, double distinct) {
  return x.a == y.a && x.b == y.b && x.type == y.type && (x.point_B - y.point_B).norm() <= distinct;
}

// Dimension of an element (face 2, edge 1, vertex 0).
int dimension(ElementId id) {
  return id.kind == ElementKind::Face ? 2 : id.kind == ElementKind::Edge ? 1 : 0;
}

// Do the points a and b (in `solid`'s frame) and the segment between them lie on every surface
// that both elements lie on, to `gap` at its midpoint? False when the elements share none.
bool segment_on_common_surfaces(const Solid& solid, ElementId x, ElementId y,
                                const Eigen::Vector3d& a, const Eigen::Vector3d& b, double gap) {
  const SurfaceSet sx = element_surfaces(solid, x), sy = element_surfaces(solid, y);
  const Eigen::Vector3d m = 0.5 * (a + b);
  bool common = false;
  for (int k = 0; k < sx.size; ++k) {
    if (!sy.contains(sx.index[k])) continue;
    common = true;
    if (std::abs(surface_distance(solid.surfaces[sx.index[k]], m)) > gap) return false;
  }
  return common;
}

// One contact found through two element pairs, the pair of lower dimension kept: the paper
// names a contact by the elements whose relative interiors hold its point.
// (a) One point: a contact at an edge point solved as f-f from one start (its point on the
// face's boundary, within Tolerances::on_boundary) and as f-e from another. Seen in Example 1
// with B moved 1e4 L away: fA-f2 and fA-e2 at one point (gaps -3.7e-12 and -7.6e-13), a state
// {(fA-e2, 1), (fA-f2, 1)} that no convex A can reach.
// (b) Two points on one contact at the gap tolerance: A touching B's face 1.3e-6 L from its
// edge, where the edge's own distance minimum lies within contact_gap too (the surfaces part
// by ~ curvature x distance^2, 1e-12 L here). Both pairs' minima are contacts, 1.3e-6 L
// apart: seen in Example 1 with A and B swapped as a state {(fA-e1, 2), (fA-f1, 1)} whose
// f-f and f-e contacts were one. They are one contact when the segment between them lies on
// the surfaces both pairs' elements share, to contact_gap at its midpoint, on A and on B; two
// separate contacts (0.05 L apart, the surfaces parting by 1e-4 L between them) are kept.
// (c) One pair's minimum found twice along such a segment, from two starts of one region
// (contact_detection's further starts): the first found is kept. Seen with the two lenses'
// nearly collinear rims (scenes/stress/collinear_edges.yaml, A and B swapped) as a state
// {(eA-eB, 2)}, which two convex solids cannot have.
void drop_boundary_duplicates(const SceneGeometry& scene, std::vector<PointContact>& minima) {
  const Tolerances& tol = scene.tol;
  std::vector<bool> drop(minima.size(), false);
  for (size_t i = 0; i < minima.size(); ++i)
    for (size_t j = 0; j < minima.size(); ++j) {
      const PointContact &x = minima[i], &y = minima[j];
      const bool same_pair = x.a == y.a && x.b == y.b;
      if (i == j || drop[j] || (same_pair && j > i)) continue;
      const bool one_point = (x.p_A - y.p_A).norm() <= tol.distinct_points &&
                             (x.p_B - y.p_B).norm() <= tol.distinct_points;
      if (!one_point &&
          !(segment_on_common_surfaces(scene.A, x.a, y.a, x.p_A, y.p_A, tol.contact_gap) &&
            segment_on_common_surfaces(scene.B, x.b, y.b, x.p_B, y.p_B, tol.contact_gap)))
        continue;
      // x is dropped for y when y's pair has lower dimension, or is x's pair found first
      // (other ties are kept: not this case)
      const int dx = dimension(x.a) + dimension(x.b), dy = dimension(y.a) + dimension(y.b);
      if (dy < dx || same_pair) {
        drop[i] = true;
        break;
      }
    }
  size_t k = 0;
  for (size_t i = 0; i < minima.size(); ++i)
    if (!drop[i]) minima[k++] = std::move(minima[i]);
  minima.resize(k);
}

// Canonical order: by pair and type, then by place (never by gap, whose last bits are
// round-off when two contacts are symmetric).
auto order_key(const PointContact& c) {
  return std::make_tuple(c.a, c.b, static_cast<int>(c.type), c.point_B.x(), c.point_B.y(),
                         c.point_B.z());
}

// How deep p lies inside `solid` (first order: -max_i g_i / |grad g_i|), when deeper than
// `depth`; nullopt otherwise. Exits at the first inequality that p does not satisfy by depth,
// so points outside (most of them) cost one or two evaluations.
std::optional<double> depth_inside(const Solid& solid, const Eigen::Vector3d& p, double depth) {
  double worst = -INFINITY;
  for (const Polynomial& g : solid.surfaces) {
    double v;
    Eigen::Vector3d grad;
    g.evaluate(p, &v, nullptr, nullptr);
    if (v >= 0) return std::nullopt;
    g.evaluate(p, nullptr, &grad, nullptr);
    const double d = v / grad.norm();
    if (d >= -depth) return std::nullopt;
    worst = std::max(worst, d);
  }
  return -worst;
}

// Mesh vertices (exact surface points) of one solid strictly inside the other prove a
// penetration even where no pair solve found its deepest point.
void vertex_evidence(const SolidMesh& mesh, const std::vector<int>& triangles, const Solid& other,
                     const Pose& to_other, double depth,
                     std::optional<std::pair<Eigen::Vector3d, double>>& deepest) {
  for (int t : triangles)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = to_other.apply(mesh.positions[mesh.triangles[t][k]]);
      const auto d = depth_inside(other, p, depth);
      if (d && (!deepest || *d > deepest->second)) deepest = std::make_pair(p, *d);
    }
}

std::vector<int> unique_sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// The overlap regions of the inflated meshes and, per region, each element pair witnessed
// there with its closest triangle pair (the starting points of its solve).
struct Regions {
  std::vector<std::vector<Candidate>> candidates;  // per region
  std::vector<int> region_of;                      // per triangle pair
};

Regions collect_regions(const ContactContext& ctx, const Pose& X_BA,
                        std::vector<std::pair<int, int>>& pairs) {
  const std::vector<int> group = group_pairs(ctx, pairs);
  const MeshIndex& iA = ctx.index_A();
  const MeshIndex& iB = ctx.index_B();
  Regions out;
  out.region_of.assign(pairs.size(), -1);
  std::vector<int> region_index(pairs.size(), -1);
  // group_pairs sorted the pairs by A's triangle: its centroid placed once per run of pairs.
  int placed_tA = -1;
  Eigen::Vector3d placed_centroid = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < pairs.size(); ++i) {
    const int root = group[i];
    if (region_index[root] < 0) {
      region_index[root] = static_cast<int>(out.candidates.size());
      out.candidates.emplace_back();
    }
    out.region_of[i] = region_index[root];
    auto& cands = out.candidates[out.region_of[i]];
    const auto [tA, tB] = pairs[i];
    if (tA != placed_tA) {
      placed_tA = tA;
      placed_centroid = X_BA.apply(iA.centroids[tA]);
    }
    const double d = (placed_centroid - iB.centroids[tB]).norm();
    for (int ka = iA.element_offsets[tA]; ka < iA.element_offsets[tA + 1]; ++ka)
      for (int kb = iB.element_offsets[tB]; kb < iB.element_offsets[tB + 1]; ++kb) {
        const ElementId a = iA.elements[ka], b = iB.elements[kb];
        auto it = std::find_if(cands.begin(), cands.end(),
                               [&](const Candidate& c) { return c.a == a && c.b == b; });
        if (it == cands.end()) it = cands.insert(cands.end(), Candidate{a, b});
        if (d < it->distance) {
          it->distance = d;
          it->pair = static_cast<int>(i);
        }
      }
  }
  return out;
}

// Steps of the descent on a face (surface_descent.h): the adaptive step reaches the bottom of
// a valley across a ring in tens of steps; the rest creep along it toward its deepest point.
constexpr int kDescentSteps = 200;

// Detection's fallback for a face pair of region r whose solve failed or ended at a saddle
// (where a solve from elsewhere in a long valley may end: the needle of
// scenes/stress/needle_in_dish.yaml poked through the dish): each face's deepest
// point inside the other's surface, by descent on the face from its deepest mesh vertex in
// the region (surface_descent.h). A point of one solid's boundary strictly inside the other
// proves the penetration that the failed solve could not locate, where the mesh vertices
// alone miss a thin sliver (a ring contact 1.1e-3 deep in scenes/torus.yaml, no vertex in it).
std::optional<Penetration> deepest_face_points(const ContactContext& ctx, const Pose& X_BA,
                                               const std::vector<std::pair<int, int>>& pairs,
                                               const std::vector<int>& region_of, size_t r,
                                               const Candidate& c) {
  const SceneGeometry& scene = ctx.scene();
  const Tolerances& tol = scene.tol;
  const Pose X_AB{X_BA.apply_inverse(Eigen::Vector3d::Zero()), X_BA.quaternion.conjugate()};
  std::vector<int> tris_A, tris_B;
  for (size_t i = 0; i < pairs.size(); ++i) {
    if (region_of[i] != static_cast<int>(r)) continue;
    if (scene.mesh_A.triangle_face[pairs[i].first] == c.a.index) tris_A.push_back(pairs[i].first);
    if (scene.mesh_B.triangle_face[pairs[i].second] == c.b.index) tris_B.push_back(pairs[i].second);
  }
  std::optional<Penetration> out;
  // S's face f descending into O's face fo; T maps S's frame into O's
  auto side = [&](const Solid& S, const SolidMesh& M, int f, const std::vector<int>& tris,
                  const Solid& O, int fo, const Pose& T, bool s_is_A) {
    const int so = O.faces[fo].surface;
    const Polynomial& h = O.surfaces[so];
    Eigen::Vector3d start = Eigen::Vector3d::Zero();
    double best = INFINITY;
    for (int t : unique_sorted(tris))
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d& p = M.positions[M.triangles[t][k]];
        double v;
        Eigen::Vector3d grad;
        h.evaluate(T.apply(p), &v, &grad, nullptr);
        if (v / grad.norm() < best) {
          best = v / grad.norm();
          start = p;
        }
      }
    if (!std::isfinite(best)) return;
    const SurfaceDescent sd =
        descend_into(S, f, T, O, so, start, tol.length_scale, tol.penetration, kDescentSteps);
    const Eigen::Vector3d x = T.apply(sd.point);
    if (const auto depth = depth_inside(O, x, tol.penetration))
      if (!out || *depth > out->depth) out = Penetration{c.a, c.b, s_is_A ? x : sd.point, *depth};
  };
  side(scene.A, scene.mesh_A, c.a.index, tris_A, scene.B, c.b.index, X_BA, true);
  side(scene.B, scene.mesh_B, c.b.index, tris_B, scene.A, c.a.index, X_AB, false);
  return out;
}

// Penetrations that no solve located in a region (and one solid wholly inside the other):
// surface points of one solid inside the other.
void add_unsolved_penetrations(const SceneGeometry& scene, const Pose& X_BA,
                               const std::vector<std::pair<int, int>>& pairs,
                               const Regions& regions, const std::vector<bool>& solved,
                               ContactReport& report) {
  const double depth = scene.tol.penetration;
  const Pose X_AB{X_BA.apply_inverse(Eigen::Vector3d::Zero()), X_BA.quaternion.conjugate()};
  const size_t n = regions.candidates.size();
  std::vector<std::vector<int>> tris_A(n), tris_B(n);
  for (size_t i = 0; i < pairs.size(); ++i) {
    tris_A[regions.region_of[i]].push_back(pairs[i].first);
    tris_B[regions.region_of[i]].push_back(pairs[i].second);
  }
  for (size_t r = 0; r < n; ++r) {
    if (solved[r]) continue;
    std::optional<std::pair<Eigen::Vector3d, double>> deep_A, deep_B;
    vertex_evidence(scene.mesh_A, unique_sorted(std::move(tris_A[r])), scene.B, X_BA, depth,
                    deep_A);
    vertex_evidence(scene.mesh_B, unique_sorted(std::move(tris_B[r])), scene.A, X_AB, depth,
                    deep_B);
    if (!deep_A && !deep_B) continue;
    const auto [tA, tB] = pairs[regions.candidates[r].front().pair];
    const ElementId a{ElementKind::Face, scene.mesh_A.triangle_face[tA]};
    const ElementId b{ElementKind::Face, scene.mesh_B.triangle_face[tB]};
    if (deep_A && (!deep_B || deep_A->second >= deep_B->second))
      report.penetrations.push_back({a, b, deep_A->first, deep_A->second});
    else
      report.penetrations.push_back({a, b, X_BA.apply(deep_B->first), deep_B->second});
  }
  // One solid entirely inside the other: no surfaces cross, so no triangles overlap.
  if (pairs.empty()) {
    const Eigen::Vector3d a0 = X_BA.apply(scene.mesh_A.positions.front());
    const Eigen::Vector3d b0 = scene.mesh_B.positions.front();
    const ElementId a{ElementKind::Face, scene.mesh_A.triangle_face.front()};
    const ElementId b{ElementKind::Face, scene.mesh_B.triangle_face.front()};
    if (const auto d = depth_inside(scene.B, a0, depth))
      report.penetrations.push_back({a, b, a0, *d});
    else if (const auto d2 = depth_inside(scene.A, X_AB.apply(b0), depth))
      report.penetrations.push_back({a, b, b0, *d2});
  }
}

// A report as DetectOptions::stop_at_penetration gives it: the first penetration alone.
void cut_at_first_penetration(ContactReport& report) {
  report.penetrations.resize(1);
  report.contacts.clear();
  report.near.clear();
  report.failed_solves = 0;
  report.cut_short = true;
}

// detect_contacts without the recent reports.
ContactReport detect_anew(const ContactContext& ctx, const Pose& X_BA,
                          const DetectOptions& options) {
  const SceneGeometry& scene = ctx.scene();
  const Tolerances& tol = scene.tol;
  ContactReport report;
  // Where the inflated meshes overlap, the exact gap is below the two inflations plus the two
  // chordal errors (contact_context.h); a minimum beyond twice that is not the region's own:
  // the solve wandered to another pairing (the needle of scenes/stress/needle_rotated.yaml
  // poked into the dish, its solve ending at a minimum 2.3 away, 0.17 L). Such a solve is
  // retried (resolve_from_mesh_start) and, failing that, counts as unresolved.
  const double region_gap =
      2 * (2 * (scene.mesh_A.chordal_error + scene.mesh_B.chordal_error) + ctx.guaranteed_band());
  std::vector<std::pair<int, int>> pairs;
  if (!options.nearby ||
      !ctx.overlapping_triangles_near(X_BA, *options.nearby, pairs, kMaxTrianglePairs))
    ctx.overlapping_triangles(X_BA, pairs, kMaxTrianglePairs);
  const Regions regions = collect_regions(ctx, X_BA, pairs);

  // Exact solves, de-duplicated: several candidates of a region reach the same contact.
  std::vector<PointContact> minima;
  std::vector<bool> penetrates(regions.candidates.size(), false);
  // one solve of candidate c of region r from triangle pair `start`: what it found
  enum class Found { Nothing, Failed, Penetration, Saddle, Minimum };
  auto solve_from = [&](size_t r, const Candidate& c, int start, PointContact* out) -> Found {
    const auto [tA, tB] = pairs[start];
    const ResolvedContact res = resolve_from_mesh_start(
        scene, X_BA, c.a, c.b, start_on(scene.A, c.a, ctx.index_A().centroids[tA]),
        start_on(scene.B, c.b, ctx.index_B().centroids[tB]), region_gap);
    if (!res.found) {
      if (!res.diverged) return Found::Nothing;
      ++report.failed_solves;
      return Found::Failed;
    }
    const PointContact& pc = res.contact;
    // A negative gap is a penetration when the points are inside the other solid (a
    // stationary point of the signed distance can also pair far-apart sides), or when either
    // point alone is deeper than the penetration tolerance inside the other solid: a surface
    // point of one solid in the other's interior proves that the interiors meet. The second
    // case is a body thinner than the meshes' inflation poked through a face (the needle in
    // scenes/stress/needle_in_dish.yaml), where B's point of the pair is outside A; there the
    // gap measures the far-apart pairing, not the penetration, so the point's own depth inside
    // the other solid is reported instead.
    const Eigen::Vector3d pA_in_B = X_BA.apply(pc.p_A), pB_in_A = X_BA.apply_inverse(pc.p_B);
    std::optional<Penetration> pen;
    if (pc.gap < -tol.penetration) {
      if (strictly_inside(scene.B, pA_in_B, 0) && strictly_inside(scene.A, pB_in_A, 0))
        pen = Penetration{pc.a, pc.b, pc.point_B, -pc.gap};
      else if (const auto dA = depth_inside(scene.B, pA_in_B, tol.penetration))
        pen = Penetration{pc.a, pc.b, pA_in_B, *dA};
      else if (const auto dB = depth_inside(scene.A, pB_in_A, tol.penetration))
        pen = Penetration{pc.a, pc.b, pc.point_B, *dB};
    }
    if (pen) {
      penetrates[r] = true;
      bool dup = false;
      for (const Penetration& p : report.penetrations)
        dup = dup || (p.a == pen->a && p.b == pen->b &&
                      (p.point_B - pen->point_B).norm() <= tol.distinct_points);
      if (!dup) report.penetrations.push_back(*pen);
      if (options.stop_at_penetration) cut_at_first_penetration(report);
      return Found::Penetration;
    }
    if (out) *out = pc;
    if (!res.minimum) return Found::Saddle;
    bool dup = false;
    for (const PointContact& f : minima) dup = dup || same_contact(f, pc, tol.distinct_points);
    if (!dup) minima.push_back(pc);
    return Found::Minimum;
  };
  std::vector<Eigen::Vector3d> midpoints;  // per triangle pair, filled when first needed
  std::vector<std::vector<const Candidate*>> unsettled(regions.candidates.size());
  for (size_t r = 0; r < regions.candidates.size(); ++r)
    for (const Candidate& c : regions.candidates[r]) {
      PointContact first;
      const Found found = solve_from(r, c, c.pair, &first);
      if (report.cut_short) return report;
      const bool wandered = found == Found::Minimum && first.gap > region_gap;
      if ((found == Found::Failed || found == Found::Saddle || wandered) &&
          c.a.kind == ElementKind::Face && c.b.kind == ElementKind::Face)
        unsettled[r].push_back(&c);
      if (found == Found::Penetration || found == Found::Nothing || !may_bifurcate(c)) continue;
      if (midpoints.empty()) {
        midpoints.resize(pairs.size());
        for (size_t i = 0; i < pairs.size(); ++i)
          midpoints[i] = 0.5 * (X_BA.apply(ctx.index_A().centroids[pairs[i].first]) +
                                ctx.index_B().centroids[pairs[i].second]);
      }
      // the region's triangle pairs witnessing this candidate
      std::vector<int> witnesses;
      for (size_t i = 0; i < pairs.size(); ++i)
        if (regions.region_of[i] == static_cast<int>(r) && witnesses_pair(ctx, pairs[i], c))
          witnesses.push_back(static_cast<int>(i));
      // more starts (farthest_witness): next to a bifurcation at any distance, else beyond the
      // separation of two minima
      std::vector<Eigen::Vector3d> centres = {midpoints[c.pair]};
      if (found == Found::Minimum) centres.push_back(first.point_B);
      double spread = found == Found::Minimum &&
                              sliding_curvature(scene, X_BA, first) <= tol.bifurcation_curvature
                          ? 0.0
                          : tol.seed_separation;
      for (int k = 0; k < kMaxExtraSolves; ++k) {
        const auto [end, distance] = farthest_witness(centres, witnesses, midpoints);
        if (end < 0 || end == c.pair || distance <= spread) break;
        centres.push_back(midpoints[end]);
        PointContact more;
        if (solve_from(r, c, end, &more) == Found::Minimum) centres.push_back(more.point_B);
        if (report.cut_short) return report;
        spread = tol.seed_separation;
      }
    }
  // Face pairs whose solve failed or ended at a saddle, in a region where no penetration was
  // found: neither may read as "apart" where the faces interpenetrate (deepest_face_points).
  for (size_t r = 0; r < regions.candidates.size(); ++r)
    for (const Candidate* c : unsettled[r]) {
      if (penetrates[r]) break;
      if (auto pen = deepest_face_points(ctx, X_BA, pairs, regions.region_of, r, *c)) {
        penetrates[r] = true;
        report.penetrations.push_back(*pen);
        if (options.stop_at_penetration) {
          cut_at_first_penetration(report);
          return report;
        }
      }
    }
  add_unsolved_penetrations(scene, X_BA, pairs, regions, penetrates, report);
  if (options.stop_at_penetration && report.penetrating()) {
    cut_at_first_penetration(report);
    return report;
  }

  drop_boundary_duplicates(scene, minima);
  for (PointContact& c : minima) {
    if (std::abs(c.gap) <= tol.contact_gap)
      report.contacts.push_back(std::move(c));
    else if (c.gap > tol.contact_gap && c.gap <= options.near_margin)
      report.near.push_back(std::move(c));
  }
  auto by_key = [](const PointContact& x, const PointContact& y) {
    return order_key(x) < order_key(y);
  };
  std::sort(report.contacts.begin(), report.contacts.end(), by_key);
  std::sort(report.near.begin(), report.near.end(), by_key);
  return report;
}

}  // namespace

ContactReport detect_contacts(const ContactContext& ctx, const Pose& X_BA,
                              const DetectOptions& options) {
  if (options.near_margin > ctx.guaranteed_band())
    throw std::invalid_argument("detect_contacts: near_margin exceeds the context's band");
  // a repeated query (the pose bit for bit, the same margin) gets the report it got before
  if (!options.recall) return detect_anew(ctx, X_BA, options);
  const ReportCache::Key key = ReportCache::key(X_BA, options.near_margin);
  std::optional<ContactReport> known = ctx.recent_reports().recall(key);
  if (known && (!known->cut_short || options.stop_at_penetration)) {
    known->recalled = true;
    // the answer a query stopping at its first penetration gets, whatever the cache held
    if (options.stop_at_penetration && known->penetrating()) cut_at_first_penetration(*known);
    return std::move(*known);
  }
  ContactReport report = detect_anew(ctx, X_BA, options);
  ctx.recent_reports().remember(key, report);
  return report;
}

ContactReport detect_contacts(const SceneGeometry& scene, const Pose& X_BA,
                              const DetectOptions& options) {
  return detect_contacts(*cached_contact_context(scene), X_BA, options);
}

}  // namespace pcsg
