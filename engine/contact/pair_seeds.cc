#include "engine/contact/pair_seeds.h"

#include <algorithm>

#include "engine/contact/contact_classification.h"

namespace pcsg {
namespace {

// Solves attempted per pair: the paper's pairs form at most a few contacts (Section V's p),
// and a dozen separated starts cover each basin with room to spare.
constexpr int kStarts = 12;

// Points of an element in its solid's frame: a face's mesh vertices (ascending), an edge's
// exact samples, a vertex's point.
std::vector<Eigen::Vector3d> samples_of(const Solid& solid, const SolidMesh& mesh,
                                        const MeshIndex& index, ElementId id) {
  std::vector<Eigen::Vector3d> out;
  if (id.kind == ElementKind::Vertex) {
    out.push_back(solid.vertices[id.index].point);
  } else if (id.kind == ElementKind::Edge) {
    for (const CurveSample& s : solid.edges[id.index].samples) out.push_back(s.point);
  } else {
    const std::vector<int>& vertices = index.face_vertices[id.index];
    out.reserve(vertices.size());
    for (int v : vertices) out.push_back(mesh.positions[v]);
  }
  return out;
}

struct Start {
  Eigen::Vector3d p_A, p_B;
  double estimate;
};

// The foot of y on the face of surface g, to first order, and the signed distance estimate.
std::pair<Eigen::Vector3d, double> first_order_foot(const Polynomial& g, const Eigen::Vector3d& y) {
  double v;
  Eigen::Vector3d grad;
  g.evaluate(y, &v, &grad, nullptr);
  const double n = grad.norm();
  if (n == 0) return {y, INFINITY};
  return {y - (v / n) * (grad / n), v / n};
}

}  // namespace

std::vector<PointContact> pair_local_minima(const ContactContext& context, const Pose& X_BA,
                                            ElementId a, ElementId b, PtcType type) {
  const SceneGeometry& scene = context.scene();
  const std::vector<Eigen::Vector3d> SA = samples_of(scene.A, scene.mesh_A, context.index_A(), a);
  const std::vector<Eigen::Vector3d> SB = samples_of(scene.B, scene.mesh_B, context.index_B(), b);
  std::vector<Start> starts;
  if (b.kind == ElementKind::Face) {
    // A's samples against B's face surface.
    const Polynomial& g = scene.B.surfaces[scene.B.faces[b.index].surface];
    for (const Eigen::Vector3d& x : SA) {
      const auto [foot, d] = first_order_foot(g, X_BA.apply(x));
      starts.push_back({x, foot, d});
    }
  } else if (a.kind == ElementKind::Face) {
    // B's samples against A's face surface, in A's frame.
    const Polynomial& g = scene.A.surfaces[scene.A.faces[a.index].surface];
    for (const Eigen::Vector3d& y : SB) {
      const auto [foot, d] = first_order_foot(g, X_BA.apply_inverse(y));
      starts.push_back({foot, y, d});
    }
  } else {
    // Curves and points: every sample pair.
    for (const Eigen::Vector3d& x : SA)
      for (const Eigen::Vector3d& y : SB) starts.push_back({x, y, (X_BA.apply(x) - y).norm()});
  }
  // By increasing estimate. The sort moves (estimate, index) pairs rather than the 56-byte
  // starts: std::sort's moves follow from its comparisons alone, which see the same estimates
  // in the same places, so the order, ties included, is the one sorting the starts gives.
  struct Ranked {
    double estimate;
    int index;
  };
  std::vector<Ranked> ranked(starts.size());
  for (size_t k = 0; k < starts.size(); ++k) ranked[k] = {starts[k].estimate, static_cast<int>(k)};
  std::sort(ranked.begin(), ranked.end(),
            [](const Ranked& s, const Ranked& t) { return s.estimate < t.estimate; });

  const double separation = scene.tol.seed_separation;
  std::vector<const Start*> chosen;
  for (const Ranked& r : ranked) {
    const Start& s = starts[r.index];
    if (static_cast<int>(chosen.size()) >= kStarts) break;
    bool near = false;
    for (const Start* c : chosen)
      near = near || ((c->p_B - s.p_B).norm() < separation &&
                      (c->p_A - s.p_A).norm() < separation);
    if (!near) chosen.push_back(&s);
  }

  // Only local minima: a saddle of the pair's distance (e.g. between two contacts of one pair)
  // is never a contact, so it must not stand in for one.
  std::vector<PointContact> out;
  for (const Start* s : chosen) {
    const PairSolution sol = solve_pair_problem(scene, X_BA, a, b, type, s->p_A, s->p_B);
    if (!sol.converged || sol.k <= 0 || !is_local_minimum(scene, X_BA, sol.contact)) continue;
    bool dup = false;
    for (const PointContact& c : out)
      dup = dup || (c.point_B - sol.contact.point_B).norm() <= scene.tol.distinct_points;
    if (!dup) out.push_back(sol.contact);
  }
  std::sort(out.begin(), out.end(),
            [](const PointContact& x, const PointContact& y) { return x.gap < y.gap; });
  return out;
}

std::vector<PointContact> PairMinimaMemo::get(const ContactContext& context, const Pose& X_BA,
                                              ElementId a, ElementId b, PtcType type) {
  Key key{};
  const std::array<std::uint64_t, 7> pose = pose_bits(X_BA);
  std::copy(pose.begin(), pose.end(), key.begin());
  key[7] = (static_cast<std::uint64_t>(a.kind) << 32) | static_cast<std::uint32_t>(a.index);
  key[8] = (static_cast<std::uint64_t>(b.kind) << 32) | static_cast<std::uint32_t>(b.index);
  key[9] = static_cast<std::uint64_t>(type);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = answers_.find(key);
    if (it != answers_.end()) return it->second;
  }
  std::vector<PointContact> minima = pair_local_minima(context, X_BA, a, b, type);
  std::lock_guard<std::mutex> lock(mutex_);
  ++computed_;
  answers_.emplace(key, minima);
  return minima;
}

size_t PairMinimaMemo::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return answers_.size();
}

size_t PairMinimaMemo::computed() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return computed_;
}

}  // namespace pcsg
