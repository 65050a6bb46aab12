#include "render/text_painter.h"

#include <stb/stb_truetype.h>

#include <algorithm>
#include <cmath>

#include "render/canvas.h"
#include "render/embedded_resources.h"

// stb_easy_font is header-only with static functions; some of them are unused here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace pcsg::render {

namespace {

// stb_easy_font's glyphs are 7 units tall with descenders in a 12-unit line; a line of
// `px` pixels scales them by px / 12.
constexpr double kEasyFontLine = 12;
constexpr char32_t kReplacement = 0xFFFD;

}  // namespace

struct TextPainter::Font {
  stbtt_fontinfo info;
  double ascent = 0, descent = 0;  // in font units (descent < 0)
  double units_per_px_height = 1;  // ascent - descent: the line height in font units
};

std::vector<char32_t> decode_utf8(std::string_view s) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + static_cast<std::size_t>(extra) >= s.size()) {  // bad or cut short
      out.push_back(kReplacement);
      ++i;
      continue;
    }
    char32_t cp = extra == 0 ? c : c & (0x3F >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto d = static_cast<unsigned char>(s[i + k]);
      if ((d >> 6) != 2) ok = false;
      cp = (cp << 6) | (d & 0x3F);
    }
    out.push_back(ok ? cp : kReplacement);
    i += ok ? extra + 1 : 1;
  }
  return out;
}

TextPainter::TextPainter() {
  const EmbeddedResource ttf = embedded_resource("label_font.ttf");
  if (ttf.empty()) return;
  auto font = std::make_unique<Font>();
  if (stbtt_InitFont(&font->info, ttf.data, stbtt_GetFontOffsetForIndex(ttf.data, 0)) == 0) return;
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&font->info, &ascent, &descent, &gap);
  font->ascent = ascent;
  font->descent = descent;
  font->units_per_px_height = ascent - descent;
  font_ = std::move(font);
}

TextPainter::~TextPainter() = default;

double TextPainter::line_height(double px) const { return std::ceil(px); }

double TextPainter::width(std::string_view text, double px) const {
  if (!font_) {
    std::string copy(text);
    return stb_easy_font_width(copy.data()) * px / kEasyFontLine;
  }
  const double scale = px / font_->units_per_px_height;
  double w = 0;
  int previous = 0;
  for (char32_t cp : decode_utf8(text)) {
    const int g = stbtt_FindGlyphIndex(&font_->info, static_cast<int>(cp));
    int advance = 0, bearing = 0;
    stbtt_GetGlyphHMetrics(&font_->info, g, &advance, &bearing);
    if (previous != 0) w += scale * stbtt_GetGlyphKernAdvance(&font_->info, previous, g);
    w += scale * advance;
    previous = g;
  }
  return w;
}

const TextPainter::Glyph& TextPainter::glyph(int index, double px, int quarter) const {
  const auto key = std::make_tuple(index, static_cast<int>(std::lround(px * 64)), quarter);
  auto it = cache_.find(key);
  if (it != cache_.end()) return it->second;
  const float scale = static_cast<float>(px / font_->units_per_px_height);
  Glyph g;
  int x1 = 0, y1 = 0;
  stbtt_GetGlyphBitmapBoxSubpixel(&font_->info, index, scale, scale, 0.25f * quarter, 0.f, &g.x0,
                                  &g.y0, &x1, &y1);
  g.width = std::max(0, x1 - g.x0);
  g.height = std::max(0, y1 - g.y0);
  g.alpha.assign(static_cast<std::size_t>(g.width) * g.height, 0);
  if (g.width > 0 && g.height > 0) {
    stbtt_MakeGlyphBitmapSubpixel(&font_->info, g.alpha.data(), g.width, g.height, g.width, scale,
                                  scale, 0.25f * quarter, 0.f, index);
  }
  return cache_.emplace(key, std::move(g)).first->second;
}

double TextPainter::draw(Image& image, double x, double y, std::string_view text, double px,
                         const Rgb& colour) const {
  if (!font_) return draw_fallback(image, x, y, text, px, colour);
  Canvas canvas(image);
  const double scale = px / font_->units_per_px_height;
  // the baseline on a whole pixel row keeps stems crisp and rendering reproducible
  const int baseline = static_cast<int>(std::lround(y + scale * font_->ascent));
  double pen = x;
  int previous = 0;
  for (char32_t cp : decode_utf8(text)) {
    const int index = stbtt_FindGlyphIndex(&font_->info, static_cast<int>(cp));
    if (previous != 0) pen += scale * stbtt_GetGlyphKernAdvance(&font_->info, previous, index);
    const int whole = static_cast<int>(std::floor(pen));
    const int quarter = std::min(3, static_cast<int>((pen - whole) * 4));
    const Glyph& g = glyph(index, px, quarter);
    for (int j = 0; j < g.height; ++j)
      for (int i = 0; i < g.width; ++i) {
        const unsigned char a = g.alpha[static_cast<std::size_t>(j) * g.width + i];
        if (a != 0) canvas.blend(whole + g.x0 + i, baseline + g.y0 + j, colour, a / 255.f);
      }
    int advance = 0, bearing = 0;
    stbtt_GetGlyphHMetrics(&font_->info, index, &advance, &bearing);
    pen += scale * advance;
    previous = index;
  }
  return pen - x;
}

double TextPainter::draw_fallback(Image& image, double x, double y, std::string_view text,
                                  double px, const Rgb& colour) const {
  // ASCII only: other code points become '?'
  std::string ascii;
  for (char32_t cp : decode_utf8(text)) ascii += cp >= 32 && cp < 127 ? static_cast<char>(cp) : '?';
  std::vector<float> quads(ascii.size() * 270 / sizeof(float) + 64);
  const int n = stb_easy_font_print(0, 0, ascii.data(), nullptr, quads.data(),
                                    static_cast<int>(quads.size() * sizeof(float)));
  const double s = px / kEasyFontLine;
  Canvas canvas(image);
  // each vertex: x, y, z, colour (4 bytes) = 4 floats; four vertices per quad
  for (int q = 0; q < n; ++q) {
    const float* v = &quads[static_cast<std::size_t>(q) * 16];
    canvas.fill_rect(x + s * v[0], y + s * v[1], x + s * v[8], y + s * v[9], colour);
  }
  return width(text, px);
}

std::string TextPainter::fit(std::string_view text, double px, double max_width) const {
  if (width(text, px) <= max_width) return std::string(text);
  const std::string ellipsis = font_ ? "\xE2\x80\xA6" : "...";
  // cut at code point boundaries until it fits with the ellipsis
  std::string s(text);
  while (!s.empty() && width(s + ellipsis, px) > max_width) {
    std::size_t cut = s.size() - 1;
    while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;
    s.resize(cut);
  }
  return s + ellipsis;
}

}  // namespace pcsg::render
