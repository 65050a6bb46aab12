// Scene files (YAML) -> SceneSpec. Every rejection is a SceneError pointing at the offending
// place of the file (1-based line:column), naming the value and what was expected.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "engine/poly/parser.h"
#include "engine/scene/scene.h"

namespace pcsg {
namespace {

using Entries = std::vector<std::pair<YAML::Node, YAML::Node>>;

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

// "[a, b, c]" of a list of scalars, as written.
std::string flow(const YAML::Node& list) {
  std::vector<std::string> items;
  for (const YAML::Node& v : list) items.push_back(v.IsScalar() ? v.Scalar() : "...");
  return "[" + join(items) + "]";
}

// How a node looks, for "got ..." in messages.
std::string describe(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  return "a map";
}

class SceneReader {
 public:
  SceneReader(const std::string& text, const std::string& path) : text_(text), path_(path) {}

  SceneSpec read() {
    YAML::Node root;
    try {
      root = YAML::Load(text_);
    } catch (const YAML::Exception& e) {
      throw SceneError(at(e.mark), "YAML syntax error: " + e.msg);
    }
    const std::string expected = "expected a map with keys name, objects and seeds";
    if (!root.IsDefined() || root.IsNull())
      throw SceneError({path_, 1, 1}, "the scene is empty; " + expected);
    if (!root.IsMap()) fail(root, expected + " at the top level, got " + describe(root));

    SceneSpec scene;
    scene.path = path_;
    scene.name = std::filesystem::path(path_).stem().string();
    // absent keys stay empty (a default YAML::Node would claim to be defined)
    std::optional<YAML::Node> objects_key, objects;
    for (const auto& [key, value] : entries(root, "the top level", {"name", "objects", "seeds"})) {
      const std::string k = key.Scalar();
      if (k == "name") {
        if (!value.IsScalar()) fail(value, "name: expected a text, got " + describe(value));
        scene.name = value.Scalar();
      } else if (k == "objects") {
        objects_key = key;
        objects = value;
      } else {
        read_seeds(value, key, scene);
      }
    }
    if (!objects) fail(root, "missing 'objects' (a map with the two objects A and B)");
    read_objects(*objects, *objects_key, scene);
    return scene;
  }

 private:
  // --- locations -------------------------------------------------------------------------------
  SourceLocation at(const YAML::Mark& m) const {
    if (m.is_null()) return {path_, 0, 0};
    return {path_, m.line + 1, m.column + 1};
  }
  SourceLocation at(const YAML::Node& n) const { return at(n.Mark()); }

  // Where byte `offset` of a scalar's value lies in the file. yaml-cpp marks a scalar at its
  // first raw character (the opening quote of a quoted one), so walk the raw text from there,
  // stepping over the quote and over escapes ("\t", "''") that are shorter once decoded.
  SourceLocation at_offset(const YAML::Node& scalar, std::size_t offset) const {
    const YAML::Mark m = scalar.Mark();
    SourceLocation loc = at(m);
    if (m.is_null() || m.pos < 0 || static_cast<std::size_t>(m.pos) >= text_.size()) return loc;
    std::size_t i = m.pos;
    char quote = 0;
    if (text_[i] == '"' || text_[i] == '\'') {
      quote = text_[i++];
      ++loc.column;
    } else if (text_[i] == '|' || text_[i] == '>') {
      return loc;  // block scalar: the text starts on a later line; keep the marker's place
    }
    for (std::size_t decoded = 0; decoded < offset && i < text_.size(); ++decoded) {
      if (text_[i] == '\n') {  // a folded line break decodes to one space
        ++i, ++loc.line, loc.column = 1;
        while (i < text_.size() && (text_[i] == ' ' || text_[i] == '\t')) ++i, ++loc.column;
        continue;
      }
      std::size_t raw = 1;
      if (quote == '"' && text_[i] == '\\' && i + 1 < text_.size()) {
        const char e = text_[i + 1];
        raw = e == 'x' ? 4 : e == 'u' ? 6 : e == 'U' ? 10 : 2;
      } else if (quote == '\'' && text_[i] == '\'') {
        raw = 2;
      }
      i += raw;
      loc.column += static_cast<int>(raw);
    }
    return loc;
  }

  [[noreturn]] void fail(const YAML::Node& n, const std::string& what) const {
    throw SceneError(at(n), what);
  }

  // The entries of a map in file order. Keys must be non-empty texts; with `allowed` given,
  // keys are checked against it and may not repeat (yaml-cpp keeps repeated keys).
  Entries entries(const YAML::Node& map, const std::string& where,
                  const std::vector<std::string>& allowed = {}) const {
    Entries out;
    std::set<std::string> seen;
    for (auto it = map.begin(); it != map.end(); ++it) {
      const YAML::Node key = it->first, value = it->second;
      if (!key.IsScalar() || key.Scalar().empty())
        fail(key, "in " + where + ": expected a name as key, got " + describe(key));
      const std::string& k = key.Scalar();
      if (!allowed.empty()) {
        if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
          fail(key, "unknown key '" + k + "' in " + where + "; expected " + join(allowed));
        if (!seen.insert(k).second) fail(key, "duplicate key '" + k + "' in " + where);
      }
      out.emplace_back(key, value);
    }
    return out;
  }

  // --- objects -----------------------------------------------------------------------------------
  void read_objects(const YAML::Node& objects, const YAML::Node& key, SceneSpec& scene) const {
    if (!objects.IsMap())
      fail(objects.IsNull() ? key : objects,
           "objects: expected a map with the two objects A and B, got " + describe(objects));
    bool have[2] = {false, false};
    for (const auto& [name, value] : entries(objects, "objects", {"A", "B"})) {
      const bool is_a = name.Scalar() == "A";
      (is_a ? scene.A : scene.B) = read_object(name, value);
      have[is_a ? 0 : 1] = true;
    }
    for (int k = 0; k < 2; ++k)
      if (!have[k])
        fail(key, std::string("objects: missing object '") + "AB"[k] +
                      "'; expected both A and B");
  }

  ObjectSpec read_object(const YAML::Node& key, const YAML::Node& value) const {
    ObjectSpec obj;
    obj.name = key.Scalar();
    obj.where = at(key);
    const std::string ctx = "object " + obj.name;
    const std::string no_faces =
        ctx + " has no faces; expected 'faces:' with at least one inequality";
    if (value.IsNull()) fail(key, no_faces);
    if (!value.IsMap()) fail(value, ctx + ": expected a map with faces, edges, vertices, got " +
                                        describe(value));
    std::optional<YAML::Node> faces, edges, vertices, faces_key;
    for (const auto& [k, v] : entries(value, ctx, {"faces", "edges", "vertices"})) {
      if (k.Scalar() == "faces") faces = v, faces_key = k;
      if (k.Scalar() == "edges") edges = v;
      if (k.Scalar() == "vertices") vertices = v;
    }
    if (!faces) fail(key, no_faces);
    if (faces->IsNull() || (faces->IsMap() && faces->size() == 0)) fail(*faces_key, no_faces);

    // one namespace per object: faces, edges and vertices are all referred to by name
    std::map<std::string, SourceLocation> names;
    auto claim = [&](const YAML::Node& name, const char* kind) {
      const auto [it, fresh] = names.emplace(name.Scalar(), at(name));
      if (!fresh)
        fail(name, "duplicate name '" + name.Scalar() + "' in " + ctx + " (" + kind +
                       "); it is already used at " + it->second.str());
    };
    for (const auto& [name, text] : entries(as_map(*faces, ctx + " faces"), ctx + " faces")) {
      claim(name, "face");
      obj.faces.push_back(read_face(name, text, ctx));
    }
    std::vector<std::string> face_names;
    for (const FaceSpec& f : obj.faces) face_names.push_back(f.name);

    if (edges && !edges->IsNull())
      for (const auto& [name, list] : entries(as_map(*edges, ctx + " edges"), ctx + " edges")) {
        claim(name, "edge");
        const auto faces_of = face_list(name, list, face_names, ctx, "edge", 2, 2);
        obj.edges.push_back({name.Scalar(), faces_of[0], faces_of[1], at(name)});
      }
    if (vertices && !vertices->IsNull())
      for (const auto& [name, list] :
           entries(as_map(*vertices, ctx + " vertices"), ctx + " vertices")) {
        claim(name, "vertex");
        obj.vertices.push_back(
            {name.Scalar(), face_list(name, list, face_names, ctx, "vertex", 3, 0), at(name)});
      }
    return obj;
  }

  const YAML::Node& as_map(const YAML::Node& n, const std::string& what) const {
    if (!n.IsMap()) fail(n, what + ": expected a map of names, got " + describe(n));
    return n;
  }

  FaceSpec read_face(const YAML::Node& name, const YAML::Node& value,
                     const std::string& ctx) const {
    const std::string face = "face '" + name.Scalar() + "' of " + ctx;
    if (!value.IsScalar())
      fail(value.IsNull() ? name : value,
           face + ": expected an inequality such as \"x^2 + y^2 + z^2 <= 1\", got " +
               describe(value));
    FaceSpec f;
    f.name = name.Scalar();
    f.text = value.Scalar();
    f.where = at_offset(value, 0);
    try {
      f.g = parse_inequality(f.text, [&](std::size_t off) { return at_offset(value, off); }).g;
    } catch (const SceneError& e) {
      // name the face too: the same typo may sit in several faces
      const std::string what = e.what(), prefix = e.where().str() + ": ";
      throw SceneError(e.where(), face + ": " + what.substr(what.rfind(prefix, 0) == 0
                                                                ? prefix.size()
                                                                : 0));
    }
    // strictly curved objects only (paper, Section I): no constants, no planes
    const int d = f.g.degree();
    if (d <= 0)
      throw SceneError(f.where, face + ": \"" + f.text + "\" is constant (degree " +
                                    std::to_string(std::max(d, 0)) +
                                    "); expected a curved surface of degree 2 to " +
                                    std::to_string(Polynomial::kMaxDegree));
    if (d == 1)
      throw SceneError(f.where, face + ": \"" + f.text +
                                    "\" is a plane: not strictly curved; expected degree 2 to " +
                                    std::to_string(Polynomial::kMaxDegree));
    return f;
  }

  // The face names of an edge ([f1, f2]) or a vertex ([f1, f2, f3, ...]): known and distinct.
  std::vector<std::string> face_list(const YAML::Node& name, const YAML::Node& list,
                                     const std::vector<std::string>& faces,
                                     const std::string& ctx, const std::string& kind,
                                     std::size_t min_count, std::size_t max_count) const {
    const std::string what = kind + " '" + name.Scalar() + "' of " + ctx;
    const std::string shape = max_count == 2 ? "a list of two face names [f1, f2]"
                                             : "a list of three or more face names [f1, f2, f3]";
    if (!list.IsSequence() || list.size() < min_count || (max_count && list.size() > max_count))
      fail(list.IsNull() ? name : list, what + ": expected " + shape + ", got " +
                                            (list.IsSequence() ? std::to_string(list.size()) +
                                                                     " entries"
                                                               : describe(list)));
    std::vector<std::string> out;
    for (const YAML::Node& f : list) {
      if (!f.IsScalar()) fail(f, what + ": expected a face name, got " + describe(f));
      const std::string& s = f.Scalar();
      if (std::find(faces.begin(), faces.end(), s) == faces.end())
        fail(f, what + " names unknown face '" + s + "'; the faces of " + ctx + " are " +
                    join(faces));
      if (std::find(out.begin(), out.end(), s) != out.end())
        fail(f, what + " names face '" + s + "' twice; expected different faces");
      out.push_back(s);
    }
    return out;
  }

  // --- seeds ---------------------------------------------------------------------------------------
  void read_seeds(const YAML::Node& seeds, const YAML::Node& key, SceneSpec& scene) const {
    const std::string expected =
        "seeds: expected 'auto' or a list of {position: [x, y, z], quaternion: [w, x, y, z]}";
    if (seeds.IsScalar() && seeds.Scalar() == "auto") {
      scene.auto_seeds = true;
      return;
    }
    if (!seeds.IsSequence() || seeds.size() == 0)
      fail(seeds.IsNull() ? key : seeds, expected + ", got " +
                                             (seeds.IsSequence() ? "an empty list"
                                                                 : describe(seeds)));
    scene.auto_seeds = false;
    int index = 0;
    for (const YAML::Node& s : seeds) {
      const std::string what = "seed " + std::to_string(++index);
      if (!s.IsMap()) fail(s, what + ": expected {position: [x, y, z], quaternion: [w, x, y, z]}"
                                     ", got " + describe(s));
      std::optional<YAML::Node> position, quaternion;
      for (const auto& [k, v] : entries(s, what, {"position", "quaternion"}))
        (k.Scalar() == "position" ? position : quaternion) = v;
      if (!position) fail(s, what + ": missing 'position: [x, y, z]'");
      if (!quaternion) fail(s, what + ": missing 'quaternion: [w, x, y, z]'");
      const std::vector<double> p = numbers(*position, what + " position", "[x, y, z]", 3);
      const std::vector<double> q = numbers(*quaternion, what + " quaternion", "[w, x, y, z]", 4);
      const Eigen::Quaterniond quat(q[0], q[1], q[2], q[3]);
      // below the smallest normal double the quaternion cannot be normalised reliably
      if (quat.norm() < std::numeric_limits<double>::min())
        fail(*quaternion, what + " quaternion " + flow(*quaternion) +
                              " is zero; expected a non-zero rotation [w, x, y, z]");
      SeedSpec seed;
      seed.pose.position = Eigen::Vector3d(p[0], p[1], p[2]);
      seed.pose.quaternion = quat;
      seed.pose = seed.pose.canonical();
      seed.where = at(s);
      scene.seeds.push_back(seed);
    }
  }

  std::vector<double> numbers(const YAML::Node& list, const std::string& what,
                              const std::string& shape, std::size_t count) const {
    if (!list.IsSequence() || list.size() != count)
      fail(list, what + ": expected " + std::to_string(count) + " numbers " + shape + ", got " +
                     (list.IsSequence() ? std::to_string(list.size()) + " entries"
                                        : describe(list)));
    std::vector<double> out;
    for (std::size_t k = 0; k < count; ++k) {
      const YAML::Node v = list[k];
      double x = std::numeric_limits<double>::quiet_NaN();
      if (v.IsScalar()) {
        try {
          x = v.as<double>();
        } catch (const YAML::Exception&) {
        }
      }
      if (!std::isfinite(x))
        fail(v, what + "[" + std::to_string(k) + "]: expected a finite number, got " +
                    describe(v));
      out.push_back(x);
    }
    return out;
  }

  const std::string& text_;
  const std::string& path_;
};

}  // namespace

SceneSpec load_scene_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw SceneError({path, 0, 0}, "cannot open the scene file (missing or unreadable); "
                                   "expected a YAML scene such as scenes/example1.yaml");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path);
}

SceneSpec parse_scene(const std::string& yaml_text, const std::string& path) {
  return SceneReader(yaml_text, path).read();
}

}  // namespace pcsg
