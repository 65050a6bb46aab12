#pragma once
// The collision models of a scene, built once and shared read-only by every detection query
// (and any number of threads): one FCL BVHModel<OBBRSSd> per solid (TOOLCHAIN: the one BV type
// that FCL 0.7 does not refit per query), over the solid's mesh inflated outward. Meshes only
// propose where contacts may be; the exact surfaces decide (paper Section IV: "our approach
// generate[s] exact point contacts ... without mesh-based approximation").
//
// Inflation: every mesh vertex moves out by delta = chordal error + band / 2 along the miter
// of the normals of the surfaces it lies on (so edges and vertices are covered too). A mesh is
// within its chordal error of the exact surface, so the inflated shells of A and B overlap
// wherever the exact gap is below the band, and each overlap region of the shells surrounds
// one or more local minima of the distance.
#include <Eigen/Core>
#include <memory>
#include <utility>
#include <vector>

#include "engine/contact/report_cache.h"
#include "engine/core/pose.h"
#include "engine/geometry/scene_geometry.h"

namespace pcsg {

// What detection needs to know about one solid's mesh triangles.
struct MeshIndex {
  std::vector<Eigen::Vector3d> centroids;  // per triangle, in the solid's frame
  // Per triangle, the elements whose contacts it may witness: its face, and the edges and
  // vertices of that face within reach of the triangle (CSR: element_offsets has T + 1 rows).
  std::vector<int> element_offsets;
  std::vector<ElementId> elements;
  // Per triangle, the triangles sharing a vertex with it (CSR), for grouping overlaps.
  std::vector<int> neighbor_offsets;
  std::vector<int> neighbors;
  // Per face of the solid, the mesh vertices of its triangles, ascending (pair_local_minima's
  // starts: listed once here instead of by a scan of every triangle at each call).
  std::vector<std::vector<int>> face_vertices;
  int triangle_count() const { return static_cast<int>(centroids.size()); }
};

// The triangle pairs that may overlap near a reference pose: every pair whose inflated
// triangles' bounding boxes (and their BVH ancestors') come within `margin` of each other at
// `X_BA`. At any pose that moves
// no point of A's inflated mesh farther than `margin` from where X_BA puts it, the overlapping
// pairs are among these, so events are located by bisection with one BVH traversal per bracket
// instead of one per pose.
struct NearbyTriangles {
  Pose X_BA;
  double margin = 0;
  // Leaf nodes of the two BVHs (A's, B's), so that a pose's test is FCL's own leaf test.
  std::vector<std::pair<int, int>> leaves;
  // False when gathering stopped at the cap (nearly conformal surfaces and a wide margin): then
  // the set answers for no pose.
  bool complete = true;
};

class ContactContext {
 public:
  // `scene` must outlive the context. `band` (a length, > 0) is the gap up to which local
  // minima are guaranteed to be found; 0 takes scene.tol.candidate_band.
  explicit ContactContext(const SceneGeometry& scene, double band = 0);
  ~ContactContext();
  ContactContext(const ContactContext&) = delete;
  ContactContext& operator=(const ContactContext&) = delete;

  const SceneGeometry& scene() const { return *scene_; }
  double guaranteed_band() const { return band_; }
  const MeshIndex& index_A() const { return index_A_; }
  const MeshIndex& index_B() const { return index_B_; }

  // The (A triangle, B triangle) pairs whose inflated triangles intersect at the pose, at most
  // `max_pairs` of them; returns false when that cap cut the list short.
  bool overlapping_triangles(const Pose& X_BA, std::vector<std::pair<int, int>>& pairs,
                             int max_pairs) const;
  // The same list from fcl::collide itself (the reference overlapping_triangles reproduces,
  // pair for pair and in the same order, with fewer box tests; tests compare the two).
  bool overlapping_triangles_by_fcl(const Pose& X_BA, std::vector<std::pair<int, int>>& pairs,
                                    int max_pairs) const;

  // The pairs that may overlap at any pose within `margin` of X_BA (see NearbyTriangles).
  NearbyTriangles nearby_triangles(const Pose& X_BA, double margin) const;
  // The same for a smaller neighbourhood, filtered from `wide` when `wide` covers it (poses
  // within `margin` of X_BA lie within wide.margin of wide.X_BA), else gathered afresh.
  NearbyTriangles nearby_triangles(const Pose& X_BA, double margin,
                                   const NearbyTriangles& wide) const;
  // The pairs that may overlap near the way from X to Y: about their middle, with a margin of
  // `growth` (>= 1) times the displacement to either end; filtered from `wide` when given and
  // covering.
  NearbyTriangles nearby_triangles_between(const Pose& X, const Pose& Y, double growth,
                                           const NearbyTriangles* wide = nullptr) const;
  // The same list as overlapping_triangles(X_BA, ...) when displacement(near.X_BA, X_BA) <=
  // near.margin: FCL's leaf test (leaf boxes, then triangles) on the nearby pairs only. Returns
  // false when the pose is not covered or the cap would cut the list (then the caller asks
  // overlapping_triangles).
  bool overlapping_triangles_near(const Pose& X_BA, const NearbyTriangles& near,
                                  std::vector<std::pair<int, int>>& pairs, int max_pairs) const;
  // An upper bound on how far any point of A's inflated mesh moves from pose X to pose Y.
  double displacement(const Pose& X, const Pose& Y) const;
  // The reports of recent queries (detect_contacts answers a repeated query from them).
  ReportCache& recent_reports() const { return *recent_reports_; }

 private:
  struct Models;
  const SceneGeometry* scene_;
  double band_ = 0;
  MeshIndex index_A_, index_B_;
  std::unique_ptr<Models> models_;
  std::unique_ptr<ReportCache> recent_reports_;
};

// The nearby triangle pairs of a bisection's shrinking bracket: gathered at the first step and
// narrowed as the bracket halves. Where the surfaces are nearly conformal a wide bracket holds
// too many pairs (the gathering stops at its cap): it is tried again once the bracket has
// shrunk fourfold, at most a few times; meanwhile the poses are queried in full.
class BracketTriangles {
 public:
  // `growth` (>= 1): the margin over the bracket's half-length (nearby_triangles_between).
  BracketTriangles(const ContactContext& context, double growth)
      : context_(context), growth_(growth) {}
  // The pairs for the bracket [lo, hi] of the next bisection step, or nullptr (query in full).
  const NearbyTriangles* update(const Pose& lo, const Pose& hi);

 private:
  const ContactContext& context_;
  double growth_;
  NearbyTriangles near_;
  bool have_ = false;
  int step_ = 0, next_try_ = 0, tries_ = 0;
};

// A context for `scene` from a small process-wide cache keyed by the scene's address and
// checked against a fingerprint of its contents (sizes, polynomials, sampled mesh vertices),
// so that detect_contacts(scene, ...) does not rebuild the BVHs on every call. Thread-safe.
std::shared_ptr<const ContactContext> cached_contact_context(const SceneGeometry& scene);

}  // namespace pcsg
