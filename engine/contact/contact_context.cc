#include "engine/contact/contact_context.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/math/geometry.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>
#include <stdexcept>

#include "engine/contact/element_geometry.h"

namespace pcsg {
namespace {

// A mesh vertex lies on a surface when within this fraction of the mesh's chordal error of it:
// vertices are projected onto their surfaces to solve accuracy (~1e-12 L), while a vertex
// inside a face is at least a fraction of a triangle (>> chordal error) from the face's edges.
constexpr double kOnSurfaceFraction = 1e-3;

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

// FCL's OBB overlap test (b2 placed in b1's frame by R, T) with b1 grown by `margin` on every
// side: a box grown so holds every point within `margin` of the box.
bool overlap_within(const Eigen::Matrix3d& R0, const Eigen::Vector3d& T0, const fcl::OBBd& b1,
                    const fcl::OBBd& b2, double margin) {
  const Eigen::Matrix3d R = b1.axis.transpose() * (R0 * b2.axis);
  const Eigen::Vector3d T = b1.axis.transpose() * (R0 * b2.To + T0 - b1.To);
  return !fcl::obbDisjoint(R, T, Eigen::Vector3d(b1.extent.array() + margin), b2.extent);
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
  models_->A = build_model(scene.A, scene.mesh_A, delta_A,
                           kOnSurfaceFraction * scene.mesh_A.chordal_error);
  models_->B = build_model(scene.B, scene.mesh_B, delta_B,
                           kOnSurfaceFraction * scene.mesh_B.chordal_error);
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
  const Model& A = *models_->A;
  const Model& B = *models_->B;
  // Depth-first over node pairs, splitting the larger box (as FCL does).
  std::vector<std::pair<int, int>> stack = {{0, 0}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const auto& na = A.getBV(a);
    const auto& nb = B.getBV(b);
    if (!overlap_within(R, T, na.bv.obb, nb.bv.obb, grown)) continue;
    if (na.isLeaf() && nb.isLeaf()) {
      if (out.leaves.size() >= kMaxNearbyLeaves) {
        out.complete = false;
        out.leaves.clear();
        return out;
      }
      out.leaves.emplace_back(a, b);
    } else if (nb.isLeaf() || (!na.isLeaf() && na.bv.size() > nb.bv.size())) {
      stack.emplace_back(na.rightChild(), b);
      stack.emplace_back(na.leftChild(), b);
    } else {
      stack.emplace_back(a, nb.rightChild());
      stack.emplace_back(a, nb.leftChild());
    }
  }
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
  for (const auto& [a, b] : near.leaves) {
    const auto& na = A.getBV(a);
    const auto& nb = B.getBV(b);
    // FCL's leaf test: the leaves' boxes, then the triangles.
    if (!fcl::overlap(R, T, na.bv, nb.bv)) continue;
    const fcl::Triangle& ta = A.tri_indices[na.primitiveId()];
    const fcl::Triangle& tb = B.tri_indices[nb.primitiveId()];
    if (!fcl::detail::Intersect<double>::intersect_Triangle(
            A.vertices[ta[0]], A.vertices[ta[1]], A.vertices[ta[2]], B.vertices[tb[0]],
            B.vertices[tb[1]], B.vertices[tb[2]], R, T))
      continue;
    if (static_cast<int>(pairs.size()) >= max_pairs - 1) return false;
    pairs.emplace_back(na.primitiveId(), nb.primitiveId());
  }
  return true;
}

}  // namespace pcsg
