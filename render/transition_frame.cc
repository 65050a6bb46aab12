#include "render/transition_frame.h"

#include <algorithm>
#include <cmath>
#include <cctype>

#include "render/canvas.h"
#include "render/contact_sheet.h"
#include "render/frame_camera.h"

namespace pcsg::render {

namespace {

// Text sizes in pixels for a 600-pixel-high view, scaled with the view's height (not below
// 0.6 of them: smaller is unreadable).
constexpr double kReferenceHeight = 600;
constexpr double kTitlePx = 19, kLinePx = 16, kMargin = 12, kLineGap = 5;
// Role rings around the renderer's contact markers: radius and width at the reference height.
constexpr double kRingRadius = 13, kRingWidth = 3.5;
// The banner's text on the warning colour.
constexpr Rgb kBannerText{1, 1, 1};

// Light grey rule between the header and the view.
constexpr Rgb kRule{0.8f, 0.8f, 0.82f};

double scale_of(int view_height) { return std::max(0.6, view_height / kReferenceHeight); }

std::string element_names(const std::vector<ElementId>& ids, const Solid& solid) {
  std::string out;
  for (const ElementId& e : ids) {
    if (e.index < 0) continue;  // no element named (see MotionFrame::collided_a)
    const std::string name = solid.element_name(e);
    if (out.find(name) == std::string::npos) out += (out.empty() ? "" : ", ") + name;
  }
  return out;
}

std::string step_text(const TransitionInfo& t, const MotionFrame& f) {
  return t.motion + "  \xC2\xB7  step " + std::to_string(f.step) +
         (t.steps > 0 ? " of " + std::to_string(t.steps) : "") + "  \xC2\xB7  " + f.phase +
         "  \xC2\xB7  " + (t.feasible ? "feasible" : "failed");
}

std::string transition_title(const TransitionInfo& t) {
  return "state " + std::to_string(t.from) + " " + t.from_cf + "  \xE2\x86\x92  " + t.target_cf +
         (t.feasible && t.to >= 0 ? "  (state " + std::to_string(t.to) + ")" : "");
}

}  // namespace

Rgb contact_role_colour(ContactRole role) {
  switch (role) {
    case ContactRole::Kept:
      return {0.10f, 0.58f, 0.24f};  // green
    case ContactRole::Changing:
      return {0.96f, 0.55f, 0.04f};  // orange
    case ContactRole::Reached:
      return {0.13f, 0.40f, 0.86f};  // blue
    case ContactRole::Undecided:
      return {0.58f, 0.22f, 0.78f};  // violet
    case ContactRole::Other:
      return palette::kWarning;
  }
  return palette::kWarning;
}

std::string transition_slug(const TransitionInfo& t) {
  // "{(fA-e1, 1), (fA-f1, 1)}" -> "fA-e1x1_fA-f1x1": entries joined by '_', the count after
  // an 'x', anything else that is not a letter, digit or '-' dropped or made '-'
  std::string out, entry;
  bool in_entry = false;
  for (char c : t.target_cf) {
    if (c == '(') {
      entry.clear();
      in_entry = true;
    } else if (c == ')' && in_entry) {
      std::string part;
      int commas = 0;
      for (char e : entry) {
        if (e == ' ') continue;
        if (e == ',') {
          part += ++commas == 1 ? 'x' : '-';
        } else {
          part += std::isalnum(static_cast<unsigned char>(e)) || e == '-' ? e : '-';
        }
      }
      out += (out.empty() ? "" : "_") + part;
      in_entry = false;
    } else if (in_entry) {
      entry += c;
    }
  }
  return std::to_string(t.from) + "-" + (out.empty() ? "empty" : out);
}

std::string collision_text(const SceneGeometry& scene, const MotionFrame& f) {
  const std::string a = element_names(f.collided_a, scene.A);
  const std::string b = element_names(f.collided_b, scene.B);
  if (a.empty() && b.empty()) return "";
  return a + " with " + b;
}

std::string collision_banner(const SceneGeometry& scene, const TransitionInfo& t,
                             const MotionFrame& f) {
  // a motion also stops at this phase without a collision (a kept contact left its elements):
  // then no elements are named, and the reason says what happened
  const std::string names = collision_text(scene, f);
  std::string what = (names.empty() ? "stopped at step " : "collision at step ") + std::to_string(f.step);
  if (!names.empty()) what += ": " + names;
  if (!t.reason.empty()) what += "  \xE2\x80\x94  " + t.reason;
  return what;
}

bool shows_failure(const TransitionInfo& t, const MotionFrame& f, bool last_frame) {
  return f.phase == "collision" || (last_frame && !t.feasible);
}

FrameRequest transition_frame_request(const TransitionInfo& t, const MotionFrame& f,
                                      const std::vector<PointContact>& start,
                                      const TransitionFrameStyle& style) {
  (void)t;
  FrameRequest r;
  r.width = style.width;
  r.height = style.height;
  r.camera = style.camera;
  r.X_BA = f.pose;
  r.contacts = f.contacts.empty() ? start : f.contacts;
  r.show_labels = style.labels;
  for (const ElementId& e : f.collided_a)
    if (e.index >= 0) r.highlighted.push_back({Object::A, e});
  for (const ElementId& e : f.collided_b)
    if (e.index >= 0) r.highlighted.push_back({Object::B, e});
  return r;
}

Image draw_transition_view(SceneRenderer& renderer, const SceneGeometry& scene,
                           const TransitionInfo& t, const MotionFrame& f,
                           const std::vector<PointContact>& start,
                           const std::vector<ContactRole>& roles,
                           const TransitionFrameStyle& style) {
  const double s = scale_of(style.height);
  const FrameRequest request = transition_frame_request(t, f, start, style);
  Image view = renderer.render(request);
  Canvas canvas(view);
  // role rings around the renderer's markers, where the renderer projects them
  const CameraView camera = frame_camera_view(scene, request);
  for (std::size_t i = 0; i < request.contacts.size() && i < roles.size(); ++i) {
    const Eigen::Vector2d p = camera.project(request.contacts[i].point_B);
    canvas.stroke_circle(p, kRingRadius * s, contact_role_colour(roles[i]), kRingWidth * s);
  }
  return view;
}

Image add_transition_header(const Image& view, const SceneGeometry& scene, const TransitionInfo& t,
                            const MotionFrame& f, const std::vector<PointContact>& start,
                            const std::vector<ContactRole>& roles, const TextPainter& text,
                            bool last_frame) {
  const double s = scale_of(view.height);
  const std::vector<PointContact>& contacts = f.contacts.empty() ? start : f.contacts;
  std::vector<ContactRole> present(roles.begin(), roles.end());
  std::sort(present.begin(), present.end());
  present.erase(std::unique(present.begin(), present.end()), present.end());

  // the header band: transition, motion and step, the current CF and the legend
  const double title_px = kTitlePx * s, line_px = kLinePx * s, margin = kMargin * s;
  const bool collision = shows_failure(t, f, last_frame);
  const double band = 2 * margin + text.line_height(title_px) + 2 * (text.line_height(line_px) + kLineGap * s);
  const double banner = collision ? text.line_height(line_px) + 2 * margin : 0;
  const int top = static_cast<int>(std::ceil(band + banner));
  Image out(view.width, view.height + top);
  Canvas canvas(out);
  canvas.fill(palette::kBackground);
  const double width = out.width - 2 * margin;
  double y = margin;
  text.draw(out, margin, y, text.fit(transition_title(t), title_px, width), title_px, palette::kText);
  y += text.line_height(title_px) + kLineGap * s;
  text.draw(out, margin, y, text.fit(step_text(t, f), line_px, width), line_px, palette::kLeader);
  y += text.line_height(line_px) + kLineGap * s;
  // legend right-aligned: a ring and the role's name for each role shown
  double legend_w = 0;
  for (ContactRole r : present) legend_w += 2.6 * line_px + text.width(contact_role_name(r), line_px);
  const std::string now = "contacts now " + ContactFormation::of(contacts).str(scene);
  text.draw(out, margin, y, text.fit(now, line_px, width - legend_w - margin), line_px, palette::kLeader);
  double lx = out.width - margin - legend_w;
  for (ContactRole r : present) {
    const Eigen::Vector2d c(lx + 0.8 * line_px, y + 0.5 * text.line_height(line_px));
    canvas.stroke_circle(c, 0.42 * line_px, contact_role_colour(r), 0.16 * line_px);
    lx += 1.8 * line_px;
    lx += text.draw(out, lx, y, contact_role_name(r), line_px, contact_role_colour(r)) + 0.8 * line_px;
  }
  // the failure banner: the offending elements named, and why the motion stopped
  if (collision) {
    canvas.fill_rect(0, band, out.width, band + banner, palette::kWarning);
    text.draw(out, margin, band + margin, text.fit(collision_banner(scene, t, f), line_px, width),
              line_px, kBannerText);
  }
  canvas.blit(view, 0, top);
  canvas.fill_rect(0, top - 1, out.width, top, kRule);  // a hairline above the view
  return out;
}

Image draw_transition_frame(SceneRenderer& renderer, const SceneGeometry& scene,
                            const TransitionInfo& t, const MotionFrame& f,
                            const std::vector<PointContact>& start,
                            const std::vector<ContactRole>& roles,
                            const TransitionFrameStyle& style, const TextPainter& text,
                            bool last_frame) {
  return add_transition_header(draw_transition_view(renderer, scene, t, f, start, roles, style),
                               scene, t, f, start, roles, text, last_frame);
}

Image transition_contact_sheet(const TransitionInfo& t, const std::vector<Image>& views,
                               const std::vector<MotionFrame>& frames,
                               const std::vector<std::vector<ContactRole>>& roles,
                               const std::vector<PointContact>& start, const SceneGeometry& scene,
                               int cell_width, const TextPainter& text) {
  std::vector<SheetCell> cells;
  std::vector<ContactRole> present;
  for (std::size_t k = 0; k < views.size(); ++k) {
    SheetCell c;
    c.picture = views[k];
    if (k < frames.size()) {
      const MotionFrame& f = frames[k];
      const std::vector<PointContact>& contacts = f.contacts.empty() ? start : f.contacts;
      c.warning = shows_failure(t, f, k + 1 == frames.size());
      const std::string names = collision_text(scene, f);
      c.caption = {"step " + std::to_string(f.step) + "  \xC2\xB7  " + f.phase,
                   !names.empty() ? names : ContactFormation::of(contacts).str(scene)};
    }
    if (k < roles.size()) present.insert(present.end(), roles[k].begin(), roles[k].end());
    cells.push_back(std::move(c));
  }
  std::sort(present.begin(), present.end());
  present.erase(std::unique(present.begin(), present.end()), present.end());
  SheetOptions o;
  o.cell_width = cell_width;
  o.title = transition_title(t);
  o.subtitle = t.motion + ", " + std::to_string(t.steps) + " steps: " +
               (t.feasible ? "feasible, reaches state " + std::to_string(t.to)
                           : "failed" + (t.reason.empty() ? std::string() : " (" + t.reason + ")"));
  for (ContactRole r : present) o.legend.push_back({contact_role_name(r), contact_role_colour(r)});
  return compose_contact_sheet(cells, o, text);
}

}  // namespace pcsg::render
