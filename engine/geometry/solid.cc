#include "engine/geometry/solid.h"

#include <algorithm>
#include <limits>

#include "engine/geometry/edge_tracer.h"

namespace pcsg {
namespace {

// max over the surfaces other than skip1, skip2 of g / |grad g| at p.
double measure_excluding(const std::vector<Polynomial>& gs, const Eigen::Vector3d& p, int skip1,
                         int skip2) {
  double m = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(gs.size()); ++i) {
    if (i == skip1 || i == skip2) continue;
    double v = 0;
    Eigen::Vector3d grad;
    gs[i].evaluate(p, &v, &grad, nullptr);
    const double n = grad.norm();
    // where the gradient vanishes the first-order distance is 0 on the surface, else infinite
    m = std::max(m, n > 0 ? v / n : (v > 0 ? std::numeric_limits<double>::infinity()
                                           : v < 0 ? -std::numeric_limits<double>::infinity()
                                                   : 0.0));
  }
  return m;
}

}  // namespace

double Solid::inside_measure(const Eigen::Vector3d& p) const {
  return measure_excluding(surfaces, p, -1, -1);
}

int Solid::face_at(int surface, const Eigen::Vector3d& p, double tol) const {
  if (measure_excluding(surfaces, p, surface, -1) > tol) return -1;
  // the patches of one surface are disjoint: the nearest patch sample tells which holds p
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    if (faces[f].surface != surface) continue;
    if (best < 0 && faces[f].samples.empty()) best = f;
    for (const auto& q : faces[f].samples) {
      const double d = (q - p).squaredNorm();
      if (d < best_d) {
        best_d = d;
        best = f;
      }
    }
  }
  return best;
}

int Solid::edge_at(int s1, int s2, const Eigen::Vector3d& p, double tol) const {
  if (measure_excluding(surfaces, p, s1, s2) > tol) return -1;
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    const Edge& E = edges[e];
    if (!((E.surface1 == s1 && E.surface2 == s2) || (E.surface1 == s2 && E.surface2 == s1)))
      continue;
    const double d = distance_to_samples(E.samples, E.closed, p);
    if (d < best_d) {
      best_d = d;
      best = e;
    }
  }
  return best;
}

const std::string& Solid::element_name(ElementId id) const {
  switch (id.kind) {
    case ElementKind::Face: return faces.at(id.index).name;
    case ElementKind::Edge: return edges.at(id.index).name;
    case ElementKind::Vertex: break;
  }
  return vertices.at(id.index).name;
}

std::vector<ElementId> Solid::adjacent(ElementId id) const {
  std::vector<ElementId> out;
  auto add = [&](ElementKind kind, const std::vector<int>& indices) {
    for (int i : indices) out.push_back({kind, i});
  };
  switch (id.kind) {
    case ElementKind::Face:
      add(ElementKind::Edge, faces.at(id.index).edges);
      add(ElementKind::Vertex, faces.at(id.index).vertices);
      break;
    case ElementKind::Edge: {
      const Edge& e = edges.at(id.index);
      add(ElementKind::Face, {e.face1, e.face2});
      add(ElementKind::Vertex, e.vertices);
      break;
    }
    case ElementKind::Vertex:
      add(ElementKind::Edge, vertices.at(id.index).edges);
      add(ElementKind::Face, vertices.at(id.index).faces);
      break;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

ElementId Solid::find(const std::string& element_name) const {
  for (int i = 0; i < static_cast<int>(faces.size()); ++i)
    if (faces[i].name == element_name) return {ElementKind::Face, i};
  for (int i = 0; i < static_cast<int>(edges.size()); ++i)
    if (edges[i].name == element_name) return {ElementKind::Edge, i};
  for (int i = 0; i < static_cast<int>(vertices.size()); ++i)
    if (vertices[i].name == element_name) return {ElementKind::Vertex, i};
  return {ElementKind::Face, -1};
}

}  // namespace pcsg
