#pragma once
// Hypothesising the locally-defined neighbour (LN) CFs of a state (paper Section III-A):
// a single PtC is changed to a neighbouring PtC; with card >= 2, action set 1 keeps some PtCs
// and changes others to neighbours, action set 2 keeps some and removes others.
#include <vector>

#include "engine/contact/contact_formation.h"

namespace pcsg {

enum class ContactAction { Keep, Change, Remove };

// What happens to one contact of the current state.
struct ContactPlan {
  ContactAction action = ContactAction::Keep;
  // For Change: the neighbouring PtC it becomes (one of its two elements replaced by an
  // adjacent element of the same solid).
  ElementId new_a, new_b;
  PtcType new_type = PtcType::FF;
  bool changes_a = false;  // the A element changes (slidingB family), else the B element
};

struct Hypothesis {
  ContactFormation cf;  // the hypothesised LN CF
  // The ways of reaching it: each a plan per contact of the current state, in its order.
  // (Several when contacts are alike, e.g. either of two fA-f1 contacts may change.)
  std::vector<std::vector<ContactPlan>> plan_options;
};

// Hypotheses take the PtC type of a pair from its elements (ptc_type_between, contact.h):
// edge-edge pairs give e-e-cross; e-e-touch is the degenerate, collinear case and is decided
// from geometry, not hypothesised.

// Neighbouring PtCs of a contact (paper Section II-D): the same A element with an element
// adjacent to B's, or the same B element with an element adjacent to A's.
std::vector<PtcCount> neighbouring_ptcs(const SceneGeometry& scene, const PointContact& c);

// All LN hypotheses of a state with the given contacts, deduplicated by CF, in a deterministic
// order (by cardinality descending, then CF order). The state's own CF is not included. With
// `every_kind_of_plan`, each keeps two plans of each kind only (plans that differ only by which
// of several alike contacts does what are of one kind), in order, so its first two plans stay
// first (GeneratorOptions::complete_search tries them all; the generator otherwise the first
// two).
std::vector<Hypothesis> hypothesise_ln(const SceneGeometry& scene,
                                       const std::vector<PointContact>& contacts,
                                       bool every_kind_of_plan = false);

}  // namespace pcsg
