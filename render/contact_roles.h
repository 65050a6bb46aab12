#pragma once
// What each contact does in a transition motion (paper Section III-C: keep, change, remove),
// for drawing: the contacts of every frame are followed from the start state's contacts by
// continuity (same element pair and nearest point first, then the nearest point of a changed
// pair), and each is given its role in the whole motion. Needs the whole sequence: with two
// contacts of one pair of which one changes, which one it is shows only at the change.
#include <vector>

#include "engine/contact/contact_formation.h"

namespace pcsg::render {

enum class ContactRole {
  Kept,       // a contact of both the start CF and the target CF, maintained
  Changing,   // a start contact the transition changes or removes (before it has)
  Reached,    // a contact of the target CF that the motion has reached
  Undecided,  // one of several alike contacts of which some are kept and some change,
              // in a motion that stopped before telling which
  Other,      // not in the plan: a contact that appeared (a collision)
};
const char* contact_role_name(ContactRole role);  // "kept", "changing", ..., "unplanned"

// roles[k][i] is the role of contacts[k][i]. `start` are the start state's contacts; a frame
// without contacts (the replay's first frame) is taken to have them. `match_distance` bounds
// how far a contact may move between frames and still be the same one across a change of
// elements (a few motion steps). With `ends_in_failure` the last frame is where the motion
// failed: a contact that changes or vanishes there is not taken as the planned change (a kept
// contact may be the one that left its elements).
std::vector<std::vector<ContactRole>> assign_contact_roles(
    const std::vector<PointContact>& start, const std::vector<std::vector<PointContact>>& contacts,
    const ContactFormation& target, double match_distance, bool ends_in_failure = false);

}  // namespace pcsg::render
