#include "engine/generator/hypothesis.h"

#include <map>

namespace pcsg {

std::vector<PtcCount> neighbouring_ptcs(const SceneGeometry& scene, const PointContact& c) {
  std::vector<PtcCount> out;
  for (const ElementId& nb : scene.B.adjacent(c.b))
    out.push_back({c.a, nb, ptc_type_between(c.a.kind, nb.kind), 1});
  for (const ElementId& na : scene.A.adjacent(c.a))
    out.push_back({na, c.b, ptc_type_between(na.kind, c.b.kind), 1});
  return out;
}

namespace {

// Enumerates every assignment of an action to each contact (odometer over the options).
void enumerate(const SceneGeometry& scene, const std::vector<PointContact>& contacts,
               std::map<ContactFormation, Hypothesis>& out) {
  const size_t n = contacts.size();
  std::vector<std::vector<ContactPlan>> options(n);
  for (size_t i = 0; i < n; ++i) {
    options[i].push_back({ContactAction::Keep, {}, {}, contacts[i].type, false});
    for (const PtcCount& nb : neighbouring_ptcs(scene, contacts[i])) {
      ContactPlan p{ContactAction::Change, nb.a, nb.b, nb.type, !(nb.a == contacts[i].a)};
      options[i].push_back(p);
    }
    // Action set 2 (removal) only exists for card >= 2 (Section III-A).
    if (n >= 2) options[i].push_back({ContactAction::Remove, {}, {}, contacts[i].type, false});
  }
  std::vector<size_t> pick(n, 0);
  while (true) {
    // Build the plan and its CF; skip "keep all" and "remove all".
    std::vector<ContactPlan> plan(n);
    ContactFormation cf;
    bool any_change = false;
    for (size_t i = 0; i < n; ++i) {
      plan[i] = options[i][pick[i]];
      switch (plan[i].action) {
        case ContactAction::Keep:
          cf.add(contacts[i].a, contacts[i].b, contacts[i].type);
          break;
        case ContactAction::Change:
          cf.add(plan[i].new_a, plan[i].new_b, plan[i].new_type);
          any_change = true;
          break;
        case ContactAction::Remove:
          any_change = true;
          break;
      }
    }
    if (any_change && !cf.empty()) {
      Hypothesis& h = out[cf];
      h.cf = cf;
      h.plan_options.push_back(std::move(plan));
    }
    // Next assignment.
    size_t k = 0;
    while (k < n && ++pick[k] == options[k].size()) pick[k++] = 0;
    if (k == n) break;
  }
}

}  // namespace

std::vector<Hypothesis> hypothesise_ln(const SceneGeometry& scene,
                                       const std::vector<PointContact>& contacts) {
  std::map<ContactFormation, Hypothesis> by_cf;
  enumerate(scene, contacts, by_cf);
  const ContactFormation own = ContactFormation::of(contacts);
  std::vector<Hypothesis> out;
  for (auto& [cf, h] : by_cf)
    if (!(cf == own)) out.push_back(std::move(h));
  // Higher cardinality first: those keep more contacts and are tried with the most
  // constrained (finite) motions first, as the paper prefers.
  std::stable_sort(out.begin(), out.end(), [](const Hypothesis& x, const Hypothesis& y) {
    return x.cf.cardinality() > y.cf.cardinality();
  });
  return out;
}

}  // namespace pcsg
