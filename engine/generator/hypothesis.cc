#include "engine/generator/hypothesis.h"

#include <algorithm>
#include <map>
#include <tuple>

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

// Plans that differ only by which of several identical contacts (one pair, one type) does
// what are alike: two of each kind are kept, which covers asymmetric situations without
// trying every permutation, and every kind is. (The first two plans of a hypothesis alone,
// whatever their kinds, never try from Example 1's {(fA-e1, 2), (fA-f1, 1)} the plans toward
// {(fA-f1, 2)} that change both rim contacts and lift off the dish, and toward {(fA-f1, 1)}
// that lift off both rims.) The filter keeps the order, so the first two plans stay first.
void keep_two_plans_of_each_kind(const std::vector<PointContact>& contacts, Hypothesis& h) {
  using Part = std::tuple<ElementId, ElementId, PtcType, ContactAction, ElementId, ElementId, int>;
  std::map<std::vector<Part>, int> kinds;
  std::vector<std::vector<ContactPlan>> kept;
  for (std::vector<ContactPlan>& plan : h.plan_options) {
    std::vector<Part> kind;
    for (size_t i = 0; i < plan.size(); ++i) {
      const ContactPlan& p = plan[i];
      const bool change = p.action == ContactAction::Change;
      kind.emplace_back(contacts[i].a, contacts[i].b, contacts[i].type, p.action,
                        change ? p.new_a : ElementId{}, change ? p.new_b : ElementId{},
                        change ? static_cast<int>(p.new_type) : -1);
    }
    std::sort(kind.begin(), kind.end());
    if (++kinds[kind] <= 2) kept.push_back(std::move(plan));
  }
  h.plan_options = std::move(kept);
}

}  // namespace

std::vector<Hypothesis> hypothesise_ln(const SceneGeometry& scene,
                                       const std::vector<PointContact>& contacts,
                                       bool every_kind_of_plan) {
  std::map<ContactFormation, Hypothesis> by_cf;
  enumerate(scene, contacts, by_cf);
  const ContactFormation own = ContactFormation::of(contacts);
  std::vector<Hypothesis> out;
  for (auto& [cf, h] : by_cf) {
    if (cf == own) continue;
    if (every_kind_of_plan) keep_two_plans_of_each_kind(contacts, h);
    out.push_back(std::move(h));
  }
  // Higher cardinality first: those keep more contacts and are tried with the most
  // constrained (finite) motions first, as the paper prefers.
  std::stable_sort(out.begin(), out.end(), [](const Hypothesis& x, const Hypothesis& y) {
    return x.cf.cardinality() > y.cf.cardinality();
  });
  return out;
}

}  // namespace pcsg
