#pragma once
// The generator's progress as one line on stderr, rewritten in place: a prefix naming the run,
// then the BFS level and candidate (or the later phase and its count) and the graph so far.
#include <cstdio>
#include <string>
#include <utility>

#include "engine/generator/generator.h"

namespace pcsg::app {

class ProgressLine : public GeneratorListener {
 public:
  // `prefix`: e.g. "pcsg generate"; nothing is printed when not `enabled`.
  explicit ProgressLine(std::string prefix, bool enabled = true)
      : prefix_(std::move(prefix)), enabled_(enabled) {}
  void on_progress(const StateGraph& g, int level, int done, int total) override {
    if (!enabled_) return;
    std::fprintf(stderr, "\r%s: level %d, candidate %d/%d, %zu states, %zu links   ",
                 prefix_.c_str(), level, done, total, g.states.size(), g.links.size());
    std::fflush(stderr);
  }
  void on_phase_progress(const StateGraph& g, const std::string& phase, int done,
                         int total) override {
    if (!enabled_) return;
    std::fprintf(stderr, "\r%s: %s, %d/%d, %zu states, %zu links   ", prefix_.c_str(),
                 phase.c_str(), done, total, g.states.size(), g.links.size());
    std::fflush(stderr);
  }
  // Ends the line (the next output starts on a line of its own).
  void finish() const {
    if (enabled_) std::fprintf(stderr, "\n");
  }

 private:
  std::string prefix_;
  bool enabled_;
};

}  // namespace pcsg::app
