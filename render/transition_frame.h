#pragma once
// The frames of a candidate transition motion (paper Section III-B/C), as replayed by
// replay_candidate: each frame shows A at the step's pose with its contacts ringed by their
// role (kept, changing, reached), under a header with the transition, the motion type, the
// step and the current CF. At a failed candidate's last frame (phase "collision") the two
// offending elements are drawn in the warning colour and named in a banner.
#include <string>
#include <vector>

#include "engine/generator/transition_motion.h"
#include "render/camera.h"
#include "render/contact_roles.h"
#include "render/scene_renderer.h"
#include "render/text_painter.h"

namespace pcsg::render {

// The candidate a sequence shows.
struct TransitionInfo {
  int from = -1;
  std::string from_cf, target_cf;  // the paper's notation
  std::string motion;              // the motion replayed (that worked, or the last one tried)
  bool feasible = false;
  int to = -1;         // the state reached, when feasible
  std::string reason;  // why the replayed motion failed
  int steps = 0;       // steps of that motion
};

// "<from>-<target CF>", file-name safe: 0-fA-e1x1_fA-f1x1.
std::string transition_slug(const TransitionInfo& t);

struct TransitionFrameStyle {
  int width = 800, height = 600;  // the 3D view; the header band comes on top of it
  Camera camera;
  bool labels = true;
};

// The renderer's request for a frame: A at the frame's pose, its contacts (the start state's
// when the frame has none, as the replay's first frame), and at a collision the collided
// elements highlighted.
FrameRequest transition_frame_request(const TransitionInfo& t, const MotionFrame& frame,
                                      const std::vector<PointContact>& start,
                                      const TransitionFrameStyle& style);

// The 3D view of a frame: the renderer's picture with a ring of the role's colour around each
// contact. `scene` must be the one `renderer` draws (e.g. a FramedScene), for the rings to
// land on the renderer's markers.
Image draw_transition_view(SceneRenderer& renderer, const SceneGeometry& scene,
                           const TransitionInfo& t, const MotionFrame& frame,
                           const std::vector<PointContact>& start,
                           const std::vector<ContactRole>& roles,
                           const TransitionFrameStyle& style);

// The view under a header band (the transition, the motion type and step, the current CF, a
// legend of the roles shown) and, where a failed motion stops (a collision frame, or the
// sequence's `last_frame` when the transition failed), a banner naming the colliding elements
// and the reason.
Image add_transition_header(const Image& view, const SceneGeometry& scene, const TransitionInfo& t,
                            const MotionFrame& frame, const std::vector<PointContact>& start,
                            const std::vector<ContactRole>& roles, const TextPainter& text,
                            bool last_frame);

// Both: one frame of the PNG sequence.
Image draw_transition_frame(SceneRenderer& renderer, const SceneGeometry& scene,
                            const TransitionInfo& t, const MotionFrame& frame,
                            const std::vector<PointContact>& start,
                            const std::vector<ContactRole>& roles,
                            const TransitionFrameStyle& style, const TextPainter& text,
                            bool last_frame);

// One sheet of the frames' views (scaled to `cell_width`), each captioned with its step, phase
// and CF; the collision frame framed in the warning colour; a legend of the roles.
Image transition_contact_sheet(const TransitionInfo& t, const std::vector<Image>& views,
                               const std::vector<MotionFrame>& frames,
                               const std::vector<std::vector<ContactRole>>& roles,
                               const std::vector<PointContact>& start, const SceneGeometry& scene,
                               int cell_width, const TextPainter& text);

// "fA with f1": the elements of a collision frame, named.
std::string collision_text(const SceneGeometry& scene, const MotionFrame& frame);
// True where the banner goes: a collision frame, or the last frame of a failed transition
// (a motion that stops without a collision: no progress, a kept contact lost, the other
// crossing at the end).
bool shows_failure(const TransitionInfo& t, const MotionFrame& frame, bool last_frame);
// "collision at step 12: fA2 with f1 — <why the motion stopped>", the banner's text ("stopped
// at step 12 — <why>" when no elements collided).
std::string collision_banner(const SceneGeometry& scene, const TransitionInfo& t,
                             const MotionFrame& frame);

Rgb contact_role_colour(ContactRole role);

}  // namespace pcsg::render
