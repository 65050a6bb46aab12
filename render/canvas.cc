#include "render/canvas.h"

#include <stb/stb_image_resize.h>

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"

namespace pcsg::render {

namespace {

std::uint8_t to_byte(float v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0.f, 1.f) * 255.f + 0.5f);
}

// Distance from p to the segment ab.
double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Coverage of a pixel whose centre is `d` pixels inside a shape's boundary (negative: outside):
// the one-pixel-wide linear ramp of a box filter across a straight edge.
float coverage(double d) { return static_cast<float>(std::clamp(d + 0.5, 0.0, 1.0)); }

}  // namespace

void Canvas::blend(int x, int y, const Rgb& c, float alpha) {
  if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || alpha <= 0) return;
  std::uint8_t* p = image_.pixel(x, y);
  const float a = std::min(alpha, 1.f);
  const float rgb[3] = {c.r, c.g, c.b};
  for (int k = 0; k < 3; ++k) p[k] = to_byte(p[k] / 255.f * (1 - a) + rgb[k] * a);
  p[3] = 255;  // the images are opaque
}

void Canvas::fill(const Rgb& c) {
  for (int y = 0; y < image_.height; ++y)
    for (int x = 0; x < image_.width; ++x) {
      std::uint8_t* p = image_.pixel(x, y);
      p[0] = to_byte(c.r), p[1] = to_byte(c.g), p[2] = to_byte(c.b), p[3] = 255;
    }
}

void Canvas::fill_rect(double x0, double y0, double x1, double y1, const Rgb& c, float alpha) {
  const int i0 = std::max(0, static_cast<int>(std::floor(x0)));
  const int j0 = std::max(0, static_cast<int>(std::floor(y0)));
  const int i1 = std::min(image_.width, static_cast<int>(std::ceil(x1)));
  const int j1 = std::min(image_.height, static_cast<int>(std::ceil(y1)));
  for (int j = j0; j < j1; ++j) {
    // the share of the pixel inside the rectangle, per axis
    const double cy = std::min<double>(j + 1, y1) - std::max<double>(j, y0);
    for (int i = i0; i < i1; ++i) {
      const double cx = std::min<double>(i + 1, x1) - std::max<double>(i, x0);
      blend(i, j, c, alpha * static_cast<float>(std::clamp(cx * cy, 0.0, 1.0)));
    }
  }
}

void Canvas::stroke_rect(double x0, double y0, double x1, double y1, const Rgb& c, double w) {
  fill_rect(x0, y0, x1, y0 + w, c);
  fill_rect(x0, y1 - w, x1, y1, c);
  fill_rect(x0, y0 + w, x0 + w, y1 - w, c);
  fill_rect(x1 - w, y0 + w, x1, y1 - w, c);
}

void Canvas::stroke_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Rgb& c,
                            double w) {
  const double r = 0.5 * w;
  const int i0 = std::max(0, static_cast<int>(std::floor(std::min(a.x(), b.x()) - r - 1)));
  const int j0 = std::max(0, static_cast<int>(std::floor(std::min(a.y(), b.y()) - r - 1)));
  const int i1 = std::min(image_.width - 1, static_cast<int>(std::ceil(std::max(a.x(), b.x()) + r + 1)));
  const int j1 = std::min(image_.height - 1, static_cast<int>(std::ceil(std::max(a.y(), b.y()) + r + 1)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double d = segment_distance({i + 0.5, j + 0.5}, a, b);
      blend(i, j, c, coverage(r - d));
    }
}

void Canvas::stroke(const Polyline& pts, const Rgb& c, double w, const Dash& dash) {
  if (pts.empty()) return;
  if (pts.size() == 1) {
    stroke_segment(pts[0], pts[0], c, w);
    return;
  }
  if (dash.on <= 0) {
    // Segments are blended one by one: a joint pixel partly covered by two segments gets a
    // little more ink than by one, invisible for the opaque strokes drawn here.
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) stroke_segment(pts[k], pts[k + 1], c, w);
    return;
  }
  // walk the polyline, emitting the "on" stretches of the pattern
  const double period = dash.on + std::max(0.0, dash.off);
  double phase = 0;  // position within the pattern at the start of the current segment
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const Eigen::Vector2d a = pts[k], b = pts[k + 1];
    const double len = (b - a).norm();
    double s = 0;
    while (s < len) {
      const double in_period = std::fmod(phase + s, period);
      const bool on = in_period < dash.on;
      const double run = std::min(len - s, on ? dash.on - in_period : period - in_period);
      if (on) stroke_segment(a + (b - a) * (s / len), a + (b - a) * ((s + run) / len), c, w);
      s += std::max(run, 1e-9);
    }
    phase += len;
  }
}

void Canvas::fill_disc(const Eigen::Vector2d& centre, double radius, const Rgb& c, float alpha) {
  const int i0 = std::max(0, static_cast<int>(std::floor(centre.x() - radius - 1)));
  const int j0 = std::max(0, static_cast<int>(std::floor(centre.y() - radius - 1)));
  const int i1 = std::min(image_.width - 1, static_cast<int>(std::ceil(centre.x() + radius + 1)));
  const int j1 = std::min(image_.height - 1, static_cast<int>(std::ceil(centre.y() + radius + 1)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double d = (Eigen::Vector2d(i + 0.5, j + 0.5) - centre).norm();
      blend(i, j, c, alpha * coverage(radius - d));
    }
}

void Canvas::stroke_circle(const Eigen::Vector2d& centre, double radius, const Rgb& c,
                           double w) {
  const double outer = radius + 0.5 * w;
  const int i0 = std::max(0, static_cast<int>(std::floor(centre.x() - outer - 1)));
  const int j0 = std::max(0, static_cast<int>(std::floor(centre.y() - outer - 1)));
  const int i1 = std::min(image_.width - 1, static_cast<int>(std::ceil(centre.x() + outer + 1)));
  const int j1 = std::min(image_.height - 1, static_cast<int>(std::ceil(centre.y() + outer + 1)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double d = std::abs((Eigen::Vector2d(i + 0.5, j + 0.5) - centre).norm() - radius);
      blend(i, j, c, coverage(0.5 * w - d));
    }
}

void Canvas::fill_convex(const Polyline& poly, const Rgb& c, float alpha) {
  if (poly.size() < 3) return;
  // orientation, so that "inside" is on the same side of every edge
  double area2 = 0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const auto& p = poly[k];
    const auto& q = poly[(k + 1) % poly.size()];
    area2 += p.x() * q.y() - q.x() * p.y();
  }
  const double sign = area2 >= 0 ? 1 : -1;
  Eigen::Vector2d lo = poly[0], hi = poly[0];
  for (const auto& p : poly) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const int i0 = std::max(0, static_cast<int>(std::floor(lo.x() - 1)));
  const int j0 = std::max(0, static_cast<int>(std::floor(lo.y() - 1)));
  const int i1 = std::min(image_.width - 1, static_cast<int>(std::ceil(hi.x() + 1)));
  const int j1 = std::min(image_.height - 1, static_cast<int>(std::ceil(hi.y() + 1)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const Eigen::Vector2d p(i + 0.5, j + 0.5);
      // signed distance to the polygon: the smallest distance inside the edges' half-planes
      double d = 1e30;
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const Eigen::Vector2d a = poly[k], b = poly[(k + 1) % poly.size()];
        const Eigen::Vector2d e = b - a;
        const double len = e.norm();
        if (len <= 0) continue;
        d = std::min(d, sign * (e.x() * (p.y() - a.y()) - e.y() * (p.x() - a.x())) / len);
      }
      blend(i, j, c, alpha * coverage(d));
    }
}

void Canvas::arrowhead(const Eigen::Vector2d& tip, const Eigen::Vector2d& direction,
                       double length, const Rgb& c, bool open, double outline) {
  if (direction.norm() <= 0) return;
  const Eigen::Vector2d u = direction.normalized(), side(-u.y(), u.x());
  const Eigen::Vector2d base = tip - length * u;
  // half-width 0.4 of the length: a clear, not blunt, head
  const Polyline head = {tip, base + 0.4 * length * side, base - 0.4 * length * side};
  if (!open) {
    fill_convex(head, c);
    return;
  }
  fill_convex(head, palette::kBackground);  // hides the line under it
  stroke({head[0], head[1], head[2], head[0]}, c, outline);
}

void Canvas::blit(const Image& source, int x, int y) {
  for (int j = std::max(0, -y); j < source.height && y + j < image_.height; ++j)
    for (int i = std::max(0, -x); i < source.width && x + i < image_.width; ++i) {
      const std::uint8_t* s = source.pixel(i, j);
      std::uint8_t* d = image_.pixel(x + i, y + j);
      std::copy(s, s + 4, d);
    }
}

Polyline flatten_bezier(const Polyline& control, int segments) {
  Polyline out;
  if (control.empty()) return out;
  out.push_back(control[0]);
  for (std::size_t k = 0; k + 3 < control.size(); k += 3) {
    const Eigen::Vector2d &p0 = control[k], &p1 = control[k + 1], &p2 = control[k + 2],
                          &p3 = control[k + 3];
    for (int s = 1; s <= segments; ++s) {
      const double t = static_cast<double>(s) / segments, u = 1 - t;
      out.push_back(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
    }
  }
  return out;
}

double polyline_length(const Polyline& pts) {
  double len = 0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) len += (pts[k + 1] - pts[k]).norm();
  return len;
}

Polyline trim_end(const Polyline& pts, double length) {
  if (pts.size() < 2) return pts;
  Polyline out = pts;
  double left = length;
  while (out.size() >= 2 && left > 0) {
    const Eigen::Vector2d a = out[out.size() - 2], b = out.back();
    const double len = (b - a).norm();
    if (len > left) {
      out.back() = b + (a - b) * (left / len);
      return out;
    }
    left -= len;
    out.pop_back();
  }
  return out;
}

PixelBounds content_bounds(const Image& image, const Rgb& background, int tolerance) {
  const int bg[3] = {to_byte(background.r), to_byte(background.g), to_byte(background.b)};
  PixelBounds b{image.width, image.height, 0, 0};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (std::abs(p[0] - bg[0]) > tolerance || std::abs(p[1] - bg[1]) > tolerance ||
          std::abs(p[2] - bg[2]) > tolerance) {
        b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y);
        b.x1 = std::max(b.x1, x + 1), b.y1 = std::max(b.y1, y + 1);
      }
    }
  return b;
}

Image cropped(const Image& image, int x0, int y0, int width, int height, const Rgb& fill) {
  Image out(std::max(1, width), std::max(1, height));
  Canvas canvas(out);
  canvas.fill(fill);
  canvas.blit(image, -x0, -y0);
  return out;
}

Image resized(const Image& source, int width, int height) {
  if (source.empty() || width < 1 || height < 1) {
    throw Error("resized: cannot resize a " + std::to_string(source.width) + "x" +
                std::to_string(source.height) + " image to " + std::to_string(width) + "x" +
                std::to_string(height));
  }
  if (width == source.width && height == source.height) return source;
  Image out(width, height);
  if (stbir_resize_uint8(source.rgba.data(), source.width, source.height, 0, out.rgba.data(),
                         width, height, 0, 4) == 0) {
    throw Error("resized: stb's resizer failed");
  }
  return out;
}

}  // namespace pcsg::render
