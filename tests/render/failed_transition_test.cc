// A failed candidate of Example 2 replayed (replay_candidate) from the graph stored in
// tests/data/graphs/example2.json: its sequence ends at the collision frame, that frame names
// the two colliding elements, and its picture shows them in the warning colour with a banner.
#include <gtest/gtest.h>

#include <algorithm>

#include "engine/generator/generator.h"
#include "engine/scene/scene.h"
#include "render/graph_json_reader.h"
#include "render/transition_frame.h"

namespace pcsg::render {
namespace {

bool is_warning(const std::uint8_t* p) {
  // palette::kWarning = (0.86, 0.12, 0.10), also as a face blended 60% over white
  return p[0] > 170 && p[0] - p[1] > 80 && p[0] - p[2] > 80;
}

TEST(FailedTransitionTest, EndsAtTheCollisionWithTheElementsHighlighted) {
  const SceneGeometry scene = build_scene_geometry(
      load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/example2.yaml"));
  const StateGraph graph =
      read_graph_json(std::string(PCSG_SOURCE_DIR) + "/tests/data/graphs/example2.json", scene);
  // the failed candidates whose reported motion stopped at a collision, cheapest replay first
  std::vector<const Candidate*> collided;
  for (const Candidate& c : graph.candidates) {
    const std::string last = c.reason.substr(c.reason.rfind(c.motion + ":") == std::string::npos
                                                 ? 0
                                                 : c.reason.rfind(c.motion + ":"));
    if (!c.feasible && last.find("collision") != std::string::npos) collided.push_back(&c);
  }
  ASSERT_FALSE(collided.empty()) << "the stored graph has failed candidates that collide";
  std::sort(collided.begin(), collided.end(), [](const Candidate* a, const Candidate* b) {
    return std::make_pair(a->attempts, a->steps) < std::make_pair(b->attempts, b->steps);
  });

  const Candidate& c = *collided.front();
  State from = graph.states[c.from];
  from.contacts = detect_contacts(scene, from.pose).contacts;  // exact, for the replay
  std::vector<MotionFrame> frames;
  const MotionOutcome outcome =
      replay_candidate(scene, from, c, [&](const MotionFrame& f) { frames.push_back(f); });
  ASSERT_FALSE(outcome.feasible) << c.cf.str(scene);
  ASSERT_FALSE(frames.empty());
  const MotionFrame& last = frames.back();
  EXPECT_EQ(last.phase, "collision") << "the sequence ends at the collision: " << outcome.reason;
  for (std::size_t k = 0; k + 1 < frames.size(); ++k) EXPECT_NE(frames[k].phase, "collision");
  ASSERT_FALSE(last.collided_a.empty());
  ASSERT_FALSE(last.collided_b.empty());

  TransitionInfo info;
  info.from = c.from;
  info.from_cf = from.cf.str(scene);
  info.target_cf = c.cf.str(scene);
  info.motion = outcome.motion;
  info.reason = outcome.reason;
  info.steps = outcome.steps;
  TransitionFrameStyle style;
  style.width = 480;
  style.height = 360;
  const FrameRequest request = transition_frame_request(info, last, from.contacts, style);
  const SceneElement ea{Object::A, last.collided_a.front()}, eb{Object::B, last.collided_b.front()};
  EXPECT_NE(std::find(request.highlighted.begin(), request.highlighted.end(), ea),
            request.highlighted.end());
  EXPECT_NE(std::find(request.highlighted.begin(), request.highlighted.end(), eb),
            request.highlighted.end());
  const std::string names = collision_text(scene, last);
  EXPECT_NE(names.find(scene.A.element_name(ea.element)), std::string::npos) << names;
  EXPECT_NE(names.find(scene.B.element_name(eb.element)), std::string::npos) << names;

  SceneRenderer renderer(scene);
  TextPainter text;
  const Image image = draw_transition_frame(renderer, scene, info, last, from.contacts, {}, style,
                                            text, /*last_frame=*/true);
  // the banner: a full-width warning band between the header and the view
  int banner_rows = 0;
  for (int y = 0; y < image.height - style.height; ++y)
    banner_rows += is_warning(image.pixel(2, y)) && is_warning(image.pixel(image.width - 3, y));
  EXPECT_GT(banner_rows, 10);
  // the highlighted elements in the view
  long red = 0;
  for (int y = image.height - style.height; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) red += is_warning(image.pixel(x, y));
  EXPECT_GT(red, 200) << "collided elements drawn in the warning colour";
}

}  // namespace
}  // namespace pcsg::render
