// The contact sheet of one transition motion of Example 1, drawn from the frames stored in
// tests/data/graphs/example1_transition.json (written once by `pcsg figures`, so that this
// image does not follow the motion code's changes), and the header of a frame.
#include <gtest/gtest.h>

#include "engine/scene/scene.h"
#include "render/framed_scene.h"
#include "render/transition_json.h"
#include "tests/render/golden.h"

namespace pcsg::render {
namespace {

// Frames as `pcsg figures` draws them by default, cells as in its sheets.
constexpr int kFrameWidth = 640, kFrameHeight = 480, kCellWidth = 400;

TEST(TransitionSheetTest, Example1SeedToEdgeContact) {
  PCSG_SKIP_WITHOUT_LABEL_FONT();
  const SceneGeometry scene = build_scene_geometry(
      load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/example1.yaml"));
  const TransitionRecord r = read_transition_json(
      std::string(PCSG_SOURCE_DIR) + "/tests/data/graphs/example1_transition.json", scene);
  ASSERT_GE(r.frames.size(), 3u);
  ASSERT_EQ(r.roles.size(), r.frames.size());
  // one framing for the sequence, as `pcsg figures` draws it
  std::vector<Pose> poses;
  for (const MotionFrame& f : r.frames) poses.push_back(f.pose);
  const SceneGeometry framed = framed_scene(scene, extent_of_A(scene, poses));
  SceneRenderer renderer(framed);
  TextPainter text;
  TransitionFrameStyle style;
  style.width = kFrameWidth;
  style.height = kFrameHeight;
  std::vector<Image> views;
  for (std::size_t k = 0; k < r.frames.size(); ++k)
    views.push_back(draw_transition_view(renderer, framed, r.info, r.frames[k], r.start,
                                         r.roles[k], style));
  const Image sheet =
      transition_contact_sheet(r.info, views, r.frames, r.roles, r.start, scene, kCellWidth, text);
  testing::expect_matches_golden(sheet, "example1_transition_sheet");
}

TEST(TransitionSheetTest, SlugNamesTheStartAndTheTarget) {
  TransitionInfo t;
  t.from = 3;
  t.target_cf = "{(fA-e1, 1), (fA-f1, 1)}";
  EXPECT_EQ(transition_slug(t), "3-fA-e1x1_fA-f1x1");
  t.target_cf = "{(eA-e1, 1, touch)}";
  EXPECT_EQ(transition_slug(t), "3-eA-e1x1-touch");
}

}  // namespace
}  // namespace pcsg::render
