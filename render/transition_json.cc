#include "render/transition_json.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/core/error.h"

namespace pcsg::render {

namespace {

using nlohmann::ordered_json;

ordered_json vec(const Eigen::Vector3d& v) { return ordered_json::array({v.x(), v.y(), v.z()}); }

Eigen::Vector3d vec(const ordered_json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

ordered_json contacts_json(const std::vector<PointContact>& cs, const SceneGeometry& scene) {
  ordered_json arr = ordered_json::array();
  for (const PointContact& c : cs)
    arr.push_back({{"a", scene.A.element_name(c.a)},
                   {"b", scene.B.element_name(c.b)},
                   {"type", ptc_type_name(c.type)},
                   {"point", vec(c.point_B)},
                   {"normal", vec(c.normal_B)}});
  return arr;
}

ElementId element(const Solid& solid, const std::string& name) {
  const ElementId id = solid.find(name);
  if (id.index < 0) throw Error("object " + solid.name + " has no element '" + name + "'");
  return id;
}

std::vector<PointContact> contacts_of(const ordered_json& arr, const SceneGeometry& scene) {
  std::vector<PointContact> out;
  for (const ordered_json& j : arr) {
    PointContact c;
    c.a = element(scene.A, j.at("a").get<std::string>());
    c.b = element(scene.B, j.at("b").get<std::string>());
    const auto type = parse_ptc_type(j.at("type").get<std::string>());
    if (!type) throw Error("unknown contact type " + j.at("type").dump());
    c.type = *type;
    c.point_B = vec(j.at("point"));
    c.normal_B = vec(j.at("normal"));
    out.push_back(c);
  }
  return out;
}

ContactRole role_of(const std::string& name) {
  for (ContactRole r : {ContactRole::Kept, ContactRole::Changing, ContactRole::Reached,
                        ContactRole::Undecided, ContactRole::Other})
    if (name == contact_role_name(r)) return r;
  throw Error("unknown contact role '" + name + "'");
}

}  // namespace

std::string transition_to_json(const TransitionRecord& r, const SceneGeometry& scene) {
  ordered_json j;
  j["from"] = r.info.from;
  j["from_cf"] = r.info.from_cf;
  j["target_cf"] = r.info.target_cf;
  j["motion"] = r.info.motion;
  j["feasible"] = r.info.feasible;
  j["to"] = r.info.to;
  j["reason"] = r.info.reason;
  j["steps"] = r.info.steps;
  j["start"] = contacts_json(r.start, scene);
  ordered_json frames = ordered_json::array();
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    const MotionFrame& f = r.frames[k];
    const Pose p = f.pose.canonical();
    ordered_json roles = ordered_json::array();
    if (k < r.roles.size())
      for (ContactRole role : r.roles[k]) roles.push_back(contact_role_name(role));
    ordered_json ca = ordered_json::array(), cb = ordered_json::array();
    for (const ElementId& e : f.collided_a)
      if (e.index >= 0) ca.push_back(scene.A.element_name(e));
    for (const ElementId& e : f.collided_b)
      if (e.index >= 0) cb.push_back(scene.B.element_name(e));
    frames.push_back({{"step", f.step},
                      {"phase", f.phase},
                      {"pose",
                       {{"position", vec(p.position)},
                        {"quaternion", ordered_json::array({p.quaternion.w(), p.quaternion.x(),
                                                            p.quaternion.y(), p.quaternion.z()})}}},
                      {"contacts", contacts_json(f.contacts, scene)},
                      {"roles", roles},
                      {"collided_a", ca},
                      {"collided_b", cb}});
  }
  j["frames"] = frames;
  return j.dump(1) + "\n";
}

TransitionRecord read_transition_json(const std::string& path, const SceneGeometry& scene) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read '" + path + "'");
  TransitionRecord r;
  try {
    const ordered_json j = ordered_json::parse(in);
    r.info.from = j.at("from").get<int>();
    r.info.from_cf = j.at("from_cf").get<std::string>();
    r.info.target_cf = j.at("target_cf").get<std::string>();
    r.info.motion = j.at("motion").get<std::string>();
    r.info.feasible = j.at("feasible").get<bool>();
    r.info.to = j.at("to").get<int>();
    r.info.reason = j.at("reason").get<std::string>();
    r.info.steps = j.at("steps").get<int>();
    r.start = contacts_of(j.at("start"), scene);
    for (const ordered_json& fj : j.at("frames")) {
      MotionFrame f;
      f.step = fj.at("step").get<int>();
      f.phase = fj.at("phase").get<std::string>();
      f.pose.position = vec(fj.at("pose").at("position"));
      const ordered_json& q = fj.at("pose").at("quaternion");
      f.pose.quaternion = Eigen::Quaterniond(q.at(0).get<double>(), q.at(1).get<double>(),
                                             q.at(2).get<double>(), q.at(3).get<double>())
                              .normalized();
      f.contacts = contacts_of(fj.at("contacts"), scene);
      for (const auto& e : fj.at("collided_a")) f.collided_a.push_back(element(scene.A, e.get<std::string>()));
      for (const auto& e : fj.at("collided_b")) f.collided_b.push_back(element(scene.B, e.get<std::string>()));
      std::vector<ContactRole> roles;
      for (const auto& role : fj.at("roles")) roles.push_back(role_of(role.get<std::string>()));
      r.frames.push_back(std::move(f));
      r.roles.push_back(std::move(roles));
    }
  } catch (const nlohmann::json::exception& e) {
    throw Error(path + ": not a transition record: " + e.what());
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  return r;
}

}  // namespace pcsg::render
