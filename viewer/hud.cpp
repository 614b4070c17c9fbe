#include "viewer/hud.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "viewer/font.hpp"

namespace mc::viewer {
namespace {

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec2 a_pos;
layout(location = 1) in vec4 a_color;
uniform vec2 u_size;
out vec4 v_color;
void main() {
  gl_Position = vec4(a_pos.x / u_size.x * 2.0 - 1.0, 1.0 - a_pos.y / u_size.y * 2.0, 0.0, 1.0);
  v_color = a_color;
}
)";

const char* kFragment = R"(#version 330 core
in vec4 v_color;
out vec4 o_color;
void main() { o_color = v_color; }
)";

const glm::vec4 kPanel{0.04f, 0.06f, 0.10f, 0.78f};
const glm::vec4 kWhite{1.0f, 1.0f, 1.0f, 1.0f};
const glm::vec4 kYellow{1.0f, 0.86f, 0.25f, 1.0f};

float text_width(std::string_view s, float scale) { return static_cast<float>(text_columns(s)) * scale; }

}  // namespace

std::string clock_text(int time) {
  const int s = std::max(0, time) / 10;
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d:%02d", s / 60, s % 60);
  return buf;
}

std::string play_mode_text(std::string_view name) {
  std::string out(name);
  for (auto& c : out) c = c == '_' ? ' ' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

Hud::~Hud() {
  if (program_) glDeleteProgram(program_);
}

bool Hud::init(std::string& error) {
  program_ = gl::make_program(kVertex, kFragment, error);
  if (!program_) return false;
  u_size_ = glGetUniformLocation(program_, "u_size");
  return true;
}

void Hud::rect(float x, float y, float w, float h, glm::vec4 c) {
  const float v[6][2] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y}, {x + w, y + h}, {x, y + h}};
  for (const auto& p : v) quads_.insert(quads_.end(), {p[0], p[1], c.r, c.g, c.b, c.a});
}

void Hud::text(float x, float y, std::string_view s, float scale, glm::vec4 color) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto& g = glyph(s[i]);
    const float gx = x + static_cast<float>(i * kGlyphAdvance) * scale;
    for (int r = 0; r < kGlyphH; ++r)
      for (int c = 0; c < kGlyphW; ++c)
        if (g[r] & (1u << (kGlyphW - 1 - c))) rect(gx + c * scale, y + r * scale, scale, scale, color);
  }
}

void Hud::flush(int width, int height) {
  if (quads_.empty()) return;
  mesh_.upload(quads_.data(), quads_.size(), {2, 4}, GL_STREAM_DRAW);
  glUseProgram(program_);
  glUniform2f(u_size_, static_cast<float>(width), static_cast<float>(height));
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  mesh_.draw();
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  quads_.clear();
}

void Hud::scoreboard(const HudInfo& info, float s, float line) {
  std::string score = std::to_string(info.score_left) + " - " + std::to_string(info.score_right);
  if (info.pen_left || info.pen_right)
    score += " (" + std::to_string(info.pen_left) + "-" + std::to_string(info.pen_right) + ")";
  const std::string clock = clock_text(info.time), mode = play_mode_text(info.play_mode);
  const float pad = 3 * s, chip = 4 * s;
  float x = 4 * s + pad;
  const float y = 4 * s;
  const float total = chip + pad + text_width(info.left_name, s) + 3 * pad + text_width(score, s) + 3 * pad +
                      text_width(info.right_name, s) + pad + chip + 4 * pad + text_width(clock, s) + 4 * pad +
                      text_width(mode, s);
  rect(4 * s, y, total + 2 * pad, line + 2 * pad, kPanel);
  const float ty = y + pad + 2 * s;
  rect(x, y + pad, chip, line, glm::vec4(info.left_color, 1.0f));
  x += chip + pad;
  text(x, ty, info.left_name, s, kWhite);
  x += text_width(info.left_name, s) + 3 * pad;
  text(x, ty, score, s, kWhite);
  x += text_width(score, s) + 3 * pad;
  text(x, ty, info.right_name, s, kWhite);
  x += text_width(info.right_name, s) + pad;
  rect(x, y + pad, chip, line, glm::vec4(info.right_color, 1.0f));
  x += chip + 4 * pad;
  text(x, ty, clock, s, kWhite);
  x += text_width(clock, s) + 4 * pad;
  text(x, ty, mode, s, kYellow);
}

void Hud::draw(const HudInfo& info, int width, int height) {
  // Font pixels in screen pixels: readable on a laptop and on a big screen.
  const float s = std::max(1.0f, std::round(static_cast<float>(height) / 300.0f));
  const float line = (kGlyphH + 4) * s, pad = 3 * s;

  // Numbers above the players: the shirt colour with the number on it.
  const float ls = std::max(1.0f, s - 1.0f);
  for (const auto& l : info.labels) {
    const std::string n = std::to_string(l.number);
    const float w = text_width(n, ls) + 4 * ls, h = (kGlyphH + 4) * ls;
    rect(l.px.x - w / 2 - ls, l.px.y - h - ls, w + 2 * ls, h + 2 * ls, {0.0f, 0.0f, 0.0f, 0.85f});
    rect(l.px.x - w / 2, l.px.y - h, w, h, glm::vec4(l.shirt, 1.0f));
    text(l.px.x - w / 2 + 2 * ls, l.px.y - h + 2 * ls, n, ls, glm::vec4(l.text, 1.0f));
  }

  // Scoreboard, top left: [chip] LEFT  1 - 5  RIGHT [chip]   12:34   PLAY ON
  if (!info.waiting) scoreboard(info, s, line);

  // Camera and playback, bottom right.
  std::string state = info.camera;
  if (!info.chosen.empty()) state += "  " + info.chosen;
  if (!info.playback.empty()) state += "  " + info.playback;
  const float sw = text_width(state, s);
  const float by = static_cast<float>(height) - line - 2 * pad - 4 * s;
  rect(static_cast<float>(width) - sw - 2 * pad - 4 * s, by, sw + 2 * pad, line + 2 * pad, kPanel);
  text(static_cast<float>(width) - sw - pad - 4 * s, by + pad + 2 * s, state, s, kWhite);

  // What is wrong: in the middle while there is no picture, else bottom left.
  if (!info.status.empty()) {
    const float max_chars = std::max(10.0f, (static_cast<float>(width) * 0.9f) / (kGlyphAdvance * s));
    std::vector<std::string> lines;
    std::string rest = info.status;
    while (!rest.empty()) {
      std::size_t n = std::min(rest.size(), static_cast<std::size_t>(max_chars));
      if (n < rest.size()) {
        const auto sp = rest.rfind(' ', n);
        if (sp != std::string::npos && sp > n / 2) n = sp;
      }
      lines.push_back(rest.substr(0, n));
      rest = rest.substr(std::min(rest.size(), n + (n < rest.size() && rest[n] == ' ' ? 1 : 0)));
    }
    float w = 0;
    for (const auto& l : lines) w = std::max(w, text_width(l, s));
    const float h = static_cast<float>(lines.size()) * line;
    const float bx = info.waiting ? (static_cast<float>(width) - w) / 2 : 4 * s + pad;
    const float top = info.waiting ? (static_cast<float>(height) - h) / 2 : by - h - 3 * pad;
    rect(bx - pad, top - pad, w + 2 * pad, h + 2 * pad, kPanel);
    for (std::size_t i = 0; i < lines.size(); ++i)
      text(bx, top + static_cast<float>(i) * line + 2 * s, lines[i], s, kYellow);
  }
  flush(width, height);
}

}  // namespace mc::viewer
