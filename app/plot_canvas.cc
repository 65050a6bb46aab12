#ifdef PCSG_WITH_RENDER
#include "app/plot_canvas.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/embedded_resources.h"

// stb: the TrueType rasteriser is compiled into libstb (linked with the renderer); the bitmap
// font is a header of static functions, some unused here.
#include <stb/stb_truetype.h>
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace pcsg::app {

struct PlotCanvas::Font {
  bool truetype = false;
  stbtt_fontinfo info{};
  double ascent = 0, descent = 0;  // font units
};

namespace {

double clamp01(double a) { return std::clamp(a, 0.0, 1.0); }

// Signed distance (pixels, < 0 inside) from p (relative to the centre, y down) to a marker.
double marker_distance(double x, double y, Marker shape, double r) {
  switch (shape) {
    case Marker::Circle:
      return std::hypot(x, y) - r;
    case Marker::Square:  // same area as the circle: side r sqrt(pi)
      return std::max(std::abs(x), std::abs(y)) - 0.886 * r;
    case Marker::Diamond:
      return (std::abs(x) + std::abs(y)) / std::sqrt(2.0) - 0.886 * r;
    case Marker::Triangle: {  // equilateral, pointing up (Inigo Quilez's distance)
      const double k = std::sqrt(3.0), s = 1.25 * r;
      double px = std::abs(x) - s, py = -y + s / k;
      if (px + k * py > 0) {
        const double nx = (px - k * py) / 2, ny = (-k * px - py) / 2;
        px = nx, py = ny;
      }
      px -= std::clamp(px, -2 * s, 0.0);
      return -std::hypot(px, py) * (py < 0 ? -1 : 1);
    }
  }
  return 0;
}

}  // namespace

PlotCanvas::PlotCanvas(int width, int height, Rgb background)
    : image_(width, height), font_(std::make_unique<Font>()) {
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image_.pixel(x, y);
      p[0] = background[0], p[1] = background[1], p[2] = background[2], p[3] = 255;
    }
  const render::EmbeddedResource ttf = render::embedded_resource("label_font.ttf");
  if (!ttf.empty() && stbtt_InitFont(&font_->info, ttf.data, 0)) {
    int a = 0, d = 0, gap = 0;
    stbtt_GetFontVMetrics(&font_->info, &a, &d, &gap);
    font_->truetype = true;
    font_->ascent = a, font_->descent = d;
  }
}

PlotCanvas::~PlotCanvas() = default;

void PlotCanvas::blend(int x, int y, Rgb color, double a) {
  if (a <= 0 || x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
  a = std::min(a, 1.0);
  std::uint8_t* p = image_.pixel(x, y);
  for (int c = 0; c < 3; ++c)
    p[c] = static_cast<std::uint8_t>(std::lround(p[c] + a * (color[c] - p[c])));
}

void PlotCanvas::line(double x0, double y0, double x1, double y1, double width, Rgb color,
                      double dash) {
  const double half = width / 2, len = std::hypot(x1 - x0, y1 - y0);
  const double dx = len > 0 ? (x1 - x0) / len : 1, dy = len > 0 ? (y1 - y0) / len : 0;
  const int xa = static_cast<int>(std::floor(std::min(x0, x1) - half - 1));
  const int xb = static_cast<int>(std::ceil(std::max(x0, x1) + half + 1));
  const int ya = static_cast<int>(std::floor(std::min(y0, y1) - half - 1));
  const int yb = static_cast<int>(std::ceil(std::max(y0, y1) + half + 1));
  for (int y = ya; y <= yb; ++y)
    for (int x = xa; x <= xb; ++x) {
      // distance from the pixel centre to the segment, and where along it the foot lies
      const double px = x + 0.5 - x0, py = y + 0.5 - y0;
      const double t = std::clamp(px * dx + py * dy, 0.0, len);
      if (dash > 0 && std::fmod(t, 2 * dash) > dash) continue;
      const double d = std::hypot(px - t * dx, py - t * dy);
      blend(x, y, color, clamp01(half + 0.5 - d));
    }
}

void PlotCanvas::fill_rect(double x0, double y0, double x1, double y1, Rgb color) {
  if (x1 < x0) std::swap(x0, x1);
  if (y1 < y0) std::swap(y0, y1);
  for (int y = static_cast<int>(std::floor(y0)); y < std::ceil(y1); ++y)
    for (int x = static_cast<int>(std::floor(x0)); x < std::ceil(x1); ++x) {
      // the pixel's area covered by the rectangle
      const double cx = std::min<double>(x + 1, x1) - std::max<double>(x, x0);
      const double cy = std::min<double>(y + 1, y1) - std::max<double>(y, y0);
      blend(x, y, color, clamp01(cx) * clamp01(cy));
    }
}

void PlotCanvas::stroke_rect(double x0, double y0, double x1, double y1, double width,
                             Rgb color) {
  line(x0, y0, x1, y0, width, color);
  line(x1, y0, x1, y1, width, color);
  line(x1, y1, x0, y1, width, color);
  line(x0, y1, x0, y0, width, color);
}

void PlotCanvas::marker(double cx, double cy, Marker shape, double r, Rgb color, bool hollow) {
  const int n = static_cast<int>(std::ceil(1.5 * r + 2));
  constexpr double kRing = 2.0;  // outline width of hollow markers (pixels)
  for (int y = static_cast<int>(cy) - n; y <= static_cast<int>(cy) + n; ++y)
    for (int x = static_cast<int>(cx) - n; x <= static_cast<int>(cx) + n; ++x) {
      const double d = marker_distance(x + 0.5 - cx, y + 0.5 - cy, shape, r);
      double a = clamp01(0.5 - d);
      if (hollow) a = std::min(a, clamp01(0.5 + d + kRing));
      blend(x, y, color, a);
    }
}

double PlotCanvas::text_width(const std::string& s, double px) const {
  if (!font_->truetype) {
    std::vector<char> buf(s.begin(), s.end());
    buf.push_back('\0');
    return stb_easy_font_width(buf.data()) * px / 10.0;
  }
  const double scale = px / (font_->ascent - font_->descent);
  double w = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    int advance = 0, lsb = 0;
    stbtt_GetCodepointHMetrics(&font_->info, static_cast<unsigned char>(s[i]), &advance, &lsb);
    w += advance * scale;
    if (i + 1 < s.size())
      w += scale * stbtt_GetCodepointKernAdvance(&font_->info, static_cast<unsigned char>(s[i]),
                                                 static_cast<unsigned char>(s[i + 1]));
  }
  return w;
}

void PlotCanvas::text(double x, double y, const std::string& s, double px, Rgb color,
                      Align align, bool vertical) {
  const double w = text_width(s, px);
  const double shift = align == Align::Left ? 0 : align == Align::Center ? w / 2 : w;
  // (u along the text, v down from the baseline) -> canvas pixel
  auto put = [&](double u, double v, double a) {
    u -= shift;
    if (vertical)
      blend(static_cast<int>(std::floor(x + v)), static_cast<int>(std::floor(y - u)), color, a);
    else
      blend(static_cast<int>(std::floor(x + u)), static_cast<int>(std::floor(y + v)), color, a);
  };
  if (!font_->truetype) {
    // stb's bitmap font: quads on a ~10-unit line, its baseline ~7 units below the top
    std::vector<char> buf(s.begin(), s.end());
    buf.push_back('\0');
    std::vector<float> quads(s.size() * 270);
    const int n = stb_easy_font_print(0, 0, buf.data(), nullptr, quads.data(),
                                      static_cast<int>(quads.size() * sizeof(float)));
    const double k = px / 10.0;
    for (int q = 0; q < n; ++q) {
      const float* v = &quads[q * 16];  // 4 vertices of (x, y, z, rgba)
      for (double yy = v[1] * k; yy < v[9] * k; yy += 1)
        for (double xx = v[0] * k; xx < v[4] * k; xx += 1) put(xx, yy - 7 * k, 1.0);
    }
    return;
  }
  const double scale = px / (font_->ascent - font_->descent);
  double pen = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    const int cp = static_cast<unsigned char>(s[i]);
    int advance = 0, lsb = 0, gw = 0, gh = 0, xoff = 0, yoff = 0;
    stbtt_GetCodepointHMetrics(&font_->info, cp, &advance, &lsb);
    const double frac = pen - std::floor(pen);
    unsigned char* bitmap = stbtt_GetCodepointBitmapSubpixel(
        &font_->info, static_cast<float>(scale), static_cast<float>(scale),
        static_cast<float>(frac), 0.f, cp, &gw, &gh, &xoff, &yoff);
    for (int gy = 0; gy < gh; ++gy)
      for (int gx = 0; gx < gw; ++gx)
        if (bitmap[gy * gw + gx])
          put(std::floor(pen) + xoff + gx + 0.5, yoff + gy + 0.5, bitmap[gy * gw + gx] / 255.0);
    stbtt_FreeBitmap(bitmap, nullptr);
    pen += advance * scale;
    if (i + 1 < s.size())
      pen += scale * stbtt_GetCodepointKernAdvance(&font_->info, cp,
                                                   static_cast<unsigned char>(s[i + 1]));
  }
}

}  // namespace pcsg::app
#endif  // PCSG_WITH_RENDER
