#include "viewer/pitch_geometry.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace mc::viewer {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kMargin = 5.0f;   // grass beyond the lines, as the page
constexpr float kApron = 40.0f;   // darker ground around it up to the horizon
const glm::vec3 kUp{0.0f, 1.0f, 0.0f};
const glm::vec3 kWhite{0.94f, 0.94f, 0.94f};

// Axis-aligned rectangle on the ground, x0..x1 (field x) by z0..z1 (field y).
void rect(std::vector<Vertex>& out, float x0, float z0, float x1, float z1, glm::vec3 color) {
  const glm::vec3 a{x0, 0, z0}, b{x1, 0, z0}, c{x1, 0, z1}, d{x0, 0, z1};
  for (const auto& p : {a, c, b, a, d, c}) out.push_back({p, kUp, color});
}

// A painted line from p to q (scene x/z), kLineWidth wide.
void line(PitchGeometry& g, glm::vec2 p, glm::vec2 q) {
  std::vector<Vertex>& out = g.markings;
  const glm::vec2 d = q - p;
  const float len = std::hypot(d.x, d.y);
  if (len <= 0) return;
  const glm::vec2 n = glm::vec2(-d.y, d.x) / len * (kLineWidth / 2);
  const glm::vec3 a{p.x + n.x, 0, p.y + n.y}, b{q.x + n.x, 0, q.y + n.y}, c{q.x - n.x, 0, q.y - n.y},
      e{p.x - n.x, 0, p.y - n.y};
  for (const auto& v : {a, c, b, a, e, c}) out.push_back({v, kUp, kWhite});
  g.center_lines.push_back({{p.x, 0, p.y}, kUp, kWhite});
  g.center_lines.push_back({{q.x, 0, q.y}, kUp, kWhite});
}

void outline(PitchGeometry& out, float x0, float z0, float x1, float z1) {
  line(out, {x0, z0}, {x1, z0});
  line(out, {x1, z0}, {x1, z1});
  line(out, {x1, z1}, {x0, z1});
  line(out, {x0, z1}, {x0, z0});
}

void arc(PitchGeometry& out, glm::vec2 c, float r, float from, float to) {
  const int n = std::max(4, static_cast<int>(std::abs(to - from) * r * 2));
  for (int i = 0; i < n; ++i) {
    const float a0 = from + (to - from) * i / n, a1 = from + (to - from) * (i + 1) / n;
    line(out, c + r * glm::vec2(std::cos(a0), std::sin(a0)), c + r * glm::vec2(std::cos(a1), std::sin(a1)));
  }
}

void spot(std::vector<Vertex>& out, glm::vec2 c, float r) {
  const int n = 12;
  for (int i = 0; i < n; ++i) {
    const float a0 = 2 * kPi * i / n, a1 = 2 * kPi * (i + 1) / n;
    out.push_back({{c.x, 0, c.y}, kUp, kWhite});
    out.push_back({{c.x + r * std::cos(a1), 0, c.y + r * std::sin(a1)}, kUp, kWhite});
    out.push_back({{c.x + r * std::cos(a0), 0, c.y + r * std::sin(a0)}, kUp, kWhite});
  }
}

void box(std::vector<ColoredBox>& out, glm::vec3 center, glm::vec3 size, glm::vec3 color) {
  out.push_back({glm::scale(glm::translate(glm::mat4(1.0f), center), size), color});
}

}  // namespace

PitchGeometry build_pitch(const proto::FieldGeometry& f) {
  PitchGeometry g;
  const float L = static_cast<float>(f.length) / 2, W = static_cast<float>(f.width) / 2;
  // Surroundings, then stripes across the length over the field and its margin.
  const glm::vec3 apron{0.20f, 0.40f, 0.18f};
  rect(g.ground, -L - kApron, -W - kApron, L + kApron, -W - kMargin, apron);
  rect(g.ground, -L - kApron, W + kMargin, L + kApron, W + kApron, apron);
  rect(g.ground, -L - kApron, -W - kMargin, -L - kMargin, W + kMargin, apron);
  rect(g.ground, L + kMargin, -W - kMargin, L + kApron, W + kMargin, apron);
  const int stripes = 18;
  const float sw = 2 * L / stripes;
  rect(g.ground, -L - kMargin, -W - kMargin, -L, W + kMargin, kGrassDark);
  rect(g.ground, L, -W - kMargin, L + kMargin, W + kMargin, kGrassDark);
  for (int i = 0; i < stripes; ++i)
    rect(g.ground, -L + i * sw, -W - kMargin, -L + (i + 1) * sw, W + kMargin, i % 2 ? kGrassDark : kGrassLight);

  auto& m = g;
  outline(m, -L, -W, L, W);
  line(m, {0, -W}, {0, W});
  arc(m, {0, 0}, static_cast<float>(f.center_circle_radius), 0, 2 * kPi);
  spot(g.markings, {0, 0}, 0.22f);
  const float pa = static_cast<float>(f.penalty_area_length), pw = static_cast<float>(f.penalty_area_width) / 2;
  const float ga = static_cast<float>(f.goal_area_length), gw = static_cast<float>(f.goal_area_width) / 2;
  const float ps = static_cast<float>(f.penalty_spot_distance), cr = static_cast<float>(f.center_circle_radius);
  for (const float s : {-1.0f, 1.0f}) {
    const float gx = s * L;
    outline(m, gx, -pw, gx - s * pa, pw);
    outline(m, gx, -gw, gx - s * ga, gw);
    const float px = gx - s * ps;
    spot(g.markings, {px, 0}, 0.22f);
    // Penalty arc: the part of the circle about the spot outside the area.
    const float a = std::acos(std::min(1.0f, (pa - ps) / cr));
    if (s < 0)
      arc(m, {px, 0}, cr, -a, a);
    else
      arc(m, {px, 0}, cr, kPi - a, kPi + a);
    for (const float t : {-1.0f, 1.0f}) {
      const float mid = std::atan2(-t, -s);  // into the field from the corner (gx, t*W)
      arc(m, {gx, t * W}, static_cast<float>(f.corner_arc_radius), mid - kPi / 4, mid + kPi / 4);
    }
  }

  // Goals: white posts and crossbar on the line, a grey frame for the net.
  const float gwh = static_cast<float>(f.goal_width) / 2, h = static_cast<float>(f.goal_height),
              d = static_cast<float>(f.goal_depth), r = 0.12f;
  const glm::vec3 net{0.75f, 0.75f, 0.78f};
  for (const float s : {-1.0f, 1.0f}) {
    const float x = s * L, xb = s * (L + d);
    for (const float t : {-1.0f, 1.0f}) {
      box(g.goals, {x + s * r / 2, h / 2, t * gwh}, {r, h, r}, kWhite);
      box(g.goals, {xb, h / 2, t * gwh}, {0.05f, h, 0.05f}, net);
      box(g.goals, {(x + xb) / 2, h, t * gwh}, {d, 0.05f, 0.05f}, net);
      box(g.goals, {(x + xb) / 2, 0.03f, t * gwh}, {d, 0.05f, 0.05f}, net);
    }
    box(g.goals, {x + s * r / 2, h, 0}, {r, r, 2 * gwh + r}, kWhite);
    box(g.goals, {xb, h, 0}, {0.05f, 0.05f, 2 * gwh}, net);
    box(g.goals, {xb, 0.03f, 0}, {0.05f, 0.05f, 2 * gwh}, net);
  }
  return g;
}

}  // namespace mc::viewer
