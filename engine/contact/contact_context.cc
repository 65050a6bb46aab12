#include "engine/contact/contact_context.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/math/geometry.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "engine/contact/element_geometry.h"
#include "engine/contact/triangle_meet.h"

namespace pcsg {
namespace {

// A mesh vertex lies on a surface when within this fraction of the mesh's chordal error of it:
// vertices are projected onto their surfaces to solve accuracy (~1e-12 L), while a vertex
// inside a face is at least a fraction of a triangle (>> chordal error) from the face's edges.
constexpr double kOnSurfaceFraction = 1e-3;

// Reports kept for repeated queries (report_cache.h): Example 1 repeats 2300 poses, all but 32
// within the last 1000 queries; a report is ~1 KB.
constexpr size_t kRecentReports = 1024;

// The outward offset of a mesh vertex: m . n_i = delta for the unit normals of all surfaces the
// vertex lies on (the miter at edges and vertices), least-norm when they are dependent.
Eigen::Vector3d inflation(const Solid& solid, const Eigen::Vector3d& p, double delta,
                          double on_surface) {
  std::vector<Eigen::Vector3d> normals;
  double best = -INFINITY;
  Eigen::Vector3d best_normal = Eigen::Vector3d::Zero();
  for (const Polynomial& g : solid.surfaces) {
    double v;
    Eigen::Vector3d grad;
    g.evaluate(p, &v, &grad, nullptr);
    if (grad.norm() == 0) continue;
    const double dist = v / grad.norm();
    if (std::abs(dist) <= on_surface) normals.push_back(grad.normalized());
    if (dist > best) {
      best = dist;
      best_normal = grad.normalized();
    }
  }
  if (normals.empty()) return delta * best_normal;  // off every surface: the nearest one's
  Eigen::MatrixXd N(normals.size(), 3);
  for (size_t i = 0; i < normals.size(); ++i) N.row(i) = normals[i].transpose();
  return N.completeOrthogonalDecomposition().solve(
      Eigen::VectorXd::Constant(normals.size(), delta));
}

MeshIndex build_index(const Solid& solid, const SolidMesh& mesh, double reach) {
  MeshIndex idx;
  const int T = static_cast<int>(mesh.triangles.size());
  idx.centroids.resize(T);
  idx.element_offsets.assign(1, 0);
  std::vector<std::vector<int>> vertex_triangles(mesh.positions.size());
  for (int t = 0; t < T; ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d c =
        (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) / 3;
    idx.centroids[t] = c;
    double radius = 0;
    for (int k = 0; k < 3; ++k) {
      radius = std::max(radius, (mesh.positions[tri[k]] - c).norm());
      vertex_triangles[tri[k]].push_back(t);
    }
    // The triangle's face, then the edges and vertices of that face it may reach.
    const int f = mesh.triangle_face[t];
    idx.elements.push_back({ElementKind::Face, f});
    const double r = radius + reach;
    for (int e = 0; e < static_cast<int>(solid.edges.size()); ++e) {
      const Edge& edge = solid.edges[e];
      if (edge.face1 != f && edge.face2 != f) continue;
      if (!edge.bbox.isEmpty() && edge.bbox.exteriorDistance(c) > r) continue;
      bool near = false;
      for (const CurveSample& s : edge.samples) near = near || (s.point - c).norm() <= r;
      if (near) idx.elements.push_back({ElementKind::Edge, e});
    }
    for (int v = 0; v < static_cast<int>(solid.vertices.size()); ++v) {
      const Vertex& vert = solid.vertices[v];
      if (std::find(vert.faces.begin(), vert.faces.end(), f) == vert.faces.end()) continue;
      if ((vert.point - c).norm() <= r) idx.elements.push_back({ElementKind::Vertex, v});
    }
    idx.element_offsets.push_back(static_cast<int>(idx.elements.size()));
  }
  // Triangles sharing a vertex.
  idx.neighbor_offsets.assign(1, 0);
  for (int t = 0; t < T; ++t) {
    std::vector<int> nb;
    for (int k = 0; k < 3; ++k)
      for (int u : vertex_triangles[mesh.triangles[t][k]])
        if (u != t) nb.push_back(u);
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    idx.neighbors.insert(idx.neighbors.end(), nb.begin(), nb.end());
    idx.neighbor_offsets.push_back(static_cast<int>(idx.neighbors.size()));
  }
  idx.face_vertices.resize(solid.faces.size());
  for (size_t f = 0; f < solid.faces.size(); ++f) {
    std::vector<bool> used(mesh.positions.size(), false);
    for (int t = 0; t < T; ++t)
      if (mesh.triangle_face[t] == static_cast<int>(f))
        for (int k = 0; k < 3; ++k) used[mesh.triangles[t][k]] = true;
    for (size_t v = 0; v < used.size(); ++v)
      if (used[v]) idx.face_vertices[f].push_back(static_cast<int>(v));
  }
  return idx;
}

// Largest spacing of consecutive edge samples: a point of an edge is this close to a sample.
double sample_spacing(const Solid& solid) {
  double h = 0;
  for (const Edge& e : solid.edges)
    for (size_t k = 1; k < e.samples.size(); ++k)
      h = std::max(h, (e.samples[k].point - e.samples[k - 1].point).norm());
  return h;
}

using Model = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<Model> build_model(const Solid& solid, const SolidMesh& mesh, double delta,
                                   double on_surface) {
  std::vector<Eigen::Vector3d> inflated(mesh.positions.size());
  for (size_t i = 0; i < inflated.size(); ++i)
    inflated[i] = mesh.positions[i] + inflation(solid, mesh.positions[i], delta, on_surface);
  std::vector<fcl::Triangle> tris;
  tris.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles) tris.emplace_back(t[0], t[1], t[2]);
  auto model = std::make_shared<Model>();
  model->beginModel(static_cast<int>(tris.size()), static_cast<int>(inflated.size()));
  model->addSubModel(inflated, tris);
  model->endModel();
  model->computeLocalAABB();
  return model;
}

// B's frame relative to A's, computed exactly as FCL's oriented mesh traversal does for
// collide(A at X_BA, B at identity): the R, T of its leaf tests, bit for bit.
void relative_transform(const Pose& X_BA, Eigen::Matrix3d& R, Eigen::Vector3d& T) {
  fcl::Transform3d tf_A = fcl::Transform3d::Identity();
  tf_A.linear() = X_BA.rotation();
  tf_A.translation() = X_BA.position;
  const fcl::Transform3d& tf1 = tf_A;
  const fcl::Transform3d tf2 = fcl::Transform3d::Identity();
  fcl::relativeTransform(tf1.linear(), tf1.translation(), tf2.linear(), tf2.translation(), R, T);
}

// Relative slack of the ball test of the traversals over round-off (~1e-16 of the
// squared distances and coordinates): two balls are taken apart only when clearly so.
constexpr double kBallRoundOff = 1e-9;

// The first six tests of FCL's obbDisjoint (box B placed in box A's frame by R, T; extents
// a, b; the same 1e-6 slack): whether a face axis of either box separates them. Looser than
// the full test (it skips the nine edge-edge axes), so it prunes a traversal less, never more.
bool disjoint_on_face_axes(const Eigen::Matrix3d& B, const Eigen::Vector3d& T,
                           const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  constexpr double reps = 1e-6;  // FCL's slack on the rotation's entries
  const Eigen::Matrix3d Bf = (B.cwiseAbs().array() + reps).matrix();
  for (int i = 0; i < 3; ++i)
    if (std::abs(T[i]) > a[i] + Bf.row(i).dot(b)) return true;
  for (int j = 0; j < 3; ++j)
    if (std::abs(B.col(j).dot(T)) > b[j] + Bf.col(j).dot(a)) return true;
  return false;
}

// Whether box b2 (placed in b1's frame by R, T) may come within `margin` of box b1: the face
// axes of FCL's OBB overlap test with b1 grown by `margin` on every side (a box grown so holds
// every point within `margin` of the box). Looser than FCL's full test, which adds the nine
// edge-edge axes: it keeps a few more leaf pairs in a nearby set, each of which the leaf test
// then rejects (its boxes are apart), and costs a third as much (measured on Example 1: the
// full test took 8% of the generation's time).
bool overlap_within(const Eigen::Matrix3d& R0, const Eigen::Vector3d& T0, const fcl::OBBd& b1,
                    const fcl::OBBd& b2, double margin) {
  const Eigen::Matrix3d R = b1.axis.transpose() * (R0 * b2.axis);
  const Eigen::Vector3d T = b1.axis.transpose() * (R0 * b2.To + T0 - b1.To);
  return !disjoint_on_face_axes(R, T, Eigen::Vector3d(b1.extent.array() + margin), b2.extent);
}

// Two doubles side by side (a GCC/Clang vector extension: SSE2 on x86-64): the traversals test
// the two child pairs of a node pair at once, each lane doing a scalar test's arithmetic.
typedef double Lanes __attribute__((vector_size(16)));
typedef long long LaneMask __attribute__((vector_size(16)));

Lanes lane_abs(Lanes x) {
  const LaneMask sign = {INT64_MIN, INT64_MIN};
  return reinterpret_cast<Lanes>(reinterpret_cast<LaneMask>(x) & ~sign);
}

// Boxes in lanes: a node's two children, or one box twice.
struct BoxLanes {
  Lanes axis[9];  // axis[3 * i + k]: component k of the box's axis i
  Lanes centre[3];
};
struct BoxSizeLanes {
  Lanes extent[3];  // half-lengths along the axes
  Lanes ball;       // radius of a ball about the centre holding the box
};

// One solid's BVH as the traversals read it: FCL's nodes keep it behind out-of-line accessors,
// interleaved with the RSS half of each OBBRSS, one node at a time. Here the two children of
// a node (FCL numbers them first_child and first_child + 1, with first_child = 1, 3, 5, ...)
// sit side by side in one block, block (first_child - 1) / 2; the root, twice, in the last.
struct BoxTree {
  struct Node {
    double size = 0;      // FCL's bv.size(), for its split rule
    int first_child = 0;  // FCL's: negative at a leaf
    int primitive = -1;   // a leaf's triangle (FCL's primitiveId, an out-of-line call)
    bool leaf() const { return first_child < 0; }
  };
  std::vector<Node> nodes;
  std::vector<BoxLanes> boxes;  // per block, in the solid's frame
  std::vector<BoxSizeLanes> sizes;
  int block_of(int n) const { return n ? (n - 1) / 2 : static_cast<int>(boxes.size()) - 1; }
  static int lane_of(int n) { return n ? (n - 1) & 1 : 0; }
  int children(int n) const { return (nodes[n].first_child - 1) / 2; }
  // The nodes in the lanes of block k.
  std::pair<int, int> lanes(int k) const {
    return k + 1 == static_cast<int>(boxes.size()) ? std::pair(0, 0)
                                                   : std::pair(2 * k + 1, 2 * k + 2);
  }
};

BoxTree box_tree(const Model& model) {
  BoxTree tree;
  const int n = model.getNumBVs();
  tree.nodes.resize(n);
  tree.boxes.resize((n - 1) / 2 + 1);
  tree.sizes.resize(tree.boxes.size());
  for (int i = 0; i < n; ++i) {
    const fcl::BVNode<fcl::OBBRSSd>& node = model.getBV(i);
    tree.nodes[i] = {node.bv.size(), node.first_child, node.isLeaf() ? node.primitiveId() : -1};
    if (!node.isLeaf() && (node.first_child % 2 != 1 || node.first_child + 1 >= n))
      throw std::logic_error("ContactContext: FCL's BVH does not number children in pairs");
  }
  for (int k = 0; k < static_cast<int>(tree.boxes.size()); ++k) {
    const auto [n0, n1] = tree.lanes(k);
    for (int l = 0; l < 2; ++l) {
      const fcl::OBBd& obb = model.getBV(l ? n1 : n0).bv.obb;
      for (int m = 0; m < 9; ++m) tree.boxes[k].axis[m][l] = obb.axis.data()[m];
      for (int m = 0; m < 3; ++m) {
        tree.boxes[k].centre[m][l] = obb.To[m];
        tree.sizes[k].extent[m][l] = obb.extent[m];
      }
      tree.sizes[k].ball[l] = obb.extent.norm();
    }
  }
  return tree;
}

// Lane `L` of x in both lanes, or x itself for L < 0 (both lanes as stored).
template <int L>
inline Lanes lanes_of(Lanes x) {
  if constexpr (L < 0)
    return x;
  else
    return Lanes{x[L], x[L]};
}

// Lane by lane, whether box a of A and box b of B (placed in A's frame) are more than `margin`
// apart: by their balls (beyond round-off), or on a face axis of either box (the first six tests
// of FCL's obbDisjoint, with its slack, a grown by the margin). Bit l of the result: lane l.
// LA (LB) >= 0 reads lane LA (LB) of a's (b's) block in both lanes: one box against the two of
// the other block, broadcast where it is read instead of copied out first.
template <int LA = -1, int LB = -1>
inline __attribute__((always_inline)) int lanes_apart(const BoxLanes& a, const BoxSizeLanes& as,
                                                      const BoxLanes& b, const BoxSizeLanes& bs,
                                                      double margin) {
  constexpr double reps = 1e-6;  // FCL's slack on the rotation's entries
  Lanes ac[3], bc[3];
  for (int k = 0; k < 3; ++k) {
    ac[k] = lanes_of<LA>(a.centre[k]);
    bc[k] = lanes_of<LB>(b.centre[k]);
  }
  Lanes d[3];
  for (int k = 0; k < 3; ++k) d[k] = bc[k] - ac[k];
  const Lanes r = lanes_of<LA>(as.ball) + lanes_of<LB>(bs.ball) + margin;
  const Lanes centres = (bc[0] * bc[0] + bc[1] * bc[1] + bc[2] * bc[2]) +
                        (ac[0] * ac[0] + ac[1] * ac[1] + ac[2] * ac[2]);
  LaneMask apart = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] >
                   r * r * (1 + kBallRoundOff) + kBallRoundOff * centres;
  if (apart[0] && apart[1]) return 3;
  // Rab(i, j) = a's axis i . b's axis j, Tab(i) = a's axis i . d: b placed in a's frame;
  // FCL's slack enters as reps times the sum of the other box's extents.
  Lanes bx[9];
  for (int m = 0; m < 9; ++m) bx[m] = lanes_of<LB>(b.axis[m]);
  Lanes Rab[9], Rabs[9], Tab[3];
  for (int i = 0; i < 3; ++i) {
    const Lanes ai[3] = {lanes_of<LA>(a.axis[3 * i]), lanes_of<LA>(a.axis[3 * i + 1]),
                         lanes_of<LA>(a.axis[3 * i + 2])};
    Tab[i] = ai[0] * d[0] + ai[1] * d[1] + ai[2] * d[2];
    for (int j = 0; j < 3; ++j) {
      const Lanes* bj = bx + 3 * j;
      Rab[3 * i + j] = ai[0] * bj[0] + ai[1] * bj[1] + ai[2] * bj[2];
      Rabs[3 * i + j] = lane_abs(Rab[3 * i + j]);
    }
  }
  const Lanes ea[3] = {lanes_of<LA>(as.extent[0]) + margin, lanes_of<LA>(as.extent[1]) + margin,
                       lanes_of<LA>(as.extent[2]) + margin};
  const Lanes eb[3] = {lanes_of<LB>(bs.extent[0]), lanes_of<LB>(bs.extent[1]),
                       lanes_of<LB>(bs.extent[2])};
  const Lanes slack_a = reps * (eb[0] + eb[1] + eb[2]), slack_b = reps * (ea[0] + ea[1] + ea[2]);
  for (int i = 0; i < 3; ++i)
    apart |= lane_abs(Tab[i]) > ea[i] + (Rabs[3 * i] * eb[0] + Rabs[3 * i + 1] * eb[1] +
                                         Rabs[3 * i + 2] * eb[2] + slack_a);
  for (int j = 0; j < 3; ++j)
    apart |= lane_abs(Rab[j] * Tab[0] + Rab[3 + j] * Tab[1] + Rab[6 + j] * Tab[2]) >
             eb[j] + (Rabs[j] * ea[0] + Rabs[3 + j] * ea[1] + Rabs[6 + j] * ea[2] + slack_b);
  return (apart[0] ? 1 : 0) | (apart[1] ? 2 : 0);
}

// B's boxes placed in A's frame for one query, a block when first needed, both lanes at once.
// Only the inner tests read them (a leaf test places its boxes as FCL does), and those need no
// particular bits: their slack (kBallRoundOff, FCL's 1e-6) is far above the round-off of a
// placement. The storage is the thread's and is reused by its next query: a stamp per block
// tells the current placements.
class PlacedBoxes {
 public:
  PlacedBoxes(const BoxTree& tree, const Eigen::Matrix3d& R, const Eigen::Vector3d& T)
      : tree_(tree) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) R_[3 * r + c] = Lanes{R(r, c), R(r, c)};
      T_[r] = Lanes{T[r], T[r]};
    }
    if (stamp_.size() < tree.boxes.size()) {
      boxes_.resize(tree.boxes.size());
      stamp_.assign(tree.boxes.size(), 0);
    }
    if (++query_ == 0) {  // wrapped: start over
      std::fill(stamp_.begin(), stamp_.end(), 0);
      query_ = 1;
    }
  }
  const BoxLanes& operator[](int k) {
    BoxLanes& p = boxes_[k];
    if (stamp_[k] != query_) {
      const BoxLanes& q = tree_.boxes[k];  // in B's frame
      for (int r = 0; r < 3; ++r) {
        const Lanes* Rr = R_ + 3 * r;
        for (int i = 0; i < 3; ++i)
          p.axis[3 * i + r] =
              Rr[0] * q.axis[3 * i] + Rr[1] * q.axis[3 * i + 1] + Rr[2] * q.axis[3 * i + 2];
        p.centre[r] = Rr[0] * q.centre[0] + Rr[1] * q.centre[1] + Rr[2] * q.centre[2] + T_[r];
      }
      stamp_[k] = query_;
    }
    return p;
  }

 private:
  const BoxTree& tree_;
  Lanes R_[9], T_[3];  // R row by row, and T, each entry in both lanes
  static thread_local std::vector<BoxLanes> boxes_;
  static thread_local std::vector<unsigned> stamp_;
  static thread_local unsigned query_;
};
thread_local std::vector<BoxLanes> PlacedBoxes::boxes_;
thread_local std::vector<unsigned> PlacedBoxes::stamp_;
thread_local unsigned PlacedBoxes::query_ = 0;

// FCL's traversal order (collisionRecurse: depth-first, the larger box split, a leaf never,
// left child first) over the node pairs whose boxes are not `margin` apart (lanes_apart);
// leaf pairs go to `leaf_pair(a, b)`, which returns false to stop. Each expansion tests the two
// child pairs at once, before they are stacked, which changes the order of no visit.
template <typename LeafPair>
bool traverse(const BoxTree& tree_A, const BoxTree& tree_B, PlacedBoxes& placed, double margin,
              std::vector<std::pair<int, int>>& stack, LeafPair&& leaf_pair) {
  stack.clear();
  const int root_A = tree_A.block_of(0), root_B = tree_B.block_of(0);
  if (lanes_apart(tree_A.boxes[root_A], tree_A.sizes[root_A], placed[root_B], tree_B.sizes[root_B],
                  margin) &
      1)
    return true;
  stack.emplace_back(0, 0);
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const BoxTree::Node& na = tree_A.nodes[a];
    const BoxTree::Node& nb = tree_B.nodes[b];
    if (na.leaf() && nb.leaf()) {
      if (!leaf_pair(a, b)) return false;
      continue;
    }
    // Split the larger box (a leaf never): its children in the lanes, the other box in both.
    const bool split_A = nb.leaf() || (!na.leaf() && na.size > nb.size);
    int apart, c0, c1;
    if (split_A) {
      const int k = tree_A.children(a), kb = tree_B.block_of(b), lb = BoxTree::lane_of(b);
      const BoxLanes& pb = placed[kb];
      apart =
          lb ? lanes_apart<-1, 1>(tree_A.boxes[k], tree_A.sizes[k], pb, tree_B.sizes[kb], margin)
             : lanes_apart<-1, 0>(tree_A.boxes[k], tree_A.sizes[k], pb, tree_B.sizes[kb], margin);
      c0 = na.first_child;
    } else {
      const int k = tree_B.children(b), ka = tree_A.block_of(a), la = BoxTree::lane_of(a);
      const BoxLanes& pb = placed[k];
      apart =
          la ? lanes_apart<1, -1>(tree_A.boxes[ka], tree_A.sizes[ka], pb, tree_B.sizes[k], margin)
             : lanes_apart<0, -1>(tree_A.boxes[ka], tree_A.sizes[ka], pb, tree_B.sizes[k], margin);
      c0 = nb.first_child;
    }
    c1 = c0 + 1;
    // Right child below left, so that the left one's pairs come first.
    if (!(apart & 2)) stack.emplace_back(split_A ? c1 : a, split_A ? b : c1);
    if (!(apart & 1)) stack.emplace_back(split_A ? c0 : a, split_A ? b : c0);
  }
  return true;
}

// Whether triangles tri_a of A and tri_b of B, of two leaves of the BVHs, intersect (B placed in
// A's frame by R, T): FCL's verdict, intersect_Triangle, where it could differ, after tests that
// only decide pairs it decides alike (the leaves' boxes apart on a face axis, triangles_meet).
// FCL's full test of the leaves' boxes is left out: boxes holding intersecting triangles overlap,
// so it rejects only pairs intersect_Triangle rejects. The verdict is the conjunction of the
// face-axis test and the triangles' test, so their order is free: the triangles go first, since
// most leaf pairs that reach here have overlapping boxes (the traversal tested them already) but
// apart triangles (about 4 in 5 in Example 1), and `boxes_apart()` (the face-axis test on the
// leaves' boxes as FCL places them) runs only for the pairs the triangles do not reject.
template <typename BoxesApart>
bool leaf_pair_intersects(const Model& A, const Model& B, int tri_a, int tri_b,
                          const Eigen::Matrix3d& R, const Eigen::Vector3d& T,
                          BoxesApart&& boxes_apart) {
  const fcl::Triangle& ta = A.tri_indices[tri_a];
  const fcl::Triangle& tb = B.tri_indices[tri_b];
  const Eigen::Vector3d& p1 = A.vertices[ta[0]];
  const Eigen::Vector3d& p2 = A.vertices[ta[1]];
  const Eigen::Vector3d& p3 = A.vertices[ta[2]];
  const Eigen::Vector3d q1 = R * B.vertices[tb[0]] + T;
  const Eigen::Vector3d q2 = R * B.vertices[tb[1]] + T;
  const Eigen::Vector3d q3 = R * B.vertices[tb[2]] + T;
  const TriangleMeet m = triangles_meet(p1, p2, p3, q1, q2, q3);
  if (m == TriangleMeet::Apart || boxes_apart()) return false;
  if (m == TriangleMeet::Intersect) return true;
  return fcl::detail::Intersect<double>::intersect_Triangle(
      p1, p2, p3, B.vertices[tb[0]], B.vertices[tb[1]], B.vertices[tb[2]], R, T);
}

// FCL's face-axis test of two leaves' boxes, oa of A and ob of B (B placed in A's frame by R,
// T), with Rab and Tab as FCL forms them: ob placed (R * axes, R * centre + T), then taken
// into oa's frame.
bool leaf_boxes_apart(const fcl::OBBd& oa, const fcl::OBBd& ob, const Eigen::Matrix3d& R,
                      const Eigen::Vector3d& T) {
  const Eigen::Matrix3d Rab = oa.axis.transpose() * (R * ob.axis);
  const Eigen::Vector3d Tab = (R * ob.To + T - oa.To).transpose() * oa.axis;
  return disjoint_on_face_axes(Rab, Tab, oa.extent, ob.extent);
}

// FCL's leaf test of leaf nodes a of A and b of B (B placed in A's frame by R, T): whether
// their triangles intersect (leaf_pair_intersects, with the leaves' boxes as FCL places them).
bool leaves_intersect(const Model& A, const Model& B, const BoxTree& tree_A, const BoxTree& tree_B,
                      int a, int b, const Eigen::Matrix3d& R, const Eigen::Vector3d& T) {
  return leaf_pair_intersects(
      A, B, tree_A.nodes[a].primitive, tree_B.nodes[b].primitive, R, T,
      [&] { return leaf_boxes_apart(A.getBV(a).bv.obb, B.getBV(b).bv.obb, R, T); });
}

// Relative growth of the nearby-pairs margin over the displacement it must cover: round-off of
// the box tests is ~1e-15 relative, so 1e-6 covers it with room while adding no pairs.
constexpr double kMarginRoundOff = 1e-6;
// Most leaf pairs gathered for one neighbourhood: a full BVH query tests ~10^4 boxes, so a
// larger set costs more than the few full queries of a bisection it would replace.
constexpr size_t kMaxNearbyLeaves = 20000;

}  // namespace

struct ContactContext::Models {
  std::shared_ptr<Model> A, B;
  BoxTree tree_A, tree_B;
  // A ball about this point (A's frame) holds A's inflated mesh.
  Eigen::Vector3d centre_A = Eigen::Vector3d::Zero();
  double radius_A = 0;
};

ContactContext::ContactContext(const SceneGeometry& scene, double band)
    : scene_(&scene), band_(band > 0 ? band : scene.tol.candidate_band) {
  if (scene.mesh_A.triangles.empty() || scene.mesh_B.triangles.empty())
    throw std::invalid_argument("ContactContext: the scene has no meshes");
  const double delta_A = scene.mesh_A.chordal_error + band_ / 2;
  const double delta_B = scene.mesh_B.chordal_error + band_ / 2;
  // A triangle witnesses contacts of elements within the inflated band of it.
  const double reach = delta_A + delta_B + band_;
  index_A_ = build_index(scene.A, scene.mesh_A, reach + sample_spacing(scene.A));
  index_B_ = build_index(scene.B, scene.mesh_B, reach + sample_spacing(scene.B));
  models_ = std::make_unique<Models>();
  recent_reports_ = std::make_unique<ReportCache>(kRecentReports);
  models_->A =
      build_model(scene.A, scene.mesh_A, delta_A, kOnSurfaceFraction * scene.mesh_A.chordal_error);
  models_->B =
      build_model(scene.B, scene.mesh_B, delta_B, kOnSurfaceFraction * scene.mesh_B.chordal_error);
  models_->tree_A = box_tree(*models_->A);
  models_->tree_B = box_tree(*models_->B);
  Eigen::AlignedBox3d box_A;
  for (int i = 0; i < models_->A->num_vertices; ++i) box_A.extend(models_->A->vertices[i]);
  models_->centre_A = box_A.center();
  for (int i = 0; i < models_->A->num_vertices; ++i)
    models_->radius_A =
        std::max(models_->radius_A, (models_->A->vertices[i] - models_->centre_A).norm());
}

ContactContext::~ContactContext() = default;

bool ContactContext::overlapping_triangles(const Pose& X_BA,
                                           std::vector<std::pair<int, int>>& pairs,
                                           int max_pairs) const {
  // FCL's traversal (collisionRecurse with MeshCollisionTraversalNodeOBBRSS: depth-first, the
  // larger box split first, left child first; a leaf pair reported when the leaves' boxes
  // overlap and intersect_Triangle says so), with savings that change no verdict: only the
  // pruning of inner pairs differs, and it stays conservative (a pair of triangles that
  // intersect has a common point in every box above them, so no test used here separates
  // their ancestors), while each leaf pair gets FCL's own tests. Each of B's boxes is placed
  // in A's frame once per query instead of once per box test; a pair of boxes whose
  // enclosing balls lie apart (by more than round-off) is skipped before any box test; inner
  // pairs are tested on the boxes' face axes only: nearly all pairs that reach the box test
  // overlap, and the nine edge-edge axes would cost more than the few pairs they separate;
  // and the two child pairs of a pair are tested together, in the two lanes of SSE2.
  Eigen::Matrix3d R;
  Eigen::Vector3d T;
  relative_transform(X_BA, R, T);
  const Model& A = *models_->A;
  const Model& B = *models_->B;
  PlacedBoxes placed(models_->tree_B, R, T);
  pairs.clear();
  thread_local std::vector<std::pair<int, int>> stack;
  const BoxTree &tree_A = models_->tree_A, &tree_B = models_->tree_B;
  return traverse(tree_A, tree_B, placed, 0, stack, [&](int a, int b) {
    if (!leaves_intersect(A, B, tree_A, tree_B, a, b, R, T)) return true;
    pairs.emplace_back(tree_A.nodes[a].primitive, tree_B.nodes[b].primitive);
    return static_cast<int>(pairs.size()) < max_pairs;
  });
}

bool ContactContext::overlapping_triangles_by_fcl(const Pose& X_BA,
                                                  std::vector<std::pair<int, int>>& pairs,
                                                  int max_pairs) const {
  fcl::CollisionRequestd request(static_cast<size_t>(max_pairs), false);
  fcl::CollisionResultd result;
  fcl::Transform3d tf_A = fcl::Transform3d::Identity();
  tf_A.linear() = X_BA.rotation();
  tf_A.translation() = X_BA.position;
  fcl::collide(models_->A.get(), tf_A, models_->B.get(), fcl::Transform3d::Identity(), request,
               result);
  pairs.clear();
  pairs.reserve(result.numContacts());
  for (size_t i = 0; i < result.numContacts(); ++i) {
    const fcl::Contactd& c = result.getContact(i);
    pairs.emplace_back(static_cast<int>(c.b1), static_cast<int>(c.b2));
  }
  return static_cast<int>(result.numContacts()) < max_pairs;
}

double ContactContext::displacement(const Pose& X, const Pose& Y) const {
  // A point p moves by (R_Y - R_X)(p - c) + (Y(c) - X(c)); |R_Y - R_X| = 2 sin(angle / 2), the
  // norm of the vector part of the relative unit quaternion.
  const Eigen::Quaterniond q = X.quaternion.normalized().conjugate() * Y.quaternion.normalized();
  const double centre = (Y.apply(models_->centre_A) - X.apply(models_->centre_A)).norm();
  return centre + 2 * q.vec().norm() * models_->radius_A;
}

NearbyTriangles ContactContext::nearby_triangles(const Pose& X_BA, double margin) const {
  NearbyTriangles out;
  out.X_BA = X_BA;
  out.margin = margin;
  Eigen::Matrix3d R;
  Eigen::Vector3d T;
  relative_transform(X_BA, R, T);
  const double grown = margin * (1 + kMarginRoundOff);
  PlacedBoxes placed(models_->tree_B, R, T);
  // FCL's order over node pairs, each pair tested by the looser ball and face-axis tests of
  // overlapping_triangles with the boxes grown by the margin (a box grown so holds every point
  // within the margin of it), leaf pairs included: the set keeps every leaf pair that may
  // overlap within the margin, in the order a full query meets them.
  std::vector<std::pair<int, int>> stack;
  out.complete =
      traverse(models_->tree_A, models_->tree_B, placed, grown, stack, [&](int a, int b) {
        if (out.leaves.size() >= kMaxNearbyLeaves) return false;
        out.leaves.emplace_back(a, b);
        return true;
      });
  if (!out.complete) out.leaves.clear();
  return out;
}

NearbyTriangles ContactContext::nearby_triangles(const Pose& X_BA, double margin,
                                                 const NearbyTriangles& wide) const {
  if (!wide.complete || displacement(wide.X_BA, X_BA) + margin > wide.margin)
    return nearby_triangles(X_BA, margin);
  NearbyTriangles out;
  out.X_BA = X_BA;
  out.margin = margin;
  Eigen::Matrix3d R;
  Eigen::Vector3d T;
  relative_transform(X_BA, R, T);
  const double grown = margin * (1 + kMarginRoundOff);
  for (const auto& [a, b] : wide.leaves)
    if (overlap_within(R, T, models_->A->getBV(a).bv.obb, models_->B->getBV(b).bv.obb, grown))
      out.leaves.emplace_back(a, b);
  return out;
}

NearbyTriangles ContactContext::nearby_triangles_between(const Pose& X, const Pose& Y,
                                                         double growth,
                                                         const NearbyTriangles* wide) const {
  Pose mid;
  mid.position = 0.5 * (X.position + Y.position);
  mid.quaternion = X.quaternion.slerp(0.5, Y.quaternion);
  const double margin = growth * std::max(displacement(mid, X), displacement(mid, Y));
  return wide ? nearby_triangles(mid, margin, *wide) : nearby_triangles(mid, margin);
}

const NearbyTriangles* BracketTriangles::update(const Pose& lo, const Pose& hi) {
  // Gathering tries for one bisection: each failed one costs about two full queries.
  constexpr int kMaxTries = 3;
  const int step = step_++;
  if (have_) {
    near_ = context_.nearby_triangles_between(lo, hi, growth_, &near_);
  } else {
    if (step < next_try_ || tries_ >= kMaxTries) return nullptr;
    ++tries_;
    next_try_ = step + 2;
    near_ = context_.nearby_triangles_between(lo, hi, growth_);
  }
  have_ = near_.complete;
  return have_ ? &near_ : nullptr;
}

bool ContactContext::overlapping_triangles_near(const Pose& X_BA, const NearbyTriangles& near,
                                                std::vector<std::pair<int, int>>& pairs,
                                                int max_pairs) const {
  if (!near.complete || displacement(near.X_BA, X_BA) > near.margin) return false;
  Eigen::Matrix3d R;
  Eigen::Vector3d T;
  relative_transform(X_BA, R, T);
  const Model& A = *models_->A;
  const Model& B = *models_->B;
  pairs.clear();
  const BoxTree &tree_A = models_->tree_A, &tree_B = models_->tree_B;
  for (const auto& [a, b] : near.leaves) {
    if (!leaves_intersect(A, B, tree_A, tree_B, a, b, R, T)) continue;
    if (static_cast<int>(pairs.size()) >= max_pairs - 1) return false;
    pairs.emplace_back(tree_A.nodes[a].primitive, tree_B.nodes[b].primitive);
  }
  return true;
}

}  // namespace pcsg
