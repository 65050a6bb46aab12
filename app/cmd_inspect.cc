// pcsg inspect SCENE [--json]: the boundary elements the kernel derived from a scene's
// inequalities (faces, edges, vertices with their adjacency, extents, areas and lengths), the
// meshes' sizes and the validation findings. Text for a person; --json for programs.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/command.h"
#include "engine/geometry/curve_fit.h"
#include "engine/geometry/mesh_measures.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"

namespace pcsg::app {
namespace {

using nlohmann::json;

// An edge counts as a circle when its samples lie within this fraction of its radius from the
// fitted circle: exact samples of a true circle deviate by round-off (~1e-12), while any other
// curve of the paper's kind deviates by far more than 1e-6.
constexpr double kCircleRelativeDeviation = 1e-6;

struct Args {
  std::string scene;
  bool json = false;
};

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json box_json(const Eigen::AlignedBox3d& b) {
  return {{"min", vec(b.min())}, {"max", vec(b.max())}};
}

std::vector<std::string> names(const Solid& s, ElementKind kind, const std::vector<int>& idx) {
  std::vector<std::string> out;
  for (int i : idx) out.push_back(s.element_name({kind, i}));
  return out;
}

json circle_json(const Edge& e) {
  const CircleFit c = fit_circle(e);
  if (!(c.radius > 0) || c.max_deviation > kCircleRelativeDeviation * c.radius) return nullptr;
  return {{"radius", c.radius}, {"centre", vec(c.centre)}, {"normal", vec(c.normal)},
          {"max_deviation", c.max_deviation}};
}

json solid_json(const Solid& s, const ObjectSpec& spec, const SolidMesh& mesh) {
  json faces = json::array(), edges = json::array(), vertices = json::array();
  for (const Face& f : s.faces)
    faces.push_back({{"name", f.name},
                     {"inequality", spec.faces[f.surface].text},
                     {"surface", s.surface_names[f.surface]},
                     {"area", f.area},
                     {"bbox", box_json(f.bbox)},
                     {"interior_point", vec(f.interior_point)},
                     {"max_curvature", f.max_curvature},
                     {"edges", names(s, ElementKind::Edge, f.edges)},
                     {"vertices", names(s, ElementKind::Vertex, f.vertices)}});
  for (const Edge& e : s.edges)
    edges.push_back({{"name", e.name},
                     {"faces", names(s, ElementKind::Face, {e.face1, e.face2})},
                     {"vertices", names(s, ElementKind::Vertex, e.vertices)},
                     {"closed", e.closed},
                     {"length", e.length},
                     {"samples", e.samples.size()},
                     {"bbox", box_json(e.bbox)},
                     {"circle", circle_json(e)}});
  for (const Vertex& v : s.vertices) {
    std::vector<std::string> surf;
    for (int i : v.surfaces) surf.push_back(s.surface_names[i]);
    vertices.push_back({{"name", v.name},
                        {"point", vec(v.point)},
                        {"surfaces", surf},
                        {"faces", names(s, ElementKind::Face, v.faces)},
                        {"edges", names(s, ElementKind::Edge, v.edges)}});
  }
  const MeshTopology topo = mesh_topology(mesh);
  return {{"bbox", box_json(s.bbox)},
          {"faces", faces},
          {"edges", edges},
          {"vertices", vertices},
          {"mesh",
           {{"triangles", mesh.triangles.size()},
            {"vertices", mesh.positions.size()},
            {"chordal_error", mesh.chordal_error},
            {"watertight", topo.watertight()},
            {"boundary_edges", topo.boundary_edges},
            {"nonmanifold_edges", topo.nonmanifold_edges},
            {"misoriented_edges", topo.misoriented_edges},
            {"volume", mesh_volume(mesh)}}}};
}

// Values below this print as 0 in the text output: round-off such as -4e-16 on a plane of
// symmetry says nothing to a reader. Set to the scene's contact tolerance (1e-9 L).
double text_zero = 0;

std::string fmt(const char* f, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, std::abs(a) < text_zero ? 0.0 : a);
  return buf;
}

std::string join(const json& list) {
  std::string s;
  for (const auto& x : list) s += (s.empty() ? "" : ", ") + x.get<std::string>();
  return s.empty() ? "-" : s;
}

std::string range(const json& box, int axis) {
  return "[" + fmt("%.6g", box["min"][axis].get<double>()) + ", " +
         fmt("%.6g", box["max"][axis].get<double>()) + "]";
}

std::string box_text(const json& box) {
  return "x " + range(box, 0) + "  y " + range(box, 1) + "  z " + range(box, 2);
}

std::string point_text(const json& p) {
  return "(" + fmt("%.6g", p[0].get<double>()) + ", " + fmt("%.6g", p[1].get<double>()) + ", " +
         fmt("%.6g", p[2].get<double>()) + ")";
}

void print_text(const json& r, double zero) {
  text_zero = zero;
  std::printf("scene    %s\n", r["scene"].get<std::string>().c_str());
  std::printf("file     %s\n", r["path"].get<std::string>().c_str());
  std::printf("length scale L = %.6g (larger bounding-box diagonal); built in %.1f ms\n",
              r["length_scale"].get<double>(), r["build_ms"].get<double>());
  for (const char* name : {"A", "B"}) {
    const json& o = r["objects"][name];
    std::printf("\nobject %s: %zu faces, %zu edges, %zu vertices\n", name, o["faces"].size(),
                o["edges"].size(), o["vertices"].size());
    std::printf("  bbox     %s\n", box_text(o["bbox"]).c_str());
    for (const auto& f : o["faces"]) {
      std::printf("  face %-8s %s\n", f["name"].get<std::string>().c_str(),
                  f["inequality"].get<std::string>().c_str());
      std::printf("           area %s   bbox %s\n", fmt("%.6g", f["area"].get<double>()).c_str(),
                  box_text(f["bbox"]).c_str());
      std::printf("           edges: %s   vertices: %s\n", join(f["edges"]).c_str(),
                  join(f["vertices"]).c_str());
    }
    for (const auto& e : o["edges"]) {
      std::printf("  edge %-8s between %s; %s, length %s\n",
                  e["name"].get<std::string>().c_str(), join(e["faces"]).c_str(),
                  e["closed"].get<bool>() ? "closed curve"
                                          : ("from vertex to vertex: " + join(e["vertices"])).c_str(),
                  fmt("%.6g", e["length"].get<double>()).c_str());
      if (!e["circle"].is_null())
        std::printf("           circle of radius %s, centre %s, normal %s\n",
                    fmt("%.6g", e["circle"]["radius"].get<double>()).c_str(),
                    point_text(e["circle"]["centre"]).c_str(),
                    point_text(e["circle"]["normal"]).c_str());
      std::printf("           bbox %s\n", box_text(e["bbox"]).c_str());
    }
    for (const auto& v : o["vertices"])
      std::printf("  vertex %-6s at %s on %s; edges: %s\n", v["name"].get<std::string>().c_str(),
                  point_text(v["point"]).c_str(), join(v["faces"]).c_str(),
                  join(v["edges"]).c_str());
    const json& m = o["mesh"];
    std::printf("  mesh     %zu triangles, %zu vertices, chordal error %.3g, %s\n",
                m["triangles"].get<std::size_t>(), m["vertices"].get<std::size_t>(),
                m["chordal_error"].get<double>(),
                m["watertight"].get<bool>() ? "watertight"
                                            : ("NOT watertight (" +
                                               std::to_string(m["boundary_edges"].get<int>()) +
                                               " boundary edges)")
                                                  .c_str());
  }
  std::printf("\nvalidation: %s\n", r["warnings"].empty() ? "ok, no warnings" : "ok, with warnings:");
  for (const auto& w : r["warnings"]) std::printf("  warning: %s\n", w.get<std::string>().c_str());
}

void run(const Args& a) {
  const SceneSpec spec = load_scene_file(a.scene);
  const auto t0 = std::chrono::steady_clock::now();
  const SceneGeometry g = build_scene_geometry(spec);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  json r = {{"scene", spec.name},
            {"path", spec.path},
            {"length_scale", g.tol.length_scale},
            {"build_ms", ms},
            {"objects",
             {{"A", solid_json(g.A, spec.A, g.mesh_A)}, {"B", solid_json(g.B, spec.B, g.mesh_B)}}},
            {"warnings", g.warnings}};
  if (a.json) {
    // the build time varies from run to run; machine-readable output stays reproducible
    r.erase("build_ms");
    std::printf("%s\n", r.dump(2).c_str());
  } else {
    print_text(r, g.tol.contact_gap);
  }
}

void setup(CLI::App& cli) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = cli.add_subcommand(
      "inspect", "Show the faces, edges and vertices derived from a scene, with validation");
  cmd->add_option("scene", args->scene, "Scene file (YAML)")->required();
  cmd->add_flag("--json", args->json, "Machine-readable output (JSON)");
  cmd->callback([args] { run(*args); });
}

}  // namespace

PCSG_REGISTER_COMMAND(10, setup);

}  // namespace pcsg::app
