// The OSMesa context: a core profile of at least 3.3 with a 4x multisampled target that keeps
// the context alive across resizes. (Rows top first is checked on a rendered frame in
// scene_renderer_test.cc: nothing outside render/ includes GL headers.)
#include "render/gl_context.h"

#include <gtest/gtest.h>

#include "engine/core/error.h"

namespace pcsg::render {
namespace {

TEST(GlContextTest, CreatesCoreProfileWithMultisampledTarget) {
  auto ctx = create_gl_context(64, 48, 4);
  EXPECT_GE(ctx->gl_version(), 33) << ctx->description();
  EXPECT_TRUE(ctx->core_profile()) << ctx->description();
  EXPECT_EQ(ctx->width(), 64);
  EXPECT_EQ(ctx->height(), 48);
  EXPECT_EQ(ctx->samples(), 4) << "llvmpipe supports 4 samples";
  EXPECT_NE(ctx->framebuffer(), 0u);
}

TEST(GlContextTest, ResizeKeepsTheContext) {
  auto ctx = create_gl_context(32, 32, 4);
  ctx->resize(50, 20);
  const Image image = ctx->read_pixels();
  EXPECT_EQ(image.width, 50);
  EXPECT_EQ(image.height, 20);
  EXPECT_EQ(image.rgba.size(), 50u * 20u * 4u);
}

TEST(GlContextTest, RejectsZeroSize) { EXPECT_THROW(create_gl_context(0, 10, 4), Error); }

TEST(GlContextTest, ClampsSamplesToWhatIsSupported) {
  EXPECT_EQ(create_gl_context(8, 8, 1)->samples(), 1);
  EXPECT_LE(create_gl_context(8, 8, 64)->samples(), 64);
}

}  // namespace
}  // namespace pcsg::render
