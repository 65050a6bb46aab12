// Contact formations (paper Section II-C): multiset semantics, cardinality, the paper's
// notation both ways, hashing, and the errors a user sees for malformed text.
#include <gtest/gtest.h>

#include "engine/contact/contact_formation.h"
#include "engine/core/error.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"

namespace pcsg {
namespace {

const SceneGeometry& example2() {
  static const SceneGeometry g = build_scene_geometry(
      load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/example2.yaml"));
  return g;
}

PointContact contact(const SceneGeometry& g, const std::string& a, const std::string& b,
                     PtcType type) {
  PointContact c;
  c.a = g.A.find(a);
  c.b = g.B.find(b);
  c.type = type;
  return c;
}

TEST(ContactFormation, CountsRepeatedPairsAsMultiplicities) {
  const SceneGeometry& g = example2();
  const ContactFormation cf = ContactFormation::of({contact(g, "fA1", "f1", PtcType::FF),
                                                    contact(g, "eA", "f1", PtcType::EF),
                                                    contact(g, "fA1", "f1", PtcType::FF)});
  EXPECT_EQ(cf.str(g), "{(eA-f1, 1), (fA1-f1, 2)}");
  EXPECT_EQ(cf.cardinality(), 3);
  EXPECT_EQ(cf.entries().size(), 2u);
  EXPECT_EQ(cf.count(g.A.find("fA1"), g.B.find("f1"), PtcType::FF), 2);
  EXPECT_EQ(cf.count(g.A.find("fA2"), g.B.find("f1"), PtcType::FF), 0);
}

TEST(ContactFormation, ParsesThePapersNotation) {
  const SceneGeometry& g = example2();
  const ContactFormation cf = ContactFormation::parse("{(eA-f1, 1), (fA2-e1, 1)}", g);
  EXPECT_EQ(cf.str(g), "{(eA-f1, 1), (fA2-e1, 1)}");
  EXPECT_EQ(cf.count(g.A.find("eA"), g.B.find("f1"), PtcType::EF), 1);
  EXPECT_EQ(cf.count(g.A.find("fA2"), g.B.find("e1"), PtcType::FE), 1);
  // Blanks are free, order is not significant, repeated entries add up.
  EXPECT_EQ(ContactFormation::parse(" { ( fA2-e1 ,1 ),(eA-f1,1) } ", g), cf);
  EXPECT_EQ(ContactFormation::parse("{(fA1-f1, 1), (fA1-f1, 1)}", g).str(g), "{(fA1-f1, 2)}");
  EXPECT_TRUE(ContactFormation::parse("{}", g).empty());
  // e-e pairs: crossing unless written as touching.
  const ContactFormation touch = ContactFormation::parse("{(eA-e1, 1, touch)}", g);
  EXPECT_EQ(touch.entries().at(0).type, PtcType::EETouch);
  EXPECT_EQ(touch.str(g), "{(eA-e1, 1, touch)}");
  EXPECT_EQ(ContactFormation::parse("{(eA-e1, 1)}", g).entries().at(0).type, PtcType::EECross);
  EXPECT_EQ(ContactFormation::parse(touch.str(g), g), touch);
}

TEST(ContactFormation, EqualFormationsHashEqually) {
  const SceneGeometry& g = example2();
  const ContactFormation a = ContactFormation::parse("{(eA-f1, 1), (fA2-e1, 1)}", g);
  const ContactFormation b = ContactFormation::parse("{(fA2-e1, 1), (eA-f1, 1)}", g);
  const ContactFormation c = ContactFormation::parse("{(fA2-e1, 2), (eA-f1, 1)}", g);
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.hash(), b.hash());
  EXPECT_NE(a, c);
  EXPECT_NE(a.hash(), c.hash());
  EXPECT_TRUE(a < c || c < a);
  EXPECT_FALSE(a < b || b < a);
}

TEST(ContactFormation, MalformedTextIsAUsageErrorNamingThePart) {
  const SceneGeometry& g = example2();
  auto message = [&](const std::string& text) {
    try {
      ContactFormation::parse(text, g);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("{(fX-f1, 1)}").find("\"fX-f1\" is not a pair"), std::string::npos);
  EXPECT_NE(message("{(f1-fA1, 1)}").find("\"f1-fA1\" is not a pair"), std::string::npos);
  EXPECT_NE(message("{(fA1-f1, 0)}").find("multiplicity \"0\""), std::string::npos);
  EXPECT_NE(message("{(fA1-f1, two)}").find("multiplicity \"two\""), std::string::npos);
  EXPECT_NE(message("{(fA1-f1, 1)").find("expected '}'"), std::string::npos);
  EXPECT_NE(message("(fA1-f1, 1)").find("expected '{'"), std::string::npos);
  EXPECT_NE(message("{(fA1-f1, 1, touch)}").find("only e-e pairs"), std::string::npos);
  EXPECT_NE(message("{(fA1-f1, 1)} x").find("unexpected text"), std::string::npos);
}

}  // namespace
}  // namespace pcsg
