#include "render/label_anchors.h"

#include <algorithm>
#include <limits>
#include <map>

namespace pcsg::render {

namespace {

// Candidates per element: enough alternatives for the layout to dodge a crowded spot.
constexpr std::size_t kMaxAnchors = 4;
// Alternative anchors must be this far (image pixels) from the ones already chosen, else they
// would offer the layout nothing new.
constexpr double kAnchorSeparationPx = 40;
// Face alternatives must be at least this share of the best one's depth inside the region.
constexpr double kInteriorShare = 0.5;
// Chamfer distance weights (3-4 metric: within 8% of Euclidean, integer arithmetic).
constexpr int kStraight = 3, kDiagonal = 4;

// For each pixel, the chamfer distance to the nearest pixel of a different id (or the border).
std::vector<int> interior_distance(const IdImage& ids) {
  const int w = ids.width, h = ids.height;
  const int inf = std::numeric_limits<int>::max() / 2;
  std::vector<int> d(static_cast<std::size_t>(w) * h, inf);
  auto at = [&](int x, int y) -> int& { return d[static_cast<std::size_t>(y) * w + x]; };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::int32_t id = ids.at(x, y);
      const bool border = x == 0 || y == 0 || x == w - 1 || y == h - 1 || ids.at(x - 1, y) != id ||
                          ids.at(x + 1, y) != id || ids.at(x, y - 1) != id ||
                          ids.at(x, y + 1) != id;
      if (border) at(x, y) = 0;
    }
  }
  for (int y = 0; y < h; ++y) {  // forward pass
    for (int x = 0; x < w; ++x) {
      int& v = at(x, y);
      if (x > 0) v = std::min(v, at(x - 1, y) + kStraight);
      if (y > 0) {
        v = std::min(v, at(x, y - 1) + kStraight);
        if (x > 0) v = std::min(v, at(x - 1, y - 1) + kDiagonal);
        if (x < w - 1) v = std::min(v, at(x + 1, y - 1) + kDiagonal);
      }
    }
  }
  for (int y = h - 1; y >= 0; --y) {  // backward pass
    for (int x = w - 1; x >= 0; --x) {
      int& v = at(x, y);
      if (x < w - 1) v = std::min(v, at(x + 1, y) + kStraight);
      if (y < h - 1) {
        v = std::min(v, at(x, y + 1) + kStraight);
        if (x < w - 1) v = std::min(v, at(x + 1, y + 1) + kDiagonal);
        if (x > 0) v = std::min(v, at(x - 1, y + 1) + kDiagonal);
      }
    }
  }
  return d;
}

// Greedy farthest-point choice: the first point, then repeatedly the one farthest from those
// chosen, while it is at least kAnchorSeparationPx away.
std::vector<Eigen::Vector2d> spread(const std::vector<Eigen::Vector2d>& ordered) {
  std::vector<Eigen::Vector2d> chosen;
  if (ordered.empty()) return chosen;
  chosen.push_back(ordered.front());
  while (chosen.size() < kMaxAnchors) {
    double best = -1;
    std::size_t best_i = 0;
    for (std::size_t i = 0; i < ordered.size(); ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& c : chosen) nearest = std::min(nearest, (ordered[i] - c).norm());
      if (nearest > best) {
        best = nearest;
        best_i = i;
      }
    }
    if (best < kAnchorSeparationPx) break;
    chosen.push_back(ordered[best_i]);
  }
  return chosen;
}

bool on_image(const Eigen::Vector2d& p, const CameraView& view) {
  return p.x() >= 0 && p.y() >= 0 && p.x() < view.width && p.y() < view.height;
}

// Is the id `id` within one id pixel of the image point p?
bool visible_near(const IdImage& ids, const Eigen::Vector2d& p, std::int32_t id) {
  const int cx = static_cast<int>(p.x() / ids.scale), cy = static_cast<int>(p.y() / ids.scale);
  for (int y = cy - 1; y <= cy + 1; ++y) {
    for (int x = cx - 1; x <= cx + 1; ++x) {
      if (x >= 0 && y >= 0 && x < ids.width && y < ids.height && ids.at(x, y) == id) return true;
    }
  }
  return false;
}

}  // namespace

std::vector<std::vector<Eigen::Vector2d>> find_label_anchors(
    const IdImage& ids, const CameraView& view, const std::vector<ElementSamples>& elements) {
  std::vector<std::vector<Eigen::Vector2d>> result(elements.size());
  const std::vector<int> depth_in = interior_distance(ids);

  // visible pixels of every id, and the centre of everything drawn
  std::map<std::int32_t, std::vector<std::size_t>> pixels_of;
  Eigen::Vector2d centre(0.5 * view.width, 0.5 * view.height);
  double covered = 0;
  Eigen::Vector2d sum(0, 0);
  for (std::size_t i = 0; i < ids.ids.size(); ++i) {
    const std::int32_t id = ids.ids[i];
    if (id == element_id::kBackground) continue;
    pixels_of[id].push_back(i);
    sum += Eigen::Vector2d(static_cast<double>(i % ids.width), static_cast<double>(i / ids.width));
    covered += 1;
  }
  if (covered > 0) centre = (sum / covered + Eigen::Vector2d(0.5, 0.5)) * ids.scale;
  auto to_image = [&](std::size_t i) {
    return Eigen::Vector2d((static_cast<double>(i % ids.width) + 0.5) * ids.scale,
                           (static_cast<double>(i / ids.width) + 0.5) * ids.scale);
  };

  for (std::size_t e = 0; e < elements.size(); ++e) {
    const SceneElement& el = elements[e].element;
    const std::int32_t id = element_id::encode(el);
    std::vector<Eigen::Vector2d> ordered;

    if (el.element.kind == ElementKind::Face) {
      auto it = pixels_of.find(id);
      if (it != pixels_of.end()) {
        // deepest interior pixels first (ties: image order, for determinism)
        std::vector<std::size_t> px = it->second;
        std::stable_sort(px.begin(), px.end(),
                         [&](std::size_t a, std::size_t b) { return depth_in[a] > depth_in[b]; });
        const int deepest = depth_in[px.front()];
        for (std::size_t i : px) {
          if (depth_in[i] < kInteriorShare * deepest) break;
          ordered.push_back(to_image(i));
        }
      }
    } else {
      // curve or vertex points where the element's own id shows, outermost first
      for (const auto& p_W : elements[e].points_W) {
        const Eigen::Vector2d p = view.project(p_W);
        if (on_image(p, view) && visible_near(ids, p, id)) ordered.push_back(p);
      }
      std::stable_sort(ordered.begin(), ordered.end(), [&](const auto& a, const auto& b) {
        return (a - centre).squaredNorm() > (b - centre).squaredNorm();
      });
    }

    if (ordered.empty()) {
      // hidden everywhere (behind other surfaces, which are transparent): the on-screen sample
      // nearest to the eye still shows through them
      const Eigen::Vector3d* nearest = nullptr;
      for (const auto& p_W : elements[e].points_W) {
        if (!on_image(view.project(p_W), view)) continue;
        if (nearest == nullptr || view.depth(p_W) < view.depth(*nearest)) nearest = &p_W;
      }
      if (nearest != nullptr) ordered.push_back(view.project(*nearest));
    }
    result[e] = spread(ordered);
  }
  return result;
}

}  // namespace pcsg::render
