// pcsg contacts SCENE --pose "x y z qw qx qy qz" [--snap CF] [--json]: the exact point
// contacts of A at a pose (paper Section II-B): the contact formation, each contact's pair,
// type, point, normal and gap, and any penetration. With --snap the pose is first projected
// onto the given CF's configurations (Section II-C) and the projected pose is printed.
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/command.h"
#include "engine/contact/contact_context.h"
#include "engine/contact/contact_formation.h"
#include "engine/core/error.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"

namespace pcsg::app {
namespace {

using nlohmann::json;

struct Args {
  std::string scene, pose, snap;
  bool json = false;
};

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json contact_json(const SceneGeometry& g, const PointContact& c) {
  json j = {{"pair", element_pair_name(g, c.a, c.b)},
            {"a", g.A.element_name(c.a)},
            {"b", g.B.element_name(c.b)},
            {"type", ptc_type_name(c.type)},
            {"point", vec(c.point_B)},
            {"normal", c.type == PtcType::VV ? json(nullptr) : vec(c.normal_B)},
            {"gap", c.gap},
            {"contact_plane", nullptr},
            {"contact_line", nullptr}};
  if (const auto p = contact_plane(c))
    j["contact_plane"] = {{"point", vec(p->point_B)}, {"normal", vec(p->normal_B)}};
  if (const auto l = contact_line(c))
    j["contact_line"] = {{"point", vec(l->point_B)}, {"direction", vec(l->direction_B)}};
  return j;
}

// Values below the scene's contact tolerance print as 0 in the text output: round-off such as
// -4e-16 on a plane of symmetry says nothing to a reader.
std::string num(double x, double zero) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", std::abs(x) < zero ? 0.0 : x);
  return buf;
}

std::string point_text(const json& p, double zero) {
  return "(" + num(p[0], zero) + ", " + num(p[1], zero) + ", " + num(p[2], zero) + ")";
}

void print_text(const json& r, double zero) {
  std::printf("scene    %s\n", r["scene"].get<std::string>().c_str());
  std::printf("pose     %s\n", r["pose"].get<std::string>().c_str());
  if (!r["snap"].is_null())
    std::printf("projected pose %s  (onto %s, %d iterations)\n",
                r["snap"]["pose"].get<std::string>().c_str(),
                r["snap"]["cf"].get<std::string>().c_str(), r["snap"]["iterations"].get<int>());
  std::printf("CF       %s\n", r["cf"].get<std::string>().c_str());
  std::printf("contacts %zu\n", r["contacts"].size());
  for (const auto& c : r["contacts"]) {
    std::printf("  %-10s %-9s point %s", c["pair"].get<std::string>().c_str(),
                c["type"].get<std::string>().c_str(), point_text(c["point"], zero).c_str());
    if (!c["normal"].is_null())
      std::printf("  normal %s", point_text(c["normal"], zero).c_str());
    std::printf("  gap %s\n", num(c["gap"], zero).c_str());
  }
  if (r["penetrations"].empty()) {
    std::printf("penetration: none\n");
    return;
  }
  for (const auto& p : r["penetrations"])
    std::printf("penetration: %s at %s, depth %s\n", p["pair"].get<std::string>().c_str(),
                point_text(p["point"], zero).c_str(), num(p["depth"], zero).c_str());
}

void run(const Args& a) {
  Pose X = parse_pose(a.pose);  // UsageError (exit 2) before the scene is built
  const SceneGeometry g = build_scene_geometry(load_scene_file(a.scene));
  const ContactContext context(g);
  json r = {{"scene", g.spec.name}, {"pose", X.str()}, {"snap", nullptr}};
  if (!a.snap.empty()) {
    const ContactFormation cf = ContactFormation::parse(a.snap, g);
    const ProjectionResult proj = project_onto_cf(context, X, cf);
    if (!proj.ok) throw Error("cannot snap onto " + cf.str(g) + ": " + proj.reason);
    X = proj.pose;
    r["snap"] = {{"cf", cf.str(g)},
                 {"pose", X.str()},
                 {"iterations", proj.iterations},
                 {"max_residual", proj.max_residual}};
  }
  const ContactReport rep = detect_contacts(context, X);
  r["cf"] = ContactFormation::of(rep.contacts).str(g);
  r["contacts"] = json::array();
  for (const PointContact& c : rep.contacts) r["contacts"].push_back(contact_json(g, c));
  r["penetrating"] = rep.penetrating();
  r["penetrations"] = json::array();
  for (const Penetration& p : rep.penetrations)
    r["penetrations"].push_back(
        {{"pair", element_pair_name(g, p.a, p.b)}, {"point", vec(p.point_B)}, {"depth", p.depth}});
  if (a.json)
    std::printf("%s\n", r.dump(2).c_str());
  else
    print_text(r, g.tol.contact_gap);
}

void setup(CLI::App& cli) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = cli.add_subcommand(
      "contacts", "Exact point contacts of A at a pose (optionally snapped onto a CF)");
  cmd->add_option("scene", args->scene, "Scene file (YAML)")->required();
  cmd->add_option("--pose", args->pose, "Pose of A in B's frame: \"x y z qw qx qy qz\"")
      ->required();
  cmd->add_option("--snap", args->snap,
                  "First project the pose onto this CF, e.g. \"{(fA-f1, 2)}\"");
  cmd->add_flag("--json", args->json, "Machine-readable output (JSON)");
  cmd->callback([args] { run(*args); });
}

}  // namespace

PCSG_REGISTER_COMMAND(20, setup);

}  // namespace pcsg::app
