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
  // (e-e pairs default to e-e-cross unless written "(eA-e1, 1, touch)").
  static ContactFormation parse(const std::string& text, const SceneGeometry& scene);

  void add(ElementId a, ElementId b, PtcType type, int count = 1);
  const std::vector<PtcCount>& entries() const { return entries_; }  // canonical order
  int cardinality() const;
  bool empty() const { return entries_.empty(); }
  // The paper's notation with the scene's element names.
  std::string str(const SceneGeometry& scene) const;
  std::uint64_t hash() const;
  bool operator==(const ContactFormation& o) const;
  bool operator<(const ContactFormation& o) const;

 private:
  std::vector<PtcCount> entries_;  // sorted by (a, b, type), counts merged
};

// Moves a pose onto the configurations of `cf`: all its contacts exact (|gap| below
// tol.solve_residual-level accuracy), every other element pair separated. Gauss-Newton on the
// stacked contact conditions with the contact Jacobian, starting from `start`.
struct ProjectionResult {
  bool ok = false;
  Pose pose;
  std::vector<PointContact> contacts;  // the cf's contacts at `pose`
  double max_residual = 0;
  std::string reason;                  // why it failed, naming elements and values
};
ProjectionResult project_onto_cf(const SceneGeometry& scene, const Pose& start,
                                 const ContactFormation& cf);

}  // namespace pcsg
