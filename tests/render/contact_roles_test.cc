// Roles of the contacts of a transition motion, followed by continuity over its frames.
#include "render/contact_roles.h"

#include <gtest/gtest.h>

namespace pcsg::render {
namespace {

const ElementId fA{ElementKind::Face, 0};
const ElementId f1{ElementKind::Face, 0}, e1{ElementKind::Edge, 0};

PointContact contact(ElementId a, ElementId b, PtcType type, double x) {
  PointContact c;
  c.a = a;
  c.b = b;
  c.type = type;
  c.point_B = Eigen::Vector3d(x, 0, 0);
  return c;
}

// A match distance of a few motion steps: the contacts below move 0.1 per frame.
constexpr double kMatch = 0.5;

TEST(ContactRolesTest, OneOfTwoAlikeContactsChangesTheOtherIsKept) {
  // {(fA-f1, 2)} -> {(fA-e1, 1), (fA-f1, 1)}: the contact at x = 1 slides onto e1
  const std::vector<PointContact> start = {contact(fA, f1, PtcType::FF, -1),
                                           contact(fA, f1, PtcType::FF, 1)};
  ContactFormation target;
  target.add(fA, f1, PtcType::FF);
  target.add(fA, e1, PtcType::FE);
  const std::vector<std::vector<PointContact>> frames = {
      {},  // the replay's first frame carries no contacts: the start's
      {contact(fA, f1, PtcType::FF, -1), contact(fA, f1, PtcType::FF, 1.1)},
      {contact(fA, f1, PtcType::FF, -1), contact(fA, e1, PtcType::FE, 1.2)}};
  const auto roles = assign_contact_roles(start, frames, target, kMatch);
  ASSERT_EQ(roles.size(), 3u);
  EXPECT_EQ(roles[0], (std::vector<ContactRole>{ContactRole::Kept, ContactRole::Changing}));
  EXPECT_EQ(roles[1], (std::vector<ContactRole>{ContactRole::Kept, ContactRole::Changing}));
  EXPECT_EQ(roles[2], (std::vector<ContactRole>{ContactRole::Kept, ContactRole::Reached}));
}

TEST(ContactRolesTest, UnresolvedWhenTheMotionStopsBeforeTheChange) {
  const std::vector<PointContact> start = {contact(fA, f1, PtcType::FF, -1),
                                           contact(fA, f1, PtcType::FF, 1)};
  ContactFormation target;
  target.add(fA, f1, PtcType::FF);
  target.add(fA, e1, PtcType::FE);
  const auto roles = assign_contact_roles(
      start, {{contact(fA, f1, PtcType::FF, -1), contact(fA, f1, PtcType::FF, 1.1)}}, target, kMatch);
  EXPECT_EQ(roles[0], (std::vector<ContactRole>{ContactRole::Undecided, ContactRole::Undecided}));
}

TEST(ContactRolesTest, RemovedAndAppearingContacts) {
  // {(fA-f1, 2)} -> {(fA-f1, 1)}: the contact at x = 1 separates; a new fA-e1 contact appears
  // (a collision), which is not in the plan
  const std::vector<PointContact> start = {contact(fA, f1, PtcType::FF, -1),
                                           contact(fA, f1, PtcType::FF, 1)};
  ContactFormation target;
  target.add(fA, f1, PtcType::FF);
  const auto roles = assign_contact_roles(
      start,
      {{contact(fA, f1, PtcType::FF, -1), contact(fA, f1, PtcType::FF, 1)},
       {contact(fA, f1, PtcType::FF, -1)},
       {contact(fA, f1, PtcType::FF, -1), contact(fA, e1, PtcType::FE, 5)}},
      target, kMatch);
  EXPECT_EQ(roles[0], (std::vector<ContactRole>{ContactRole::Kept, ContactRole::Changing}));
  EXPECT_EQ(roles[1], (std::vector<ContactRole>{ContactRole::Kept}));
  EXPECT_EQ(roles[2], (std::vector<ContactRole>{ContactRole::Kept, ContactRole::Other}));
}

TEST(ContactRolesTest, AContactLostAtTheFailureIsNotThePlannedChange) {
  // one of two fA-f1 contacts is to change; the motion fails when one of them leaves its
  // elements: which of the two was to change is still unknown
  const std::vector<PointContact> start = {contact(fA, f1, PtcType::FF, -1),
                                           contact(fA, f1, PtcType::FF, 1)};
  ContactFormation target;
  target.add(fA, f1, PtcType::FF);
  target.add(fA, e1, PtcType::FE);
  const std::vector<std::vector<PointContact>> frames = {
      {contact(fA, f1, PtcType::FF, -1), contact(fA, f1, PtcType::FF, 1)},
      {contact(fA, f1, PtcType::FF, -1)}};
  const auto failed = assign_contact_roles(start, frames, target, kMatch, true);
  EXPECT_EQ(failed[0], (std::vector<ContactRole>{ContactRole::Undecided, ContactRole::Undecided}));
  // the same vanishing before the end of a motion counts as the change
  const auto went_on = assign_contact_roles(start, frames, target, kMatch, false);
  EXPECT_EQ(went_on[0], (std::vector<ContactRole>{ContactRole::Kept, ContactRole::Changing}));
}

}  // namespace
}  // namespace pcsg::render
