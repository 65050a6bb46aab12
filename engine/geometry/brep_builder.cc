#include "engine/geometry/brep_builder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "engine/geometry/edge_tracer.h"
#include "engine/geometry/element_extents.h"
#include "engine/geometry/element_naming.h"
#include "engine/geometry/solid_extent.h"
#include "engine/geometry/surface.h"
#include "engine/geometry/surface_patch.h"
#include "engine/poly/parser.h"

namespace pcsg {
namespace {

// A clipped component smaller than this fraction of a discovery cell's area is a numerical
// sliver where a surface merely touches the solid (tangent along a curve or at a point), not a
// face: real faces found on the grid span at least part of a cell.
constexpr double kMinComponentArea = 1e-6;

std::string point_str(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return buf;
}

std::string num_str(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string sine_str(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", s);
  return buf;
}

struct Builder {
  const ObjectSpec& object;
  Solid& solid;
  Tolerances tol;
  double h = 0;  // discovery grid spacing
  std::vector<SurfacePatch> patches;

  int n() const { return static_cast<int>(solid.surfaces.size()); }
  const FaceSpec& spec(int i) const { return object.faces[i]; }

  // Faces: the connected components of each surface's clipped patch, largest first.
  void discover_faces(const Eigen::AlignedBox3d& box) {
    patches.resize(n());
    for (int i = 0; i < n(); ++i) {
      if (solid.surfaces[i].degree() <= 0) continue;
      patches[i] = surface_patch(solid.surfaces, i, box, h, tol);
      const SurfacePatch& P = patches[i];
      int count = 0;
      const std::vector<int> label = triangle_components(P, &count);
      std::vector<double> area(count, 0.0);
      std::vector<std::vector<int>> verts(count);
      std::vector<int> vertex_label(P.positions.size(), -1);
      for (std::size_t t = 0; t < P.triangles.size(); ++t) {
        const auto& T = P.triangles[t];
        const int c = label[t];
        area[c] += 0.5 * (P.positions[T[1]] - P.positions[T[0]])
                             .cross(P.positions[T[2]] - P.positions[T[0]])
                             .norm();
        for (int q = 0; q < 3; ++q)
          if (vertex_label[T[q]] != c) {
            if (vertex_label[T[q]] < 0) verts[c].push_back(T[q]);
            vertex_label[T[q]] = c;
          }
      }
      std::vector<int> order;
      for (int c = 0; c < count; ++c)
        if (area[c] > kMinComponentArea * h * h) order.push_back(c);
      std::stable_sort(order.begin(), order.end(),
                       [&](int a, int b) { return area[a] > area[b]; });
      for (int k = 0; k < static_cast<int>(order.size()); ++k) {
        Face f;
        f.name = k == 0 ? spec(i).name : spec(i).name + "#" + std::to_string(k + 1);
        f.surface = i;
        std::sort(verts[order[k]].begin(), verts[order[k]].end());
        for (int v : verts[order[k]]) f.samples.push_back(P.positions[v]);
        solid.faces.push_back(std::move(f));
      }
    }
  }

  [[noreturn]] void tangential(int a, int b, const Eigen::Vector3d& p) const {
    throw SceneError(spec(a).where,
                     "faces " + spec(a).name + " and " + spec(b).name +
                         " meet tangentially at " + point_str(p) +
                         " (sine of the angle between their normals " +
                         sine_str(normals_sine(solid.surfaces[a], solid.surfaces[b], p)) +
                         ", below " + sine_str(tol.tangential_sine) +
                         "): no proper edge forms there; pcsg needs faces that cross at an "
                         "angle");
  }

  // Edges: every component of each pair's curve inside the solid, traced from the patches'
  // cut points (each seeds a new component unless an earlier trace already passed by it).
  void trace_edges(std::vector<TracedCurve>* curves, std::vector<std::pair<int, int>>* pairs) {
    for (int a = 0; a < n(); ++a)
      for (int b = a + 1; b < n(); ++b) {
        std::vector<Eigen::Vector3d> seeds;
        for (int s : {a, b}) {
          const int other = s == a ? b : a;
          const SurfacePatch& P = patches[s];
          for (std::size_t v = 0; v < P.positions.size(); ++v)
            if (P.on[v] == (std::uint64_t{1} << other)) seeds.push_back(P.positions[v]);
        }
        std::vector<TracedCurve> found;
        for (const auto& s0 : seeds) {
          bool covered = false;
          for (const auto& c : found)
            covered = covered ||
                      distance_to_samples(c.samples, c.closed, s0) < 0.5 * tol.edge_sample_step;
          if (covered) continue;
          const Projection pr = project_onto_curve(solid.surfaces[a], solid.surfaces[b], s0, tol);
          if (normals_sine(solid.surfaces[a], solid.surfaces[b], pr.point) < tol.tangential_sine)
            tangential(a, b, pr.point);
          if (!pr.converged || solid.inside_measure(pr.point) > tol.on_boundary) continue;
          bool again = false;
          for (const auto& c : found)
            again = again || distance_to_samples(c.samples, c.closed, pr.point) <
                                 0.5 * tol.edge_sample_step;
          if (again) continue;
          TracedCurve curve;
          std::string reason;
          Eigen::Vector3d tangential_at;
          if (!trace_curve(solid.surfaces, a, b, pr.point, tol, &curve, &reason,
                           &tangential_at)) {
            if (tangential_at.allFinite()) tangential(a, b, tangential_at);
            throw SceneError(spec(a).where, "the edge where faces " + spec(a).name + " and " +
                                                spec(b).name + " meet: " + reason);
          }
          found.push_back(std::move(curve));
        }
        for (auto& c : found) {
          curves->push_back(std::move(c));
          pairs->emplace_back(a, b);
        }
      }
  }

  // The vertex at p (merging ends closer than tol.distinct_points).
  int vertex_at(const Eigen::Vector3d& p) {
    for (int v = 0; v < static_cast<int>(solid.vertices.size()); ++v)
      if ((solid.vertices[v].point - p).norm() <= tol.distinct_points) return v;
    Vertex V;
    V.point = p;
    for (int i = 0; i < n(); ++i)
      if (solid.surfaces[i].degree() > 0 &&
          surface_distance(solid.surfaces[i], p) <= tol.on_boundary)
        V.surfaces.push_back(i);
    solid.vertices.push_back(V);
    return static_cast<int>(solid.vertices.size()) - 1;
  }

  void make_edges(const std::vector<TracedCurve>& curves,
                  const std::vector<std::pair<int, int>>& pairs) {
    for (std::size_t k = 0; k < curves.size(); ++k) {
      const TracedCurve& c = curves[k];
      Edge e;
      e.surface1 = pairs[k].first;
      e.surface2 = pairs[k].second;
      e.samples = c.samples;
      e.closed = c.closed;
      e.length = c.length;
      const Eigen::Vector3d mid = c.samples[c.samples.size() / 2].point;
      e.face1 = solid.face_at(e.surface1, mid, tol.on_boundary);
      e.face2 = solid.face_at(e.surface2, mid, tol.on_boundary);
      if (e.face1 < 0 || e.face2 < 0)
        throw SceneError(spec(e.surface1).where,
                         "the edge where faces " + spec(e.surface1).name + " and " +
                             spec(e.surface2).name + " meet near " + point_str(mid) +
                             " bounds no face of one of them (a face thinner than the "
                             "discovery grid?)");
      if (!c.closed) {
        e.vertices.push_back(vertex_at(c.samples.front().point));
        const int last = vertex_at(c.samples.back().point);
        if (last != e.vertices.front()) e.vertices.push_back(last);
      }
      e.bbox = edge_bbox(solid.surfaces, e, tol);
      solid.edges.push_back(std::move(e));
    }
  }
};

}  // namespace

Solid build_solid(const ObjectSpec& object, std::vector<std::string>* warnings) {
  if (static_cast<int>(object.faces.size()) > kMaxSurfaces)
    throw SceneError(object.where, "object " + object.name + " has " +
                                       std::to_string(object.faces.size()) +
                                       " inequalities; at most " +
                                       std::to_string(kMaxSurfaces) + " are supported");
  Solid solid;
  solid.name = object.name;
  for (const auto& f : object.faces) {
    solid.surfaces.push_back(f.g);
    solid.surface_names.push_back(f.name);
  }
  const SolidExtent extent = solid_extent(object);
  const Eigen::AlignedBox3d& box = extent.box;
  // Every surface expanded about a point near the solid (Polynomial::origin): a solid far
  // from its frame's origin is then evaluated without cancellation. Measured on Example 1's
  // B moved 1.32e5 (1e4 L) away (scenes/stress/example1_far_rotated.yaml): g near the surface
  // had round-off ~4e-6 from terms of 1.7e10 (a distance error ~5e-7, 4e-8 L, against
  // solve_residual 1e-12 L), and edge tracing failed; about the new origin g's terms are ~16.
  // The origin is the box's centre rounded to a multiple of its diagonal, so a solid around
  // its frame's origin keeps origin zero and its coefficients exactly. A face with its text
  // is parsed again about the origin (parse_inequality_about): recentring the coefficients
  // expanded about zero cannot restore what their rounding lost, ~1e-6 in g's constant for
  // the needle moved 1.3e5 away (scenes/stress/needle_far_rotated.yaml), which moves its
  // surface by ~1e-7 (1e-8 L, against solve_residual 1e-12 L).
  {
    const double D = box.diagonal().norm();
    const Eigen::Vector3d o = (box.center() / D).array().round().matrix() * D;
    // Only a text that is g's source (parsed about zero it gives g exactly; a scene rewritten
    // by moved_scene states its coefficients to 10 digits) is parsed again.
    if (!o.isZero())
      for (size_t i = 0; i < solid.surfaces.size(); ++i) {
        const FaceSpec& f = object.faces[i];
        Polynomial& g = solid.surfaces[i];
        const auto locate = locate_from(f.where);
        bool source = false;
        try {
          source = !f.text.empty() && g.origin().isZero() &&
                   parse_inequality(f.text, locate).g.coeffs() == g.coeffs();
        } catch (const SceneError&) {
          // a spec built in code whose text is only a label: keep its g
        }
        g = source ? parse_inequality_about(f.text, o, locate).g : g.recentred(o);
      }
  }
  // the object's own tolerances: its B-rep does not depend on the other object
  Builder b{object, solid, Tolerances::for_length_scale(box.diagonal().norm()), 0.0, {}};
  // the grid: discovery_cells along the box's longest side, finer for a thin solid (a
  // needle 1:1:100, scenes/stress/needle_in_dish.yaml, fell between the grid's vertices)
  b.h = std::min(box.sizes().maxCoeff() / b.tol.discovery_cells,
                 extent.thickness / b.tol.discovery_cells_across);
  {
    double cells = 1;
    for (int a = 0; a < 3; ++a) cells *= std::ceil(box.sizes()[a] / b.h) + 1;
    if (cells > b.tol.discovery_max_cells)
      throw SceneError(object.where,
                       "object " + object.name + " is too thin to discover: " +
                           num_str(extent.thickness) + " thick in a box of " +
                           num_str(box.sizes().x()) + " x " + num_str(box.sizes().y()) +
                           " x " + num_str(box.sizes().z()) + ", it needs a grid of " +
                           num_str(cells) + " cells (at most " +
                           num_str(b.tol.discovery_max_cells) + ")");
  }
  b.discover_faces(box);
  if (solid.faces.empty())
    throw SceneError(object.where, "object " + object.name +
                                       " is empty: its inequalities leave no face on a grid "
                                       "of cells " + num_str(b.h) + " wide across its box (it "
                                       "has no interior, or a part thinner than a cell)");
  std::vector<TracedCurve> curves;
  std::vector<std::pair<int, int>> pairs;
  b.trace_edges(&curves, &pairs);
  b.make_edges(curves, pairs);
  name_and_link_elements(solid, object);
  // extremes are searched within three coarse cells of the grid's samples (a thin solid's
  // finer grid still misses its tapering ends: a needle's last 0.065 of 2.5)
  compute_face_extents(solid, 3 * box.sizes().maxCoeff() / b.tol.discovery_cells, b.tol);
  for (const auto& f : solid.faces) solid.bbox.extend(f.bbox);
  // inequalities that shape nothing: harmless, but likely not what the author meant
  for (int i = 0; i < b.n(); ++i) {
    bool has_face = false;
    for (const auto& f : solid.faces) has_face = has_face || f.surface == i;
    if (!has_face && warnings)
      warnings->push_back(object.faces[i].where.str() + ": object " + object.name +
                          ": inequality " + object.faces[i].name + " ('" +
                          object.faces[i].text +
                          "') contributes no face: the other inequalities already imply it, "
                          "or it touches the solid only along a curve or at a point");
  }
  return solid;
}

}  // namespace pcsg
