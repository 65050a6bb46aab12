#pragma once
// Shared by the generator tests: loading the shipped scenes, a graph's comparable signature.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/generator/generator.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"

namespace pcsg::testing {

inline std::string scene_path(const std::string& name) {
  return std::string(PCSG_SOURCE_DIR) + "/scenes/" + name;
}

// A graph's structure independent of witness poses and state numbering: the distinct CFs of
// its states and the distinct CF pairs of its LN links. Distinct, because two witnesses of one
// CF that pcsg could not yet prove CF-connected stay two states (an open defect recorded in
// docs/paper-comparison.md), and how many such duplicates appear depends on the witnesses.
struct GraphSignature {
  std::vector<std::string> states;
  std::vector<std::string> links;
  bool operator==(const GraphSignature& o) const { return states == o.states && links == o.links; }
};

inline GraphSignature signature(const StateGraph& g, const SceneGeometry& scene) {
  GraphSignature s;
  for (const State& st : g.states) s.states.push_back(st.cf.str(scene));
  for (const Link& l : g.links)
    if (l.kind == LinkKind::LN)
      s.links.push_back(g.states[l.from].cf.str(scene) + " -> " + g.states[l.to].cf.str(scene));
  std::sort(s.states.begin(), s.states.end());
  s.states.erase(std::unique(s.states.begin(), s.states.end()), s.states.end());
  std::sort(s.links.begin(), s.links.end());
  s.links.erase(std::unique(s.links.begin(), s.links.end()), s.links.end());
  return s;
}

inline std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += "  " + s + "\n";
  return out;
}

// The lines of `a` that `b` lacks, sorted (the difference a failing comparison lists).
inline std::vector<std::string> only_in(std::vector<std::string> a, std::vector<std::string> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::vector<std::string> out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

// A signature stored as text, tests/data/signatures/<name>.txt: one "state <CF>" line per
// distinct state CF and one "link <CF> -> <CF>" line per distinct LN link, sorted as
// signature() sorts them ('#' lines are comments). It is the reference of tests whose own
// generation of it would cost too much (Example 2 under scaling, ~6 minutes per run), and is
// itself checked against a live generation (Generator.Example2WitnessesAreExact).
inline std::string signature_file(const std::string& name) {
  return std::string(PCSG_SOURCE_DIR) + "/tests/data/signatures/" + name + ".txt";
}

inline std::string signature_text(const GraphSignature& s) {
  std::string out;
  for (const std::string& st : s.states) out += "state " + st + "\n";
  for (const std::string& l : s.links) out += "link " + l + "\n";
  return out;
}

inline GraphSignature read_signature(const std::string& name) {
  std::ifstream in(signature_file(name));
  if (!in) throw std::runtime_error("cannot read " + signature_file(name));
  GraphSignature s;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (line.rfind("state ", 0) == 0) {
      s.states.push_back(line.substr(6));
    } else if (line.rfind("link ", 0) == 0) {
      s.links.push_back(line.substr(5));
    } else {
      throw std::runtime_error(signature_file(name) + ": unexpected line '" + line + "'");
    }
  }
  return s;
}

// `have` equals the stored signature `name`; on a difference the lines only one side has are
// listed, and `have` is written to signatures/<name>-<test>.txt in the working directory (the
// build's tests folder; one file per test, since several tests check one signature) to be
// reviewed and copied over the stored one when the change is intended.
inline void expect_stored_signature(const GraphSignature& have, const std::string& name) {
  const GraphSignature want = read_signature(name);
  if (have == want) return;
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string written =
      "signatures/" + name + "-" +
      (test ? std::string(test->test_suite_name()) + "." + test->name() : std::string("run")) +
      ".txt";
  std::filesystem::create_directories("signatures");
  std::ofstream(written) << signature_text(have);
  ADD_FAILURE() << "the graph differs from " << signature_file(name) << " (this run's written to "
                << std::filesystem::absolute(written).string() << ")\n"
                << "states only here:\n"
                << join(only_in(have.states, want.states)) << "states only there:\n"
                << join(only_in(want.states, have.states)) << "links only here:\n"
                << join(only_in(have.links, want.links)) << "links only there:\n"
                << join(only_in(want.links, have.links));
}

// How many states each CF holds, one "count N <CF>" line per CF, sorted by CF: what a signature
// does not see, a region left as two states by a failed join (Example 2's far frame held one
// {(fA1-e1, 2)} more than its own frame until session 50).
inline std::vector<std::string> state_counts(const StateGraph& g, const SceneGeometry& scene) {
  std::map<std::string, int> n;
  for (const State& st : g.states) ++n[st.cf.str(scene)];
  std::vector<std::string> out;
  for (const auto& [cf, k] : n) out.push_back("count " + std::to_string(k) + " " + cf);
  return out;
}

// `have` equals the stored counts tests/data/signatures/<name>.txt (state_counts' lines; '#'
// lines are comments); on a difference the lines only one side has are listed.
inline void expect_stored_state_counts(const std::vector<std::string>& have,
                                       const std::string& name) {
  std::ifstream in(signature_file(name));
  if (!in) throw std::runtime_error("cannot read " + signature_file(name));
  std::vector<std::string> want;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') want.push_back(line);
  if (have == want) return;
  ADD_FAILURE() << "the states per CF differ from " << signature_file(name) << "\nonly here:\n"
                << join(only_in(have, want)) << "only there:\n"
                << join(only_in(want, have));
}

}  // namespace pcsg::testing
