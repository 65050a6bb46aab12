#pragma once
// Shared by the stress and metamorphic tests (scenes/stress/): generating a scene, comparing
// graphs by their states and adjacencies, checking witnesses and scene-file coefficients.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "engine/contact/contact.h"
#include "engine/contact/contact_classification.h"
#include "engine/generator/hypothesis.h"
#include "generator_test_support.h"

namespace pcsg::testing {

inline std::string stress_path(const std::string& name) {
  return std::string(PCSG_SOURCE_DIR) + "/scenes/stress/" + name;
}

struct Generated {
  SceneGeometry scene;
  StateGraph graph;
};

// Two threads: the graph does not depend on the count (generator.h), the run time does.
inline Generated generate(const SceneSpec& spec, GeneratorOptions opt) {
  Generated g{build_scene_geometry(spec), {}};
  opt.threads = 2;
  g.graph = generate_graph(g.scene, opt);
  return g;
}

// Without `search_upward` (the upward probes and projections) the graph is the seeds' LN
// graphs (paper Section III) alone.
inline Generated generate(const SceneSpec& spec, bool search_upward = true) {
  GeneratorOptions opt;
  opt.probe_upward = search_upward;
  opt.project_upward = search_upward;
  return generate(spec, opt);
}

// Example 1's graph, generated once per process: the tests that compare against it run in one
// process each group (tests/CMakeLists.txt, GROUPS).
inline const Generated& example1() {
  static const Generated g = generate(load_scene_file(scene_path("example1.yaml")));
  return g;
}

inline std::string adjacent_pair(const std::string& a, const std::string& b) {
  return a < b ? a + " -- " + b : b + " -- " + a;
}

// Which states are linked, as unordered CF pairs, sorted: the direction of an LN link between
// two states of equal cardinality depends on which one the BFS reached first, which is not
// what the stress tests are about (the metamorphic invariance tests compare directed links).
inline std::vector<std::string> adjacency(const StateGraph& g, const SceneGeometry& scene) {
  std::vector<std::string> out;
  for (const Link& l : g.links)
    out.push_back(adjacent_pair(g.states[l.from].cf.str(scene), g.states[l.to].cf.str(scene)));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

inline std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

// Every witness, re-checked by the exact contact computation, carries its state's CF and no
// penetration, and its contacts are exact to 1e-10 L (the generator's own witness check).
// Every link joins two states; an LN link never raises cardinality (Section II-D) and joins
// CFs an LN hypothesis joins, in either direction between states of one cardinality (Section
// III-A: some PtCs kept, some changed to neighbouring ones, some removed; hypothesise_ln with
// every kind of plan): the generator's motions only arrive
// at their hypotheses' CFs, so a link between other CFs came through a symmetry image read on
// another CF (Example 2 far and rotated until session 49: {(fA2-e1, 2)} -> {(fA1-e1, 1)}, the
// mirror image of a link from {(eA-e1, 1), (fA2-e1, 1)}, whose reflected witness read
// {(fA2-e1, 2)}).
inline void expect_witnesses_valid(const Generated& g) {
  for (const State& s : g.graph.states) {
    const ContactReport rep = detect_contacts(g.scene, s.pose);
    EXPECT_FALSE(rep.penetrating()) << "state " << s.id << " " << s.cf.str(g.scene);
    EXPECT_EQ(ContactFormation::of(rep.contacts).str(g.scene), s.cf.str(g.scene))
        << "state " << s.id;
    for (const PointContact& c : rep.contacts) {
      EXPECT_LE(std::abs(c.gap), 1e-10 * g.scene.tol.length_scale)
          << "state " << s.id << ": the witness's contacts are exact to 1e-10 of the size";
      // A point contact, not a curve of contact (is_ring_contact: the torus's ring states
      // until session 65).
      EXPECT_FALSE(is_ring_contact(g.scene, s.pose, c))
          << "state " << s.id << " " << s.cf.str(g.scene) << ": " << g.scene.A.element_name(c.a)
          << "-" << g.scene.B.element_name(c.b) << " touches along a curve";
    }
  }
  const int n = static_cast<int>(g.graph.states.size());
  for (const Link& l : g.graph.links) {
    ASSERT_TRUE(l.from >= 0 && l.from < n && l.to >= 0 && l.to < n) << l.from << " -> " << l.to;
    if (l.kind != LinkKind::LN) continue;
    const State &from = g.graph.states[l.from], &to = g.graph.states[l.to];
    EXPECT_LE(to.cf.cardinality(), from.cf.cardinality());
    // (between states of one cardinality the reverse of a motion is an LN link too, add_link:
    // {(fA1-eB, 1)} -> {(eA-eB, 1, touch)} reverses a motion from the touch, which no f-e
    // hypothesis names, since an e-e PtC hypothesised from one is a crossing)
    auto joins = [&](const State& x, const State& y) {
      for (const Hypothesis& h : hypothesise_ln(g.scene, x.contacts, true))
        if (h.cf == y.cf) return true;
      return false;
    };
    const bool hypothesised =
        joins(from, to) || (to.cf.cardinality() == from.cf.cardinality() && joins(to, from));
    EXPECT_TRUE(hypothesised) << "LN link " << from.cf.str(g.scene) << " -> " << to.cf.str(g.scene)
                              << " (" << l.motion << "): no LN hypothesis joins these CFs";
  }
}

// The states (CFs with repeats) and the adjacency of a graph equal the expected ones.
inline void expect_graph(const Generated& g, const std::vector<std::string>& states,
                         const std::vector<std::string>& adjacent) {
  std::vector<std::string> got_states;
  for (const State& s : g.graph.states) got_states.push_back(s.cf.str(g.scene));
  EXPECT_EQ(sorted(got_states), sorted(states)) << "got states:\n" << join(sorted(got_states));
  const std::vector<std::string> got_adj = adjacency(g.graph, g.scene);
  EXPECT_EQ(got_adj, sorted(adjacent)) << "got adjacency:\n" << join(got_adj);
  expect_witnesses_valid(g);
}

// Two circular rims centred on their own frames' z axes (the lenses of the stress scenes, the
// bowl's rims e1 and e2) crossing at a state's e-e contact: the sign of (t_A x t_B) . n, with
// t = z x p the counterclockwise tangents. It is constant on a region of an e-e-cross CF and
// changes only through e-e-touch (t_A parallel to t_B), a different CF: so such a CF has two
// regions, one of each sign (turning a lens over changes the sign). rim_tangents: t_A and t_B
// in B's frame at contact c of state s.
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> rim_tangents(const State& s,
                                                                const PointContact& c) {
  return {s.pose.rotate(Eigen::Vector3d::UnitZ().cross(c.p_A)),
          Eigen::Vector3d::UnitZ().cross(c.p_B)};
}

inline int rim_crossing_sign(const State& s, const std::string& pair, const SceneGeometry& scene) {
  for (const PointContact& c : s.contacts)
    if (element_pair_name(scene, c.a, c.b) == pair) {
      const auto [t_A, t_B] = rim_tangents(s, c);
      return t_A.cross(t_B).dot(c.normal_B) > 0 ? 1 : -1;
    }
  ADD_FAILURE() << "state " << s.id << " has no contact " << pair;
  return 0;
}

// The states of the e-e-cross CF {(pair, 1)} are two regions of opposite crossing signs.
inline void expect_both_crossing_regions(const Generated& g, const std::string& pair) {
  std::vector<int> signs;
  for (const State& s : g.graph.states)
    if (s.cf.str(g.scene) == "{(" + pair + ", 1)}")
      signs.push_back(rim_crossing_sign(s, pair, g.scene));
  std::sort(signs.begin(), signs.end());
  EXPECT_EQ(signs, (std::vector<int>{-1, 1})) << pair << ": one region of each crossing sign";
}

// Example 2's lens (fA1 - eA - fA2) against B (f1 - e1 - f2 - e2 - f3): every pair of an A
// element and a B element is a single-contact CF (A is convex, and turning it over exchanges
// fA1 and fA2), two adjacent when one of the two elements changes to an adjacent one: a 3 x 5
// grid of 15 CFs and 22 adjacent pairs (adjacent_pair), each list sorted.
struct LensGrid {
  std::vector<std::string> cfs, adjacent;
};
inline LensGrid lens_single_contact_grid() {
  const std::vector<std::string> a = {"fA1", "eA", "fA2"}, b = {"f1", "e1", "f2", "e2", "f3"};
  auto cf = [&](size_t i, size_t j) { return "{(" + a[i] + "-" + b[j] + ", 1)}"; };
  LensGrid grid;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) {
      grid.cfs.push_back(cf(i, j));
      if (i + 1 < a.size()) grid.adjacent.push_back(adjacent_pair(cf(i, j), cf(i + 1, j)));
      if (j + 1 < b.size()) grid.adjacent.push_back(adjacent_pair(cf(i, j), cf(i, j + 1)));
    }
  grid.cfs = sorted(grid.cfs);
  grid.adjacent = sorted(grid.adjacent);
  return grid;
}

// The links between single-contact states, as unique sorted adjacent pairs.
inline std::vector<std::string> single_contact_adjacency(const StateGraph& g,
                                                         const SceneGeometry& scene) {
  std::vector<std::string> out;
  for (const Link& l : g.links) {
    const State &from = g.states[l.from], &to = g.states[l.to];
    if (from.cf.cardinality() == 1 && to.cf.cardinality() == 1)
      out.push_back(adjacent_pair(from.cf.str(scene), to.cf.str(scene)));
  }
  out = sorted(out);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Each face of `got` is a positive multiple of the same face of `want` (same surface, same
// solid side), to `relative` of the largest coefficient: a scene file holds what its comment
// says it is.
inline void expect_faces_proportional(const ObjectSpec& got, const ObjectSpec& want,
                                      double relative) {
  ASSERT_EQ(got.faces.size(), want.faces.size()) << got.name;
  for (size_t i = 0; i < want.faces.size(); ++i) {
    const Polynomial &a = got.faces[i].g, &b = want.faces[i].g;
    const double k = a.max_abs_coeff() / b.max_abs_coeff();
    for (int n = 0; n < Polynomial::kNumCoeffs; ++n)
      EXPECT_NEAR(a.coeffs()[n], k * b.coeffs()[n], relative * a.max_abs_coeff())
          << got.name << "." << got.faces[i].name << " coefficient " << n;
  }
}

}  // namespace pcsg::testing
