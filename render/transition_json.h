#pragma once
// A drawn transition as JSON (frames.json next to its PNGs): the candidate, the start
// contacts, and every drawn frame with its pose, contacts, roles, phase and collided
// elements. Lets a sequence be inspected or drawn again without replaying the motion (the
// contact-sheet golden test reads one from tests/data/graphs/).
#include <string>
#include <vector>

#include "render/contact_roles.h"
#include "render/transition_frame.h"

namespace pcsg::render {

struct TransitionRecord {
  TransitionInfo info;
  std::vector<PointContact> start;              // the start state's contacts
  std::vector<MotionFrame> frames;              // the frames drawn
  std::vector<std::vector<ContactRole>> roles;  // per frame, per contact
};

std::string transition_to_json(const TransitionRecord& record, const SceneGeometry& scene);
// Throws pcsg::Error naming the file and what is wrong with it.
TransitionRecord read_transition_json(const std::string& path, const SceneGeometry& scene);

}  // namespace pcsg::render
