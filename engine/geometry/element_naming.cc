#include "engine/geometry/element_naming.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

namespace pcsg {
namespace {

bool lex_less(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

int surface_index(const ObjectSpec& object, const std::string& name, const SourceLocation& where,
                  const std::string& what) {
  for (int i = 0; i < static_cast<int>(object.faces.size()); ++i)
    if (object.faces[i].name == name) return i;
  throw SceneError(where, what + " names face '" + name + "', which object " + object.name +
                              " does not have");
}

// The k-th (0-based) component's name: "base", "base#2", ...
std::string numbered(const std::string& base, int k) {
  return k == 0 ? base : base + "#" + std::to_string(k + 1);
}

}  // namespace

void name_and_link_elements(Solid& solid, const ObjectSpec& object) {
  const auto& names = solid.surface_names;
  // vertices: by their surfaces, then by position
  std::vector<int> vorder(solid.vertices.size());
  std::iota(vorder.begin(), vorder.end(), 0);
  std::stable_sort(vorder.begin(), vorder.end(), [&](int a, int b) {
    const Vertex &A = solid.vertices[a], &B = solid.vertices[b];
    if (A.surfaces != B.surfaces) return A.surfaces < B.surfaces;
    return lex_less(A.point, B.point);
  });
  std::vector<int> vnew(vorder.size());
  std::vector<Vertex> vertices;
  for (int k = 0; k < static_cast<int>(vorder.size()); ++k) {
    vnew[vorder[k]] = k;
    vertices.push_back(solid.vertices[vorder[k]]);
  }
  solid.vertices = std::move(vertices);
  for (auto& e : solid.edges)
    for (int& v : e.vertices) v = vnew[v];
  // edges: by their surfaces, then longest first, then by their lowest sample
  auto lowest = [](const Edge& e) {
    Eigen::Vector3d m = e.samples.front().point;
    for (const auto& s : e.samples)
      if (lex_less(s.point, m)) m = s.point;
    return m;
  };
  std::stable_sort(solid.edges.begin(), solid.edges.end(), [&](const Edge& a, const Edge& b) {
    if (a.surface1 != b.surface1) return a.surface1 < b.surface1;
    if (a.surface2 != b.surface2) return a.surface2 < b.surface2;
    if (a.length != b.length) return a.length > b.length;
    return lex_less(lowest(a), lowest(b));
  });

  // adjacency
  for (auto& f : solid.faces) f.edges.clear(), f.vertices.clear();
  for (auto& v : solid.vertices) v.edges.clear(), v.faces.clear();
  for (int e = 0; e < static_cast<int>(solid.edges.size()); ++e) {
    const Edge& E = solid.edges[e];
    for (int f : {E.face1, E.face2}) solid.faces[f].edges.push_back(e);
    for (int v : E.vertices) {
      solid.vertices[v].edges.push_back(e);
      for (int f : {E.face1, E.face2}) solid.vertices[v].faces.push_back(f);
    }
  }
  for (int v = 0; v < static_cast<int>(solid.vertices.size()); ++v) {
    auto& V = solid.vertices[v];
    std::sort(V.faces.begin(), V.faces.end());
    V.faces.erase(std::unique(V.faces.begin(), V.faces.end()), V.faces.end());
    std::sort(V.edges.begin(), V.edges.end());
    V.edges.erase(std::unique(V.edges.begin(), V.edges.end()), V.edges.end());
    for (int f : V.faces) solid.faces[f].vertices.push_back(v);
  }
  for (auto& f : solid.faces) {
    std::sort(f.edges.begin(), f.edges.end());
    f.edges.erase(std::unique(f.edges.begin(), f.edges.end()), f.edges.end());
    std::sort(f.vertices.begin(), f.vertices.end());
    f.vertices.erase(std::unique(f.vertices.begin(), f.vertices.end()), f.vertices.end());
  }

  // names: the scene's first, generated ones for the rest
  std::map<std::pair<int, int>, int> edge_count;
  std::map<std::pair<int, int>, const EdgeNameSpec*> edge_spec;
  for (const auto& spec : object.edges) {
    const int a = surface_index(object, spec.face1, spec.where, "edge '" + spec.name + "'");
    const int b = surface_index(object, spec.face2, spec.where, "edge '" + spec.name + "'");
    const auto key = std::minmax(a, b);
    bool found = false;
    for (const auto& e : solid.edges) found = found || (e.surface1 == key.first && e.surface2 == key.second);
    if (!found)
      throw SceneError(spec.where, "edge '" + spec.name + "': faces " + spec.face1 + " and " +
                                       spec.face2 + " never meet on the boundary of object " +
                                       object.name);
    edge_spec[key] = &spec;
  }
  for (auto& e : solid.edges) {
    const std::pair<int, int> key{e.surface1, e.surface2};
    const int k = edge_count[key]++;
    const auto it = edge_spec.find(key);
    e.name = numbered(it != edge_spec.end()
                          ? it->second->name
                          : "e_" + names[e.surface1] + "_" + names[e.surface2],
                      k);
  }
  std::map<std::vector<int>, int> vertex_count;
  std::vector<bool> named(solid.vertices.size(), false);
  for (const auto& spec : object.vertices) {
    std::set<int> want;
    for (const auto& f : spec.faces)
      want.insert(surface_index(object, f, spec.where, "vertex '" + spec.name + "'"));
    int k = 0;
    for (int v = 0; v < static_cast<int>(solid.vertices.size()); ++v) {
      const auto& s = solid.vertices[v].surfaces;
      if (named[v] || !std::includes(s.begin(), s.end(), want.begin(), want.end())) continue;
      solid.vertices[v].name = numbered(spec.name, k++);
      named[v] = true;
    }
    if (k == 0) {
      std::string list;
      for (const auto& f : spec.faces) list += (list.empty() ? "" : ", ") + f;
      throw SceneError(spec.where, "vertex '" + spec.name + "': faces " + list +
                                       " never meet at a point of object " + object.name);
    }
  }
  for (int v = 0; v < static_cast<int>(solid.vertices.size()); ++v) {
    if (named[v]) continue;
    auto& V = solid.vertices[v];
    std::string base = "v";
    for (int s : V.surfaces) base += "_" + names[s];
    V.name = numbered(base, vertex_count[V.surfaces]++);
  }
}

}  // namespace pcsg
