#include "engine/geometry/solid_extent.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <Eigen/LU>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "engine/geometry/univariate_roots.h"

namespace pcsg {
namespace {

// Directions sampled on the unit sphere: ~0.14 rad apart, so any cone of directions wider than
// that is hit; narrower ones are found by refining around the best samples.
constexpr int kFibonacciDirections = 600;
// A normalised homogeneous value below -this is negative beyond doubt: the values are computed
// to ~1e-15, and the test is dimensionless (each h_i is divided by its largest coefficient).
constexpr double kSignThreshold = 1e-9;
// Directions whose max_i h_i is below this are candidate recession directions worth refining.
constexpr double kCandidateLevel = 0.05;
// A solid that stays inside along a ray for this many times its size is unbounded.
constexpr double kFarFactor = 1e6;
// Ray intervals are capped at this many times the median hit distance for the first box; the
// growing-box check then enlarges it if needed.
constexpr double kCapFactor = 1e3;
// Growing-box check: doublings before the solid is declared unbounded (2^20 ~ 10^6, the same
// factor as kFarFactor), and samples per box side.
constexpr int kMaxDoublings = 20;
constexpr int kBoundarySamples = 24;

std::string vec_str(const Eigen::Vector3d& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
  return buf;
}

std::vector<Eigen::Vector3d> sphere_directions() {
  std::vector<Eigen::Vector3d> dirs;
  // the 26 lattice directions first: axes and diagonals are where degenerate directions of
  // hand-written scenes usually lie
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) dirs.push_back(Eigen::Vector3d(x, y, z).normalized());
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < kFibonacciDirections; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / kFibonacciDirections;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    dirs.emplace_back(r * std::cos(golden * k), r * std::sin(golden * k), z);
  }
  return dirs;
}

bool inside(const std::vector<Polynomial>& gs, const Eigen::Vector3d& p) {
  for (const auto& g : gs)
    if (g.value(p) > 0) return false;
  return true;
}

struct Extent {
  const ObjectSpec& object;
  std::vector<Polynomial> gs;
  std::vector<Polynomial> tops;  // normalised top-degree homogeneous parts

  [[noreturn]] void unbounded(const Eigen::Vector3d& d, const std::string& how) const {
    throw SceneError(object.where, "object " + object.name +
                                       " is unbounded: it extends to infinity along " +
                                       vec_str(d) + " (" + how +
                                       "); pcsg needs bounded objects");
  }

  double top_max(const Eigen::Vector3d& d) const {
    double m = -std::numeric_limits<double>::infinity();
    for (const auto& h : tops) m = std::max(m, h.value(d));
    return m;
  }

  // Compass search on the sphere for a local minimum of max_i h_i, from d.
  Eigen::Vector3d refine_direction(Eigen::Vector3d d) const {
    double best = top_max(d);
    for (double step = 0.1; step > 1e-10;) {
      const Eigen::Vector3d ref = std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX()
                                                        : Eigen::Vector3d::UnitY();
      const Eigen::Vector3d u = d.cross(ref).normalized(), v = d.cross(u);
      bool improved = false;
      for (const Eigen::Vector3d& e : {u, Eigen::Vector3d(-u), v, Eigen::Vector3d(-v)}) {
        const Eigen::Vector3d c = (d + step * e).normalized();
        const double m = top_max(c);
        if (m < best) {
          best = m;
          d = c;
          improved = true;
          break;
        }
      }
      if (!improved) step *= 0.5;
    }
    return d;
  }

  // Sorted parameters t >= 0 of [o + t d] where the solid's inside/outside status may change.
  // Returns the inside intervals (t0, t1); t1 is infinite for a ray that ends inside.
  std::vector<std::pair<double, double>> inside_intervals(const Eigen::Vector3d& o,
                                                          const Eigen::Vector3d& d) const {
    std::vector<std::array<double, 5>> qs;
    std::vector<double> breaks{0.0};
    for (const auto& g : gs) {
      qs.push_back(g.along_line(o, d));
      for (double t : real_roots(qs.back()))
        if (t > 0) breaks.push_back(t);
    }
    std::sort(breaks.begin(), breaks.end());
    auto in = [&](double t) {
      for (const auto& q : qs)
        if (evaluate_univariate(q, t) > 0) return false;
      return true;
    };
    auto tail_in = [&]() {  // beyond every root: the sign of each leading coefficient
      for (const auto& q : qs) {
        int n = 4;
        while (n >= 0 && q[n] == 0.0) --n;
        if (n >= 0 && q[n] > 0) return false;
      }
      return true;
    };
    std::vector<std::pair<double, double>> out;
    for (std::size_t k = 0; k < breaks.size(); ++k) {
      const bool last = k + 1 == breaks.size();
      const bool is_in = last ? tail_in() : in(0.5 * (breaks[k] + breaks[k + 1]));
      if (!is_in) continue;
      const double t1 = last ? std::numeric_limits<double>::infinity() : breaks[k + 1];
      if (!out.empty() && out.back().second == breaks[k])
        out.back().second = t1;
      else
        out.emplace_back(breaks[k], t1);
    }
    return out;
  }

  // The box; `thickness` as SolidExtent::thickness.
  Eigen::AlignedBox3d run(double* thickness) const {
    const std::vector<Eigen::Vector3d> dirs = sphere_directions();
    // (1) a direction where every top-degree part is negative: a ray that ends inside
    std::vector<double> m(dirs.size());
    for (std::size_t k = 0; k < dirs.size(); ++k) m[k] = top_max(dirs[k]);
    const std::size_t kmin = std::min_element(m.begin(), m.end()) - m.begin();
    if (m[kmin] < kCandidateLevel) {
      const Eigen::Vector3d d = refine_direction(dirs[kmin]);
      if (top_max(d) < -kSignThreshold) unbounded(d, "every inequality's top-degree part is "
                                                     "negative there");
    }
    // ray origins: the frame origin and the centre of each face (one Newton step on grad g)
    std::vector<Eigen::Vector3d> origins{Eigen::Vector3d::Zero()};
    for (const auto& g : gs) {
      Eigen::Vector3d grad;
      Eigen::Matrix3d H;
      g.evaluate(Eigen::Vector3d::Zero(), nullptr, &grad, &H);
      Eigen::FullPivLU<Eigen::Matrix3d> lu(H);
      if (!lu.isInvertible()) continue;
      const Eigen::Vector3d c = -lu.solve(grad);
      if (c.allFinite() && (c - origins.back()).norm() > 0) origins.push_back(c);
    }
    // cast rays: inside intervals give exact boundary points and points inside the solid
    std::vector<Eigen::Vector3d> hits, inner;
    std::vector<double> dist;
    double deepest = 0;  // largest over inside origins of the shortest exit
    for (const auto& o : origins) {
      double exit = std::numeric_limits<double>::infinity();
      for (const auto& d : dirs)
        for (const auto& [t0, t1] : inside_intervals(o, d)) {
          if (!std::isfinite(t1)) unbounded(d, "a ray from " + vec_str(o) + " ends inside");
          if (t1 - t0 <= 0) continue;
          hits.push_back(o + t0 * d);
          hits.push_back(o + t1 * d);
          inner.push_back(o + 0.5 * (t0 + t1) * d);
          dist.push_back(t1);
          if (t0 == 0) exit = std::min(exit, t1);
        }
      if (std::isfinite(exit) && inside(gs, o)) deepest = std::max(deepest, exit);
    }
    // the chords' midpoints' centroid: central in a convex solid, where the frame's origin
    // and the surfaces' centres can lie on the boundary (three spheres through each other's
    // centres)
    if (!inner.empty()) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (const auto& p : inner) centre += p;
      centre /= static_cast<double>(inner.size());
      if (inside(gs, centre)) {
        double exit = std::numeric_limits<double>::infinity();
        for (const auto& d : dirs)
          for (const auto& [t0, t1] : inside_intervals(centre, d))
            if (t0 == 0) exit = std::min(exit, t1);
        if (std::isfinite(exit)) deepest = std::max(deepest, exit);
      }
    }
    *thickness = deepest > 0 ? 2 * deepest : std::numeric_limits<double>::infinity();
    if (inner.empty())
      throw SceneError(object.where, "object " + object.name +
                                         " is empty: no point satisfies all of its "
                                         "inequalities");
    std::nth_element(dist.begin(), dist.begin() + dist.size() / 2, dist.end());
    const double scale = dist[dist.size() / 2];
    // (2) directions where the top-degree parts vanish: follow them from inside points
    std::vector<Eigen::Vector3d> tried;
    for (std::size_t k = 0; k < dirs.size(); ++k) {
      if (m[k] >= kCandidateLevel) continue;
      bool near = false;
      for (const auto& t : tried) near = near || t.dot(dirs[k]) > std::cos(0.3);
      if (near) continue;
      tried.push_back(dirs[k]);
      const Eigen::Vector3d d = refine_direction(dirs[k]);
      if (top_max(d) > kSignThreshold) continue;
      for (std::size_t j = 0; j < inner.size(); j += std::max<std::size_t>(1, inner.size() / 16))
        for (const auto& [t0, t1] : inside_intervals(inner[j], d))
          if (t0 == 0 && t1 > kFarFactor * scale)
            unbounded(d, "the solid stays inside along it for over 10^6 times its size");
    }
    // (3) growing-box check, from the box of the hits (intervals capped at a large multiple
    // of the typical size, so a slender but bounded tail does not inflate the first box)
    Eigen::AlignedBox3d box;
    for (const auto& p : hits)
      if (p.norm() <= kCapFactor * scale + origins.back().norm()) box.extend(p);
    for (const auto& p : inner) box.extend(p);
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(0.05 * box.diagonal().norm());
    box = Eigen::AlignedBox3d(box.min() - pad, box.max() + pad);
    for (int doubling = 0;; ++doubling) {
      const auto crossing = boundary_crossing(box);
      if (!crossing) return box;
      if (doubling == kMaxDoublings)
        unbounded((*crossing - box.center()).normalized(),
                  "it crosses the boundary of every box up to 10^6 times its size");
      const Eigen::Vector3d half = box.sizes();  // doubles each side about the centre
      box = Eigen::AlignedBox3d(box.center() - half, box.center() + half);
    }
  }

  // A point of the solid on the box's boundary, sampled on a grid per side.
  std::optional<Eigen::Vector3d> boundary_crossing(const Eigen::AlignedBox3d& box) const {
    const int n = kBoundarySamples;
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
        for (int a = 0; a <= n; ++a)
          for (int b = 0; b <= n; ++b) {
            Eigen::Vector3d p;
            p[axis] = side ? box.max()[axis] : box.min()[axis];
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            p[u] = box.min()[u] + box.sizes()[u] * a / n;
            p[v] = box.min()[v] + box.sizes()[v] * b / n;
            if (inside(gs, p)) return p;
          }
    return std::nullopt;
  }
};

}  // namespace

Eigen::AlignedBox3d solid_box_estimate(const ObjectSpec& object) {
  return solid_extent(object).box;
}

SolidExtent solid_extent(const ObjectSpec& object) {
  Extent e{object, {}, {}};
  for (const auto& f : object.faces) {
    const int deg = f.g.degree();
    if (deg <= 0) {
      // a constant inequality: always true (no constraint) or never (nothing is inside)
      if (f.g.coeff(0, 0, 0) > 0)
        throw SceneError(f.where, "face " + f.name + " ('" + f.text +
                                      "') holds nowhere, so object " + object.name +
                                      " is empty");
      continue;
    }
    e.gs.push_back(f.g);
    const Polynomial h = f.g.homogeneous_part(deg);
    e.tops.push_back(h * (1.0 / h.max_abs_coeff()));
  }
  if (e.gs.empty())
    throw SceneError(object.where, "object " + object.name +
                                       " has no non-constant inequality: it is all of space, "
                                       "which is unbounded");
  SolidExtent out;
  out.box = e.run(&out.thickness);
  return out;
}

}  // namespace pcsg
