#include "render/annotations.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "render/label_layout.h"
#include "render/palette.h"

namespace pcsg::render {

namespace {

// Sizes in pixels at the reference height of 960, scaled with the image (Overlay::ui_scale).
constexpr float kMargin = 16;        // header offset from the image corner
constexpr float kHeaderLineGap = 6;  // between the title and the subtitle
constexpr float kLabelPadX = 7, kLabelPadY = 3;
constexpr float kLabelRounding = 4;
constexpr float kLabelBorder = 1.5f;
constexpr float kLeaderWidth = 1.4f;
constexpr float kAnchorDot = 3.2f;
constexpr float kMarkerRadius = 6.5f;
constexpr float kMarkerRing = 2.0f;
constexpr float kNormalWidth = 2.2f;
constexpr float kArrowHead = 10;
// Contact normals are drawn this long, as a share of the scene's size (larger bbox diagonal).
constexpr double kNormalLengthShare = 0.08;
// Label fill: the element's colour this far toward white, so that dark text stays readable.
constexpr float kLabelFillLightening = 0.72f;
// Label border: the element's colour this far toward black.
constexpr float kLabelBorderDarkening = 0.35f;
// Same units as kMargin: the header's nominal height at the reference size (title + gap +
// subtitle + margins), used before fonts are known to keep the objects out of it.
constexpr double kHeaderNominal = 2 * kMargin + 23 + kHeaderLineGap + 19;
constexpr double kReferenceHeight = 960;

const Solid& solid_of(const SceneGeometry& s, Object o) { return o == Object::A ? s.A : s.B; }

bool is_highlighted(const FrameRequest& f, const SceneElement& e) {
  return std::find(f.highlighted.begin(), f.highlighted.end(), e) != f.highlighted.end();
}

const std::string& element_name(const SceneGeometry& s, const SceneElement& e) {
  const Solid& solid = solid_of(s, e.object);
  switch (e.element.kind) {
    case ElementKind::Face:
      return solid.faces[e.element.index].name;
    case ElementKind::Edge:
      return solid.edges[e.element.index].name;
    case ElementKind::Vertex:
      return solid.vertices[e.element.index].name;
  }
  return solid.name;
}

ImVec2 iv(const Eigen::Vector2d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y())};
}

Box draw_header(Overlay& overlay, const FrameRequest& f, float s) {
  ImDrawList& dl = overlay.draw_list();
  float y = kMargin * s;
  float right = kMargin * s;
  const unsigned text = palette::kText.packed();
  if (!f.title.empty()) {
    dl.AddText(overlay.font(FontRole::Title), overlay.font_size(FontRole::Title),
               ImVec2(kMargin * s, y), text, f.title.c_str());
    right = std::max(right, kMargin * s + overlay.text_size(FontRole::Title, f.title).x);
    y += overlay.font_size(FontRole::Title) + kHeaderLineGap * s;
  }
  if (!f.subtitle.empty()) {
    dl.AddText(overlay.font(FontRole::Subtitle), overlay.font_size(FontRole::Subtitle),
               ImVec2(kMargin * s, y), palette::kLeader.packed(), f.subtitle.c_str());
    right = std::max(right, kMargin * s + overlay.text_size(FontRole::Subtitle, f.subtitle).x);
    y += overlay.font_size(FontRole::Subtitle);
  }
  return Box{0, 0, right + kMargin * s, y + 0.5 * kMargin * s};
}

// Contact markers (and normals) and highlighted vertices; returns the boxes labels must keep
// clear of.
std::vector<Box> draw_contacts(Overlay& overlay, const AnnotationInput& in, float s) {
  ImDrawList& dl = overlay.draw_list();
  std::vector<Box> boxes;
  const double normal_length = kNormalLengthShare * in.scene->tol.length_scale;
  for (const PointContact& c : in.frame->contacts) {
    const Eigen::Vector2d p = in.view->project(c.point_B);
    if (in.frame->show_normals && c.normal_B.norm() > 0) {
      const Eigen::Vector2d q =
          in.view->project(c.point_B + normal_length * c.normal_B.normalized());
      const Eigen::Vector2d d = q - p;
      if (d.norm() > kArrowHead * s) {
        const Eigen::Vector2d u = d.normalized(), side(-u.y(), u.x());
        const Eigen::Vector2d base = q - kArrowHead * s * u;
        dl.AddLine(iv(p), iv(base), palette::kContact.packed(), kNormalWidth * s);
        dl.AddTriangleFilled(iv(q), iv(base + 0.45 * kArrowHead * s * side),
                             iv(base - 0.45 * kArrowHead * s * side), palette::kContact.packed());
      }
      boxes.push_back(Box{std::min(p.x(), q.x()), std::min(p.y(), q.y()), std::max(p.x(), q.x()),
                          std::max(p.y(), q.y())});
    }
    dl.AddCircleFilled(iv(p), (kMarkerRadius + kMarkerRing) * s, palette::kBackground.packed());
    dl.AddCircleFilled(iv(p), kMarkerRadius * s, palette::kContact.packed());
    dl.AddCircle(iv(p), (kMarkerRadius + kMarkerRing) * s, palette::kText.packed(0.8f), 0, 1.f * s);
    const double r = (kMarkerRadius + kMarkerRing + 2) * s;
    boxes.push_back(Box{p.x() - r, p.y() - r, p.x() + r, p.y() + r});
  }
  // highlighted vertices (a vertex has no surface or line to colour): a warning ring
  for (const SceneElement& e : in.frame->highlighted) {
    if (e.element.kind != ElementKind::Vertex) continue;
    const Solid& solid = solid_of(*in.scene, e.object);
    if (e.element.index < 0 || e.element.index >= static_cast<int>(solid.vertices.size())) continue;
    const Eigen::Vector3d& p_own = solid.vertices[e.element.index].point;
    const Eigen::Vector2d p =
        in.view->project(e.object == Object::A ? in.X_WA.apply(p_own) : p_own);
    dl.AddCircle(iv(p), kMarkerRadius * s, palette::kWarning.packed(), 0, 2.5f * s);
    const double r = (kMarkerRadius + 2) * s;
    boxes.push_back(Box{p.x() - r, p.y() - r, p.x() + r, p.y() + r});
  }
  return boxes;
}

void draw_labels(Overlay& overlay, const AnnotationInput& in, std::vector<Box> obstacles, float s) {
  const SceneGeometry& scene = *in.scene;
  const auto anchors = find_label_anchors(*in.ids, *in.view, *in.samples);

  std::vector<LabelRequest> requests(in.samples->size());
  for (std::size_t i = 0; i < requests.size(); ++i) {
    const ImVec2 t =
        overlay.text_size(FontRole::Label, element_name(scene, (*in.samples)[i].element));
    requests[i].size = Eigen::Vector2d(t.x + 2 * kLabelPadX * s, t.y + 2 * kLabelPadY * s);
    requests[i].anchors = anchors[i];
  }

  // the coverage mask: labels prefer boxes over the white background
  std::vector<char> mask(in.ids->ids.size());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = in.ids->ids[i] != element_id::kBackground;
  const CoverageMap coverage(in.ids->width, in.ids->height, in.ids->scale, mask);

  LabelLayoutOptions options;
  options.width = in.view->width;
  options.height = in.view->height;
  options.margin *= s;
  options.gap *= s;
  options.anchor_clearance *= s;
  for (double& l : options.leader_lengths) l *= s;
  for (double& l : options.fallback_leader_lengths) l *= s;
  options.obstacles = std::move(obstacles);
  options.coverage = &coverage;
  const std::vector<PlacedLabel> placed = place_labels(requests, options);

  // leaders under the boxes, so that a box edge is never crossed by a line
  ImDrawList& dl = overlay.draw_list();
  for (const PlacedLabel& p : placed) {
    if (!p.placed) continue;
    dl.AddLine(iv(p.anchor), iv(p.leader_end), palette::kLeader.packed(), kLeaderWidth * s);
    dl.AddCircleFilled(iv(p.anchor), kAnchorDot * s, palette::kLeader.packed());
  }
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const PlacedLabel& p = placed[i];
    if (!p.placed) continue;
    const SceneElement& e = (*in.samples)[i].element;
    const bool warn = is_highlighted(*in.frame, e);
    Rgb fill = palette::kBackground, border = palette::kEdge;
    if (e.element.kind == ElementKind::Face) {
      const Rgb c = palette::face(e.object == Object::B, e.element.index);
      fill = c.mix(palette::kBackground, kLabelFillLightening);
      border = c.mix(Rgb{0, 0, 0}, kLabelBorderDarkening);
    }
    if (warn) border = palette::kWarning;
    const ImVec2 a = iv({p.box.x0, p.box.y0}), b = iv({p.box.x1, p.box.y1});
    dl.AddRectFilled(a, b, fill.packed(), kLabelRounding * s);
    dl.AddRect(a, b, border.packed(), kLabelRounding * s, 0, (warn ? 2.f : 1.f) * kLabelBorder * s);
    const std::string& name = element_name(scene, e);
    dl.AddText(overlay.font(FontRole::Label), overlay.font_size(FontRole::Label),
               ImVec2(a.x + kLabelPadX * s, a.y + kLabelPadY * s),
               (warn ? palette::kWarning : palette::kText).packed(), name.c_str());
  }
}

}  // namespace

double header_height(const FrameRequest& frame) {
  if (frame.title.empty() && frame.subtitle.empty()) return 0;
  return kHeaderNominal * std::max(0.5, frame.height / kReferenceHeight);
}

void draw_annotations(Overlay& overlay, const AnnotationInput& in) {
  const float s = overlay.ui_scale();
  std::vector<Box> obstacles;
  if (!in.frame->title.empty() || !in.frame->subtitle.empty()) {
    obstacles.push_back(draw_header(overlay, *in.frame, s));
  }
  for (const Box& b : draw_contacts(overlay, in, s)) obstacles.push_back(b);
  if (in.frame->show_labels && in.ids != nullptr && in.samples != nullptr) {
    draw_labels(overlay, in, std::move(obstacles), s);
  }
}

}  // namespace pcsg::render
