// scaled_scene and moved_scene, checked by evaluating transformed points: the transformed
// face must take at the transformed point the value the original took at the original point.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <stdexcept>

#include "engine/poly/parser.h"
#include "engine/scene/scene.h"

namespace pcsg {
namespace {

const std::string kScenes = std::string(PCSG_SOURCE_DIR) + "/scenes/";
// Substitution multiplies out up to fourth powers of coordinates of size ~5: relative round-off
// of a few hundred ulps of the largest term.
constexpr double kRelative = 1e-11;

SceneSpec example_with_seeds() {
  SceneSpec s = load_scene_file(kScenes + "example1.yaml");
  s.auto_seeds = false;
  SeedSpec seed;
  seed.pose.position = {0.5, -1, 6};
  seed.pose.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  s.seeds.push_back(seed);
  return s;
}

// Random points in [-5, 5]^3, the size of the examples; fixed seed for repeatable failures.
std::vector<Eigen::Vector3d> points() {
  std::mt19937 rng(7);
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < 20; ++k) {
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a) p[a] = static_cast<double>(rng()) / 4294967296.0 * 10 - 5;
    out.push_back(p);
  }
  return out;
}

// |a - b| relative to the size of the polynomial's terms at p.
void expect_close(double a, double b, const Polynomial& g, const std::string& what) {
  const double size = g.max_abs_coeff() * 625;  // |p|^4 <= 5^4
  EXPECT_NEAR(a, b, kRelative * size) << what;
}

// The face text is rewritten with the polynomial: reparsing it gives the same g.
void expect_text_matches(const FaceSpec& f) {
  const Polynomial back = parse_inequality(f.text).g;
  for (int n = 0; n < Polynomial::kNumCoeffs; ++n)
    EXPECT_NEAR(back.coeffs()[n], f.g.coeffs()[n], 1e-9 * f.g.max_abs_coeff())
        << f.name << ": \"" << f.text << "\"";  // printed with 10 significant digits
}

TEST(SceneTransform, ScaledSceneScalesBothObjectsAndSeeds) {
  const SceneSpec s = example_with_seeds();
  for (double scale : {2.5, 1e-3, 1e3}) {
    const SceneSpec t = scaled_scene(s, scale);
    ASSERT_EQ(t.B.faces.size(), s.B.faces.size());
    for (const Eigen::Vector3d& p : points()) {
      for (size_t i = 0; i < s.B.faces.size(); ++i)
        expect_close(t.B.faces[i].g.value(scale * p), s.B.faces[i].g.value(p), s.B.faces[i].g,
                     "B." + s.B.faces[i].name);
      expect_close(t.A.faces[0].g.value(scale * p), s.A.faces[0].g.value(p), s.A.faces[0].g,
                   "A.fA");
    }
    // the sphere band of radius 4 becomes radius 4 s
    EXPECT_NEAR(t.B.faces[1].g.value({0, 0, 4 * scale}), 0, kRelative * 16);
    EXPECT_TRUE(t.seeds[0].pose.position.isApprox(s.seeds[0].pose.position * scale, 1e-15));
    EXPECT_TRUE(t.seeds[0].pose.quaternion.isApprox(s.seeds[0].pose.quaternion, 1e-15));
    for (const FaceSpec& f : t.B.faces) expect_text_matches(f);
  }
}

TEST(SceneTransform, ScaledSceneRejectsBadScales) {
  const SceneSpec s = example_with_seeds();
  EXPECT_THROW(scaled_scene(s, 0), std::invalid_argument);
  EXPECT_THROW(scaled_scene(s, -2), std::invalid_argument);
  EXPECT_THROW(scaled_scene(s, NAN), std::invalid_argument);
}

TEST(SceneTransform, MovedSceneMovesBAndTheSeeds) {
  const SceneSpec s = example_with_seeds();
  Pose X;
  X.position = {1.5, -2, 0.25};
  X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(2.1, Eigen::Vector3d(-1, 0.5, 2).normalized()));
  const SceneSpec t = moved_scene(s, X);
  for (const Eigen::Vector3d& p : points()) {
    // B's faces follow B: g'(X p) = g(p)
    for (size_t i = 0; i < s.B.faces.size(); ++i)
      expect_close(t.B.faces[i].g.value(X.apply(p)), s.B.faces[i].g.value(p), s.B.faces[i].g,
                   "B." + s.B.faces[i].name);
    // A's faces are in A's own frame: unchanged
    EXPECT_EQ(t.A.faces[0].g.coeffs(), s.A.faces[0].g.coeffs());
    // a point of A lands where X puts the old place: X_BA' p_A = X (X_BA p_A)
    const Eigen::Vector3d expected = X.apply(s.seeds[0].pose.apply(p));
    EXPECT_TRUE(t.seeds[0].pose.apply(p).isApprox(expected, 1e-14)) << p.transpose();
  }
  EXPECT_GE(t.seeds[0].pose.quaternion.w(), 0) << "canonical";
  for (const FaceSpec& f : t.B.faces) expect_text_matches(f);

  // moving back by X^-1 restores B's faces
  const SceneSpec back = moved_scene(t, X.inverse());
  for (size_t i = 0; i < s.B.faces.size(); ++i)
    for (int n = 0; n < Polynomial::kNumCoeffs; ++n)
      EXPECT_NEAR(back.B.faces[i].g.coeffs()[n], s.B.faces[i].g.coeffs()[n],
                  kRelative * s.B.faces[i].g.max_abs_coeff());
  EXPECT_TRUE(back.seeds[0].pose.position.isApprox(s.seeds[0].pose.position, 1e-14));
}

TEST(SceneTransform, TorusSurvivesScalingAndMotion) {
  // degree 4 faces substitute exactly as quadrics do
  const SceneSpec s = parse_scene(
      "objects:\n"
      "  A: {faces: {fA: \"x^2 + y^2 + z^2 <= 1\"}}\n"
      "  B: {faces: {torus: \"(x^2 + y^2 + z^2 + 3.75)^2 <= 16(x^2 + y^2)\"}}\n",
      "torus.yaml");
  Pose X;
  X.position = {0, 0, 3};
  X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  const SceneSpec t = moved_scene(scaled_scene(s, 2), X);
  // the outer equator point (2.5, 0, 0) goes to 2 * (2.5, 0, 0) = (5, 0, 0), then X keeps x
  EXPECT_NEAR(t.B.faces[0].g.value({5, 0, 3}), 0, kRelative * t.B.faces[0].g.max_abs_coeff() * 1e3);
  // the tube's top (2, 0, 0.5) -> (4, 0, 1) -> rotated about x: (4, -1, 0) + (0, 0, 3)
  EXPECT_NEAR(t.B.faces[0].g.value({4, -1, 3}), 0, kRelative * t.B.faces[0].g.max_abs_coeff() * 1e3);
  EXPECT_EQ(t.B.faces[0].g.degree(), 4);
}

}  // namespace
}  // namespace pcsg
