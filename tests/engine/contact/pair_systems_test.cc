// The pair systems' Jacobians against central differences, and their residual-only evaluation
// (the Newton solver's trials) against the full one, bit for bit, for every PtC type with
// unknowns: the three-sphere lens (faces, edges, vertices) over the bowl-topped body, and the
// same scene with A and B swapped (so that B has the vertices).
#include "engine/contact/pair_systems.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"
#include "engine/scene/scene_swap.h"

namespace pcsg {
namespace {

// Central differences with a step of 1e-6 of each unknown's scale on the dimensionless system
// (rows and unknowns in units of L): truncation ~1e-12, round-off ~1e-10; a wrong term of a
// formula is O(1), so 1e-6 separates the two by four orders either way.
constexpr double kFdStep = 1e-6;
constexpr double kFdTolerance = 1e-6;
// Starts within a tenth of L of an element's point: near enough that the jets are those of the
// contact's neighbourhood, far enough that no term vanishes by symmetry.
constexpr double kSpread = 0.1;

struct Scenes {
  SceneGeometry lens_over_bowl, bowl_over_lens;
};

const Scenes& scenes() {
  static const Scenes s = [] {
    const SceneSpec spec =
        load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/three_spheres.yaml");
    return Scenes{build_scene_geometry(spec), build_scene_geometry(swap_objects(spec))};
  }();
  return s;
}

std::vector<ElementId> elements_of(const Solid& s) {
  std::vector<ElementId> out;
  for (size_t i = 0; i < s.faces.size(); ++i) out.push_back({ElementKind::Face, int(i)});
  for (size_t i = 0; i < s.edges.size(); ++i) out.push_back({ElementKind::Edge, int(i)});
  for (size_t i = 0; i < s.vertices.size(); ++i) out.push_back({ElementKind::Vertex, int(i)});
  return out;
}

Eigen::Vector3d point_of(const Solid& s, ElementId id) {
  switch (id.kind) {
    case ElementKind::Face:
      return s.faces[id.index].interior_point;
    case ElementKind::Edge:
      return s.edges[id.index].samples[0].point;
    case ElementKind::Vertex:
      return s.vertices[id.index].point;
  }
  return Eigen::Vector3d::Zero();
}

// A pose of A a little above B's dish, turned so that no axis is special.
Pose above(const SceneGeometry& scene) {
  Pose X;
  X.quaternion = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  X.position = Eigen::Vector3d(0.3, -0.2, 0.5) * scene.tol.length_scale;
  return X;
}

// Calls `check(system, z, name, L)` at several starts near each element pair with unknowns.
template <typename Check>
void for_each_pair_system(Check&& check) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int systems = 0;
  std::set<PtcType> types;
  for (const SceneGeometry* scene : {&scenes().lens_over_bowl, &scenes().bowl_over_lens}) {
    const double L = scene->tol.length_scale;
    const Pose X = above(*scene);
    for (ElementId a : elements_of(scene->A))
      for (ElementId b : elements_of(scene->B)) {
        const PtcType type = ptc_type_between(a.kind, b.kind);
        if (type == PtcType::VV) continue;  // no unknowns
        const PairSystem system(PairSetup::make(*scene, X, a, b), type);
        const std::string name = scene->A.element_name(a) + "-" + scene->B.element_name(b);
        for (int k = 0; k < 4; ++k) {
          const Eigen::Vector3d dA(u(rng), u(rng), u(rng)), dB(u(rng), u(rng), u(rng));
          SmallVector z = system.initial(point_of(scene->A, a) + kSpread * L * dA,
                                         point_of(scene->B, b) + kSpread * L * dB);
          // The gap and the normals' ratio away from their starting values too.
          if (type == PtcType::FF) z[7] = 1 + 0.1 * u(rng);
          check(system, z, name + " start " + std::to_string(k), L);
          ++systems;
        }
        types.insert(type);
      }
  }
  // Every type with unknowns was met (e-e-touch is pair_touch.h's, v-v has none).
  EXPECT_EQ(types.size(), 8u);
  EXPECT_GT(systems, 100);
}

bool same_bits(const SmallVector& x, const SmallVector& y) {
  return x.size() == y.size() &&
         std::memcmp(x.data(), y.data(), sizeof(double) * static_cast<size_t>(x.size())) == 0;
}

TEST(PairSystems, ResidualAloneIsTheFullEvaluationsBits) {
  for_each_pair_system(
      [](const PairSystem& system, const SmallVector& z, const std::string& at, double) {
        SmallVector F, rs, F_alone, rs_alone;
        SmallMatrix J;
        system.evaluate(z, F, J, rs);
        system.evaluate_residual(z, F_alone, rs_alone);
        EXPECT_TRUE(same_bits(F, F_alone))
            << at << ": F " << F.transpose() << " vs " << F_alone.transpose();
        EXPECT_TRUE(same_bits(rs, rs_alone)) << at << ": row scales";
      });
}

TEST(PairSystems, JacobiansMatchCentralDifferences) {
  for_each_pair_system(
      [](const PairSystem& system, const SmallVector& z, const std::string& at, double L) {
        const int n = system.size();
        SmallVector F, rs, cs;
        SmallMatrix J;
        system.evaluate(z, F, J, rs);
        system.unknown_scales(cs);
        // Compared dimensionless: row i times rs_i, column j times the unknown's scale cs_j.
        for (int j = 0; j < n; ++j) {
          const double h = kFdStep * cs[j];
          SmallVector zp = z, zm = z, Fp, Fm, rs_unused;
          zp[j] += h;
          zm[j] -= h;
          system.evaluate_residual(zp, Fp, rs_unused);
          system.evaluate_residual(zm, Fm, rs_unused);
          for (int i = 0; i < n; ++i) {
            const double units = rs[i] * cs[j] / L;
            const double fd = (Fp[i] - Fm[i]) / (2 * h) * units, an = J(i, j) * units;
            EXPECT_NEAR(fd, an, kFdTolerance * std::max(1.0, std::abs(an)))
                << at << ": dF" << i << "/dz" << j;
          }
        }
      });
}

}  // namespace
}  // namespace pcsg
