// Straight-segment detection on analytic surfaces: ruled ones must be caught from a handful of
// points, strictly curved ones never, at any scale and position.
#include "engine/geometry/straight_line.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>

#include "engine/poly/parser.h"
#include "engine/scene/scene.h"

namespace pcsg {
namespace {

const Eigen::AlignedBox3d kBox(Eigen::Vector3d(-3, -3, -3), Eigen::Vector3d(3, 3, 3));
const double kL = 6 * std::sqrt(3.0);  // the box diagonal
// "A handful of points": ruled surfaces must be found from these few.
constexpr int kFewPoints = 5;
// Curved surfaces are checked at many points, so that hyperbolic and parabolic regions (torus)
// are visited too.
constexpr int kManyPoints = 200;

Polynomial P(const std::string& text) { return parse_polynomial(text); }

// g seen through x -> s R x + t: a rotated, moved, scaled copy of the same surface.
Polynomial moved(const Polynomial& g, double s, const Eigen::Vector3d& t) {
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  // h(x) = g(R^T (x - t) / s)
  return g.substituted(R.transpose() / s, -R.transpose() * t / s);
}

std::optional<StraightLineWitness> detect(const Polynomial& g, const Eigen::AlignedBox3d& box,
                                          double L, int n) {
  const std::vector<Eigen::Vector3d> pts = sample_surface(g, box, n, 42);
  EXPECT_GE(static_cast<int>(pts.size()), std::min(n, kFewPoints)) << "too few samples of "
                                                                  << g.str();
  return find_straight_line(g, pts, L);
}

// The witness line really lies on the surface over a length L on both sides.
void expect_on_surface(const Polynomial& g, const StraightLineWitness& w, double L) {
  EXPECT_NEAR(w.direction.norm(), 1, 1e-12);
  EXPECT_LE(w.residual, Tolerances{}.straight_line_relative);
  for (double t : {-1.0, -0.3, 0.6, 1.0}) {
    const Eigen::Vector3d q = w.point + t * L * w.direction;
    // distance estimate |g| / |grad g| at the line's points, relative to L
    const double gn = g.gradient(q).norm();
    if (gn > 0) {
      EXPECT_LT(std::abs(g.value(q)) / gn, 1e-8 * L) << g.str() << " at t=" << t;
    }
  }
}

const char* const kRuled[] = {
    "x + 2y - z - 1",     // plane
    "x^2 + y^2 - 1",      // circular cylinder
    "4x^2 + 9y^2 - 9",    // elliptic cylinder
    "x^2 - y",            // parabolic cylinder
    "x^2 + y^2 - z^2",    // cone (apex at the origin, never sampled exactly)
    "x^2 + y^2 - z^2 - 1",  // one-sheet hyperboloid
    "z - xy",             // hyperbolic paraboloid
    "x^2 - y^2 - z",      // hyperbolic paraboloid, other form
    "x^4 + y^4 - 1",      // a quartic cylinder: ruled though not a quadric
    "z(x^2 + y^2) - 2xy",  // Pluecker's conoid (cubic): horizontal lines through the z-axis
};

const char* const kCurved[] = {
    "x^2 + y^2 + z^2 - 4",                    // sphere
    "225x^2 + 100y^2 + 36z^2 - 225",          // the paper's ellipsoid
    "x^2 + y^2 - z",                          // elliptic paraboloid
    "x^2 + y^2 - z^2 + 1",                    // two-sheet hyperboloid
    "(x^2 + y^2 + z^2 + 3.75)^2 - 16(x^2 + y^2)",  // torus R = 2, r = 0.5
    "(x^2 + y^2 + z^2 + 1.75)^2 - 9(x^2 + y^2)",   // torus R = 1.5, r = 1
    "x^4 + y^4 + z^4 - 1",                    // superellipsoid (flat points at the poles)
};

TEST(StraightLine, RuledSurfacesAreDetected) {
  for (const char* text : kRuled) {
    const Polynomial g = P(text);
    const auto w = detect(g, kBox, kL, kFewPoints);
    ASSERT_TRUE(w.has_value()) << text;
    expect_on_surface(g, *w, kL);
  }
}

TEST(StraightLine, CurvedSurfacesAreNotDetected) {
  for (const char* text : kCurved) {
    const auto w = detect(P(text), kBox, kL, kManyPoints);
    EXPECT_FALSE(w.has_value()) << text << ": line at " << w->point.transpose() << " along "
                                << w->direction.transpose() << ", residual " << w->residual;
  }
}

TEST(StraightLine, TorusSaddleAndParabolicPointsAreCurved) {
  // the inner equator is hyperbolic (two asymptotic directions), the top circle parabolic
  // (one, along the circle): candidates exist there, and the cubic/quartic terms reject them
  const Polynomial torus = P("(x^2 + y^2 + z^2 + 3.75)^2 - 16(x^2 + y^2)");
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(1.5, 0, 0), Eigen::Vector3d(0, -1.5, 0),
                                   Eigen::Vector3d(2, 0, 0.5), Eigen::Vector3d(0, 2, -0.5)}) {
    ASSERT_NEAR(torus.value(p), 0, 1e-12);
    EXPECT_FALSE(find_straight_line(torus, {p}, kL).has_value()) << p.transpose();
  }
}

TEST(StraightLine, PaperFacesAreStrictlyCurved) {
  for (const char* file : {"example1.yaml", "example2.yaml"}) {
    const SceneSpec s = load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/" + file);
    const Eigen::AlignedBox3d box(Eigen::Vector3d(-5, -5, -5), Eigen::Vector3d(5, 5, 5));
    for (const ObjectSpec* o : {&s.A, &s.B})
      for (const FaceSpec& f : o->faces)
        EXPECT_FALSE(detect(f.g, box, 10 * std::sqrt(3.0), kManyPoints).has_value())
            << file << " " << o->name << "." << f.name;
  }
}

TEST(StraightLine, ScaleAndPlacementInvariant) {
  // the same surfaces at scales 1e-3 .. 1e3, rotated and moved, with g multiplied by 1e6:
  // the answers must not change
  for (double s : {1e-3, 1.0, 1e3}) {
    const Eigen::Vector3d t = Eigen::Vector3d(0.3, -0.2, 0.1) * s;
    const Eigen::AlignedBox3d box(kBox.min() * s + t, kBox.max() * s + t);
    for (const char* text : kRuled) {
      const Polynomial g = moved(P(text), s, t) * 1e6;
      const auto w = detect(g, box, kL * s, kFewPoints);
      ASSERT_TRUE(w.has_value()) << text << " at scale " << s;
      expect_on_surface(g, *w, kL * s);
    }
    for (const char* text : kCurved) {
      const auto w = detect(moved(P(text), s, t) * 1e-6, box, kL * s, kManyPoints / 4);
      EXPECT_FALSE(w.has_value()) << text << " at scale " << s << ", residual " << w->residual;
    }
  }
}

TEST(StraightLine, SingularPointsAreSkipped) {
  // the cone's apex has no tangent plane; nothing to decide there
  EXPECT_FALSE(find_straight_line(P("x^2 + y^2 - z^2"), {Eigen::Vector3d::Zero()}, 1.0));
  EXPECT_FALSE(find_straight_line(P("x^2 + y^2 - z^2"), {}, 1.0));
}

TEST(StraightLine, SampleSurfaceIsDeterministicAndOnTheSurface) {
  const Polynomial g = P("(x^2 + y^2 + z^2 + 3.75)^2 - 16(x^2 + y^2)");
  const auto a = sample_surface(g, kBox, 30, 5);
  const auto b = sample_surface(g, kBox, 30, 5);
  const auto c = sample_surface(g, kBox, 30, 6);
  ASSERT_EQ(a.size(), 30u);
  ASSERT_EQ(b.size(), a.size());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k], b[k]) << "same seed, same points";
    EXPECT_TRUE(kBox.contains(a[k]));
    // on the surface to the solve tolerance (distance estimate |g| / |grad g|)
    EXPECT_LE(std::abs(g.value(a[k])) / g.gradient(a[k]).norm(),
              Tolerances::for_length_scale(kL).solve_residual);
  }
  EXPECT_NE(a[0], c[0]) << "another seed, other points";
  // a surface outside the box gives no points, and n <= 0 none either
  EXPECT_TRUE(sample_surface(P("x^2 + y^2 + z^2 - 100"), kBox, 10, 1).empty());
  EXPECT_TRUE(sample_surface(g, kBox, 0, 1).empty());
}

}  // namespace
}  // namespace pcsg
