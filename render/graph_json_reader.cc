#include "render/graph_json_reader.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/core/error.h"

namespace pcsg::render {

namespace {

using nlohmann::json;

// Every lookup names where it is in the file, so that a bad entry is found at once.
struct Reader {
  std::string path;
  const SceneGeometry& scene;

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw Error(path + ": " + where + ": " + what);
  }
  const json& field(const json& j, const char* key, const std::string& where) const {
    if (!j.is_object() || !j.contains(key)) fail(where, std::string("no \"") + key + "\"");
    return j.at(key);
  }
  double number(const json& j, const std::string& where) const {
    if (!j.is_number()) fail(where, "expected a number, got " + j.dump());
    return j.get<double>();
  }
  int integer(const json& j, const char* key, const std::string& where) const {
    const json& v = field(j, key, where);
    if (!v.is_number_integer()) fail(where, std::string(key) + ": expected an integer, got " + v.dump());
    return v.get<int>();
  }
  std::string text(const json& j, const char* key, const std::string& where) const {
    const json& v = field(j, key, where);
    if (!v.is_string()) fail(where, std::string(key) + ": expected a string, got " + v.dump());
    return v.get<std::string>();
  }
  Eigen::Vector3d vector3(const json& j, const std::string& where) const {
    if (!j.is_array() || j.size() != 3) fail(where, "expected [x, y, z], got " + j.dump());
    return {number(j[0], where), number(j[1], where), number(j[2], where)};
  }
  ElementId element(const Solid& solid, const json& j, const char* key,
                    const std::string& where) const {
    const std::string name = text(j, key, where);
    const ElementId id = solid.find(name);
    if (id.index < 0)
      fail(where, "object " + solid.name + " has no element '" + name +
                      "' (was the graph generated from this scene?)");
    return id;
  }
  PtcType type(const json& j, const std::string& where) const {
    const std::string name = text(j, "type", where);
    const auto t = parse_ptc_type(name);
    if (!t) fail(where, "unknown contact type '" + name + "'");
    return *t;
  }
  ContactFormation cf(const json& arr, const std::string& where) const {
    if (!arr.is_array()) fail(where, "\"cf\": expected an array, got " + arr.dump());
    ContactFormation f;
    for (const json& e : arr)
      f.add(element(scene.A, e, "a", where), element(scene.B, e, "b", where), type(e, where),
            integer(e, "count", where));
    return f;
  }
  Pose pose(const json& j, const std::string& where) const {
    Pose p;
    p.position = vector3(field(j, "position", where), where + ", position");
    const json& q = field(j, "quaternion", where);
    if (!q.is_array() || q.size() != 4) fail(where, "quaternion: expected [w, x, y, z]");
    const Eigen::Quaterniond quat(number(q[0], where), number(q[1], where), number(q[2], where),
                                  number(q[3], where));
    if (!(quat.norm() > 0)) fail(where, "quaternion is zero");
    p.quaternion = quat.normalized();
    return p;
  }
  PointContact contact(const json& j, const std::string& where) const {
    PointContact c;
    c.a = element(scene.A, j, "a", where);
    c.b = element(scene.B, j, "b", where);
    c.type = type(j, where);
    c.point_B = vector3(field(j, "point", where), where + ", point");
    if (j.contains("normal")) c.normal_B = vector3(j["normal"], where + ", normal");
    if (j.contains("gap")) c.gap = number(j["gap"], where + ", gap");
    return c;
  }
};

}  // namespace

StateGraph read_graph_json(const std::string& path, const SceneGeometry& scene) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read '" + path + "' (write one with `pcsg generate -o DIR`)");
  json root;
  try {
    root = json::parse(in);
  } catch (const json::parse_error& e) {
    throw Error(path + ": not valid JSON: " + e.what());
  }
  const Reader r{path, scene};
  StateGraph g;
  g.scene = root.value("scene", scene.spec.name);
  const json& states = r.field(root, "states", "top level");
  if (!states.is_array()) r.fail("top level", "\"states\" is not an array");
  for (std::size_t i = 0; i < states.size(); ++i) {
    const json& s = states[i];
    const std::string where = "states[" + std::to_string(i) + "]";
    State st;
    st.id = r.integer(s, "id", where);
    if (st.id != static_cast<int>(i)) r.fail(where, "id " + std::to_string(st.id) + " is not its index");
    st.cf = r.cf(r.field(s, "cf", where), where);
    st.pose = r.pose(r.field(s, "pose", where), where + ", pose");
    for (const json& c : s.value("contacts", json::array())) st.contacts.push_back(r.contact(c, where));
    st.seed = s.value("seed", false);
    st.depth = s.value("depth", 0);
    g.states.push_back(std::move(st));
  }
  const int n = static_cast<int>(g.states.size());
  for (const json& l : root.value("links", json::array())) {
    const std::string where = "link " + l.dump();
    Link link;
    link.from = r.integer(l, "from", where);
    link.to = r.integer(l, "to", where);
    if (link.from < 0 || link.from >= n || link.to < 0 || link.to >= n)
      r.fail(where, "names a state outside 0.." + std::to_string(n - 1));
    const std::string kind = r.text(l, "kind", where);
    if (kind != "LN" && kind != "GN") r.fail(where, "kind must be LN or GN");
    link.kind = kind == "LN" ? LinkKind::LN : LinkKind::GN;
    link.motion = l.value("motion", std::string());
    g.links.push_back(link);
  }
  const json& candidates = root.value("candidates", json::array());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const json& c = candidates[i];
    const std::string where = "candidates[" + std::to_string(i) + "]";
    Candidate cand;
    cand.from = r.integer(c, "from", where);
    if (cand.from < 0 || cand.from >= n) r.fail(where, "from names no state");
    cand.cf = r.cf(r.field(c, "cf", where), where);
    cand.feasible = c.value("feasible", false);
    cand.to = c.value("to", -1);
    cand.motion = c.value("motion", std::string());
    cand.reason = c.value("reason", std::string());
    cand.steps = c.value("steps", 0);
    cand.attempts = c.value("attempts", 0);
    cand.crossing = c.value("crossing", std::string());
    if (c.contains("start")) cand.start = r.pose(c["start"], where + ", start");
    if (c.contains("run")) {
      const json& run = r.field(c, "run", where);
      cand.run.start = r.integer(run, "start", where + ", run");
      cand.run.plan = r.integer(run, "plan", where + ", run");
      cand.run.variant = r.integer(run, "variant", where + ", run");
    }
    g.candidates.push_back(std::move(cand));
  }
  if (root.contains("stats") && root["stats"].is_object())
    g.stats.seconds = root["stats"].value("seconds", 0.0);
  return g;
}

}  // namespace pcsg::render
