#include "anim/mocap/tools/figure_png.hpp"

#include <algorithm>
#include <cmath>

namespace mc::anim::mocap::tools {

namespace {
// Dark to light (the paper: low cost dark, high cost light), through blue.
void ramp(float t, std::uint8_t& r, std::uint8_t& g, std::uint8_t& b) {
  t = std::clamp(t, 0.0f, 1.0f);
  r = static_cast<std::uint8_t>(20 + 235 * std::pow(t, 1.2f));
  g = static_cast<std::uint8_t>(20 + 225 * t);
  b = static_cast<std::uint8_t>(60 + 160 * std::sqrt(t));
}
void diverge(float t, std::uint8_t& r, std::uint8_t& g, std::uint8_t& b) {
  t = std::clamp(t, -1.0f, 1.0f);
  if (t < 0) { r = g = static_cast<std::uint8_t>(255 * (1 + t)); b = 255; }
  else { r = 255; g = b = static_cast<std::uint8_t>(255 * (1 - t)); }
}
void line(Image& img, int x0, int y0, int x1, int y1, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  const int n = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
  for (int i = 0; i <= n; ++i) {
    const float t = n ? static_cast<float>(i) / static_cast<float>(n) : 0;
    img.set(static_cast<int>(std::lround(static_cast<float>(x0) + t * static_cast<float>(x1 - x0))),
            static_cast<int>(std::lround(static_cast<float>(y0) + t * static_cast<float>(y1 - y0))), r, g, b);
  }
}
}  // namespace

Image heat_map(const MapGrid& grid, const std::vector<float>& v, const HeatStyle& st) {
  Image img(grid.width * st.px, grid.height * st.px, 128);
  for (int i = 0; i < grid.cells(); ++i) {
    const int cx = i % grid.width, cy = i / grid.width;
    std::uint8_t r = 150, g = 150, b = 150;  // unreached: grey
    const float val = v[static_cast<std::size_t>(i)];
    const bool obstacle = st.obstacles && (*st.obstacles)[static_cast<std::size_t>(i)];
    if (obstacle) { r = g = b = 255; }
    else if (val != kUnreached && std::isfinite(val)) {
      if (st.diverging) diverge(val / std::max(1e-6f, st.vmax), r, g, b);
      else ramp((val - st.vmin) / std::max(1e-6f, st.vmax - st.vmin), r, g, b);
    }
    if (st.highlight && (*st.highlight)[static_cast<std::size_t>(i)]) {
      r = static_cast<std::uint8_t>(r / 3); g = static_cast<std::uint8_t>(std::min(255, g / 3 + 170)); b = static_cast<std::uint8_t>(b / 3);
    }
    for (int y = 0; y < st.px; ++y)
      for (int x = 0; x < st.px; ++x) {
        const bool edge = obstacle && (x == 0 || y == 0 || x == st.px - 1 || y == st.px - 1);
        if (edge) img.set(cx * st.px + x, cy * st.px + y, 0, 0, 0);
        else img.set(cx * st.px + x, cy * st.px + y, r, g, b);
      }
  }
  for (int m : st.marks) {
    if (m < 0 || m >= grid.cells()) continue;
    const int cx = m % grid.width, cy = m / grid.width;
    const int x0 = cx * st.px, y0 = cy * st.px, x1 = x0 + st.px - 1, y1 = y0 + st.px - 1;
    line(img, x0, y0, x1, y1, 255, 255, 0);
    line(img, x0, y1, x1, y0, 255, 255, 0);
  }
  return img;
}

Image plot(const std::vector<Series>& series, float x0, float x1, float y0, float y1, bool lines, int w, int h) {
  Image img(w, h, 255);
  const int l = 40, rgt = w - 10, top = 10, bot = h - 30;
  auto px = [&](float x) { return l + static_cast<int>(std::lround((x - x0) / (x1 - x0) * static_cast<float>(rgt - l))); };
  auto py = [&](float y) { return bot - static_cast<int>(std::lround((y - y0) / (y1 - y0) * static_cast<float>(bot - top))); };
  // Axes and ten ticks on each.
  line(img, l, bot, rgt, bot, 0, 0, 0);
  line(img, l, bot, l, top, 0, 0, 0);
  for (int k = 0; k <= 10; ++k) {
    const int tx = l + (rgt - l) * k / 10, ty = bot - (bot - top) * k / 10;
    line(img, tx, bot, tx, bot + 5, 0, 0, 0);
    line(img, l - 5, ty, l, ty, 0, 0, 0);
    for (int x = l + 1; x < rgt; x += 4) img.set(x, ty, 220, 220, 220);
  }
  for (const auto& s : series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i])) continue;
      const int X = px(s.x[i]), Y = py(s.y[i]);
      if (lines && i > 0 && std::isfinite(s.y[i - 1])) {
        line(img, px(s.x[i - 1]), py(s.y[i - 1]), X, Y, s.r, s.g, s.b);
        line(img, px(s.x[i - 1]), py(s.y[i - 1]) + 1, X, Y + 1, s.r, s.g, s.b);
      } else if (!lines) {
        for (int d = -1; d <= 1; ++d) { img.set(X + d, Y, s.r, s.g, s.b); img.set(X, Y + d, s.r, s.g, s.b); }
      }
    }
  }
  return img;
}

}  // namespace mc::anim::mocap::tools
