// pcsg render SCENE [--pose P | --graph DIR --state N] [--size WxH] [--camera "az el zoom"]
//                   [--normals] [--no-labels] -o FILE.png
// Draws the two objects as the paper's figures do (transparent, edges as solid lines, every
// face and edge labelled): apart by default (Fig. 5a, 7a), at a pose with its exact contacts
// marked, or at a state of a generated graph. Penetrating poses show the colliding elements in
// the warning colour.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "app/command.h"
#include "app/render/graph_state.h"
#include "engine/contact/contact_formation.h"
#include "engine/core/error.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"
#include "render/scene_renderer.h"

namespace pcsg::app {
namespace {

// Largest image side accepted: far above any figure, well below llvmpipe's 16384 limit and
// the memory of a 4x multisampled target (8192^2 * 4 samples * 8 bytes = 2 GB).
constexpr int kMaxImageSide = 8192;

struct Args {
  std::string scene, pose, graph, size = "1280x960", camera, out;
  int state = -1;
  bool normals = false, no_labels = false;
};

void parse_size(const std::string& text, int* w, int* h) {
  char x = 0;
  std::string rest;
  std::istringstream in(text);
  if (!(in >> *w >> x >> *h) || (x != 'x' && x != 'X') || (in >> rest) || *w < 1 || *h < 1 ||
      *w > kMaxImageSide || *h > kMaxImageSide) {
    throw UsageError("--size \"" + text + "\": expected WIDTHxHEIGHT, each 1.." +
                     std::to_string(kMaxImageSide) + ", e.g. 1280x960");
  }
}

void run(const Args& a) {
  // command-line values first, so that mistakes are reported before the scene is built
  render::FrameRequest f;
  parse_size(a.size, &f.width, &f.height);
  if (!a.camera.empty()) f.camera = render::parse_camera(a.camera);
  if (!a.pose.empty() && !a.graph.empty()) throw UsageError("give --pose or --graph, not both");
  if (!a.graph.empty() && a.state < 0) throw UsageError("--graph needs --state N (N >= 0)");
  if (a.graph.empty() && a.state >= 0) throw UsageError("--state needs --graph DIR");
  std::optional<Pose> pose;
  if (!a.pose.empty()) pose = parse_pose(a.pose);

  const SceneGeometry scene = build_scene_geometry(load_scene_file(a.scene));
  f.title = scene.spec.name.empty() ? a.scene : scene.spec.name;
  f.show_normals = a.normals;
  f.show_labels = !a.no_labels;
  if (pose) {
    const ContactReport report = detect_contacts(scene, *pose);
    f.X_BA = *pose;
    f.contacts = report.contacts;
    f.subtitle = ContactFormation::of(report.contacts).str(scene);
    if (report.contacts.empty()) f.subtitle += "  (no contact)";
    // a collision: its elements in the warning colour, each pair named once
    std::string pairs;
    for (const Penetration& p : report.penetrations) {
      const render::SceneElement ea{render::Object::A, p.a}, eb{render::Object::B, p.b};
      if (std::find(f.highlighted.begin(), f.highlighted.end(), ea) == f.highlighted.end() ||
          std::find(f.highlighted.begin(), f.highlighted.end(), eb) == f.highlighted.end()) {
        pairs += (pairs.empty() ? "" : ", ") + element_pair_name(scene, p.a, p.b);
      }
      f.highlighted.push_back(ea);
      f.highlighted.push_back(eb);
    }
    if (!pairs.empty()) f.subtitle += "   penetrating: " + pairs;
  } else if (!a.graph.empty()) {
    const GraphStateView state = read_graph_state(a.graph, a.state, scene);
    f.X_BA = state.pose;
    f.contacts = state.contacts;
    f.subtitle = "state " + std::to_string(state.id) + ": " + state.cf_text;
  } else {
    f.subtitle = "objects apart";
  }

  render::SceneRenderer renderer(scene);
  const render::Image image = renderer.render(f);
  render::write_png(image, a.out);
  std::printf("wrote %s (%dx%d)\n", a.out.c_str(), image.width, image.height);
}

void setup(CLI::App& cli) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = cli.add_subcommand(
      "render", "Draw the objects (apart, at a pose, or at a graph state) to a PNG");
  cmd->add_option("scene", args->scene, "Scene file (YAML)")->required();
  cmd->add_option("--pose", args->pose,
                  "Pose of A in B's frame, \"x y z qw qx qy qz\"; its contacts are marked");
  cmd->add_option("--graph", args->graph, "Folder with graph.json from `pcsg generate`");
  cmd->add_option("--state", args->state, "Id of the state of --graph to draw");
  cmd->add_option("--size", args->size, "Image size WIDTHxHEIGHT (default 1280x960)");
  cmd->add_option("--camera", args->camera,
                  "\"azimuth elevation zoom\" in degrees, degrees, factor (default \"-60 20 1\")");
  cmd->add_flag("--normals", args->normals, "Draw the contact normals");
  cmd->add_flag("--no-labels", args->no_labels, "Leave out the element labels");
  cmd->add_option("-o,--out", args->out, "Output PNG file")->required();
  cmd->callback([args] { run(*args); });
}

}  // namespace

PCSG_REGISTER_COMMAND(40, setup);

}  // namespace pcsg::app
