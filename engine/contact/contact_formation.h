#pragma once
// A contact formation (paper Section II-C): the multiset of PtCs, printed in the paper's
// notation, e.g. {(fA-f1, 2)} or {(eA-f1, 1), (fA2-e1, 1)}.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/contact/contact.h"

namespace pcsg {

struct PtcCount {
  ElementId a, b;
  PtcType type = PtcType::FF;
  int count = 1;
};

class ContactFormation {
 public:
  ContactFormation() = default;
  // The CF of a list of contacts (multiplicity = number of contacts of each pair and type).
  static ContactFormation of(const std::vector<PointContact>& contacts);
  // Parses the paper's notation against the scene's element names; throws UsageError naming
  // the text and the unknown element or malformed part. Types are derived from the elements
  // (e-e pairs default to e-e-cross unless written "(eA-e1, 1, touch)"). "{}" is the empty CF.
  static ContactFormation parse(const std::string& text, const SceneGeometry& scene);

  // Adds `count` (>= 1) PtCs of the pair and type; `type` must join a's and b's kinds.
  void add(ElementId a, ElementId b, PtcType type, int count = 1);
  const std::vector<PtcCount>& entries() const { return entries_; }  // canonical order
  // Multiplicity of one PtC (0 when absent).
  int count(ElementId a, ElementId b, PtcType type) const;
  // card(CF) = n_1 + ... + n_m (Section II-C).
  int cardinality() const;
  bool empty() const { return entries_.empty(); }
  // The paper's notation with the scene's element names, entries sorted by name.
  std::string str(const SceneGeometry& scene) const;
  // Depends only on the entries (element indices, types, counts): equal CFs hash equally.
  std::uint64_t hash() const;
  bool operator==(const ContactFormation& o) const;
  bool operator!=(const ContactFormation& o) const { return !(*this == o); }
  bool operator<(const ContactFormation& o) const;

 private:
  std::vector<PtcCount> entries_;  // sorted by (a, b, type), counts merged
};

// "fA-f1": an element pair in the paper's notation.
std::string element_pair_name(const SceneGeometry& scene, ElementId a, ElementId b);

class ContactContext;
class PairMinimaMemo;

// Moves a pose onto the configurations of `cf`: all its contacts exact (every residual below
// tol.solve_residual), every other element pair separated. Gauss-Newton with minimum-norm
// steps on the stacked contact conditions and their twist Jacobians (contact.h), re-solving
// each pair problem from its previous points at every iterate; the result is then checked by
// detection, which must report exactly `cf` and no penetration.
struct ProjectionOptions {
  // Starting points for the CF's contacts (e.g. the contacts of a nearby pose). Contacts
  // without one are taken from detection at the start pose, then from sampling the two
  // elements (pair_seeds.h).
  std::vector<PointContact> seeds;
  // Where set, the sampled local minima come from (and are kept in) this memo (pair_seeds.h):
  // the same answers, computed once for projections that share a start pose.
  PairMinimaMemo* minima = nullptr;
};
struct ProjectionResult {
  bool ok = false;
  Pose pose;
  std::vector<PointContact> contacts;  // the cf's contacts at `pose` (as detected)
  double max_residual = 0;
  int iterations = 0;
  std::string reason;  // why it failed, naming elements and values
};
ProjectionResult project_onto_cf(const ContactContext& context, const Pose& start,
                                 const ContactFormation& cf, const ProjectionOptions& options = {});
// The same with the scene's cached context (contact_context.h).
ProjectionResult project_onto_cf(const SceneGeometry& scene, const Pose& start,
                                 const ContactFormation& cf, const ProjectionOptions& options = {});

}  // namespace pcsg
