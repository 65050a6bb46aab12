#include "engine/generator/hypothesis.h"

#include <gtest/gtest.h>

#include "engine/contact/contact.h"
#include "generator_test_support.h"

namespace pcsg {
namespace {

std::vector<std::string> cf_texts(const std::vector<Hypothesis>& hs, const SceneGeometry& scene) {
  std::vector<std::string> out;
  for (const Hypothesis& h : hs) out.push_back(h.cf.str(scene));
  return out;
}

TEST(Hypothesis, Example1SeedHasTheLocallyDefinedNeighbours) {
  const SceneGeometry scene =
      build_scene_geometry(load_scene_file(testing::scene_path("example1.yaml")));
  // Two fA-f1 contacts, as at the seed (positions are irrelevant to hypothesising).
  PointContact c;
  c.a = scene.A.find("fA");
  c.b = scene.B.find("f1");
  c.type = PtcType::FF;
  const auto hs = hypothesise_ln(scene, {c, c});
  const auto texts = cf_texts(hs, scene);
  // f1 is adjacent to e1 only (B has no vertices): keep/change/remove for each of the two.
  for (const char* expected :
       {"{(fA-f1, 1)}", "{(fA-e1, 1)}", "{(fA-e1, 2)}", "{(fA-e1, 1), (fA-f1, 1)}"})
    EXPECT_NE(std::find(texts.begin(), texts.end(), expected), texts.end())
        << expected << " missing from\n" << testing::join(texts);
  EXPECT_EQ(hs.size(), 4u) << testing::join(texts);
  // Higher cardinality first.
  for (size_t i = 1; i < hs.size(); ++i)
    EXPECT_GE(hs[i - 1].cf.cardinality(), hs[i].cf.cardinality());
}

TEST(Hypothesis, SingleContactOnlyChanges) {
  const SceneGeometry scene =
      build_scene_geometry(load_scene_file(testing::scene_path("example1.yaml")));
  PointContact c;
  c.a = scene.A.find("fA");
  c.b = scene.B.find("e1");
  c.type = PtcType::FE;
  const auto texts = cf_texts(hypothesise_ln(scene, {c}), scene);
  // e1's neighbours on B are f1 and f2; A has a single face.
  EXPECT_EQ(texts, (std::vector<std::string>{"{(fA-f1, 1)}", "{(fA-f2, 1)}"}))
      << testing::join(texts);
}

}  // namespace
}  // namespace pcsg
