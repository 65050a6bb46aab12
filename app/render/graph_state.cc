#include "app/render/graph_state.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/core/error.h"

namespace pcsg::app {
namespace {

using nlohmann::json;

Eigen::Vector3d vector3(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() ||
      !j[2].is_number()) {
    throw Error(where + ": expected [x, y, z], got " + j.dump());
  }
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

ElementId element(const Solid& solid, const json& name, const std::string& where) {
  if (!name.is_string()) throw Error(where + ": expected an element name, got " + name.dump());
  const ElementId id = solid.find(name.get<std::string>());
  if (id.index < 0) {
    throw Error(where + ": object " + solid.name + " has no element '" + name.get<std::string>() +
                "' (was the graph generated from this scene?)");
  }
  return id;
}

// The paper's notation from the "cf" array when the file has no "cf_text".
std::string cf_text_of(const json& cf) {
  std::string text = "{";
  for (const json& e : cf) {
    if (text.size() > 1) text += ", ";
    if (e.is_string()) {
      text += e.get<std::string>();
    } else {
      text += "(" + e.value("a", std::string("?")) + "-" + e.value("b", std::string("?")) + ", " +
              std::to_string(e.value("count", 1)) + ")";
    }
  }
  return text + "}";
}

}  // namespace

GraphStateView read_graph_state(const std::string& dir, int state, const SceneGeometry& scene) {
  const std::string path = (std::filesystem::path(dir) / "graph.json").string();
  std::ifstream in(path);
  if (!in) throw Error("cannot read '" + path + "' (run `pcsg generate` with -o " + dir + ")");
  json root;
  try {
    root = json::parse(in);
  } catch (const json::parse_error& e) {
    throw Error(path + ": not valid JSON: " + e.what());
  }
  if (!root.contains("states") || !root["states"].is_array()) {
    throw Error(path + ": no \"states\" array");
  }

  const json* found = nullptr;
  std::string ids;
  const json& states = root["states"];
  for (std::size_t i = 0; i < states.size(); ++i) {
    const int id = states[i].value("id", static_cast<int>(i));  // the index when ids are absent
    ids += (ids.empty() ? "" : ", ") + std::to_string(id);
    if (id == state) found = &states[i];
  }
  if (found == nullptr) {
    throw UsageError("--state " + std::to_string(state) + ": " + path + " has states " +
                     (ids.empty() ? "none" : ids));
  }
  const json& s = *found;
  const std::string where = path + ", state " + std::to_string(state);

  GraphStateView view;
  view.id = state;
  if (!s.contains("pose") || !s["pose"].is_object()) throw Error(where + ": no \"pose\"");
  view.pose.position = vector3(s["pose"].value("position", json()), where + ", pose.position");
  const json& q = s["pose"].value("quaternion", json());
  if (!q.is_array() || q.size() != 4) {
    throw Error(where + ": pose.quaternion: expected [w, x, y, z], got " + q.dump());
  }
  Eigen::Quaterniond quat(q[0].get<double>(), q[1].get<double>(), q[2].get<double>(),
                          q[3].get<double>());
  if (!(quat.norm() > 0)) throw Error(where + ": pose.quaternion is zero");
  view.pose.quaternion = quat.normalized();

  if (s.contains("cf_text") && s["cf_text"].is_string()) {
    view.cf_text = s["cf_text"].get<std::string>();
  } else if (s.contains("cf") && s["cf"].is_array()) {
    view.cf_text = cf_text_of(s["cf"]);
  }

  for (const json& c : s.value("contacts", json::array())) {
    const std::string cw = where + ", contact " + c.dump();
    PointContact pc;
    pc.a = element(scene.A, c.value("a", json()), cw);
    pc.b = element(scene.B, c.value("b", json()), cw);
    const auto type = parse_ptc_type(c.value("type", std::string()));
    if (!type) throw Error(cw + ": unknown contact type");
    pc.type = *type;
    pc.point_B = vector3(c.value("point", json()), cw + ", point");
    const json& n = c.value("normal", json());
    if (!n.is_null()) pc.normal_B = vector3(n, cw + ", normal");
    pc.gap = c.value("gap", 0.0);
    view.contacts.push_back(pc);
  }
  return view;
}

}  // namespace pcsg::app
