#pragma once
// Local distance minima of one element pair at a pose, whatever their gap: the starting points
// of a projection onto a contact formation when the start pose's detection does not already
// show the pair (paper Section II-C: the same pair may form several contacts, so all minima
// are wanted, not only the nearest).
#include <array>
#include <cstdint>
#include <map>
#include <mutex>
#include <vector>

#include "engine/contact/contact_context.h"
#include "engine/contact/pair_solver.h"

namespace pcsg {

// Samples both elements (mesh vertices of faces, exact samples of edges, vertex points),
// ranks them by a first-order distance estimate, solves the pair from the best spatially
// separated ones and returns the distinct converged local minima with opposite normals, by
// increasing gap. The solutions are this pair's even where its points leave the elements
// (the projection needs the pair itself; detection decides the final classification).
std::vector<PointContact> pair_local_minima(const ContactContext& context, const Pose& X_BA,
                                            ElementId a, ElementId b, PtcType type);

// pair_local_minima's answers, each computed once: the projections that start from one pose
// toward several CFs ask for the same pair there again (project_upward in the generator:
// every target CF of a state shares the state's pairs at each of its turned starts; 1,361 of
// Example 1's 6,866 calls repeated their exact inputs). The answer is a pure function of
// the context and the inputs, so one found here is the one computing it again would give.
// Thread-safe; two threads asking at once may both compute it.
class PairMinimaMemo {
 public:
  std::vector<PointContact> get(const ContactContext& context, const Pose& X_BA, ElementId a,
                                ElementId b, PtcType type);
  // Answers kept, and samplings run (more than kept when two threads raced on one input).
  size_t size() const;
  size_t computed() const;

 private:
  // The pose's seven coordinates bit for bit, then a, b and the type.
  using Key = std::array<std::uint64_t, 10>;
  mutable std::mutex mutex_;
  std::map<Key, std::vector<PointContact>> answers_;
  size_t computed_ = 0;
};

}  // namespace pcsg
