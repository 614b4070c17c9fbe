#include "anim/tools/strip_plot.hpp"

#include <cmath>
#include <cstdlib>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/tools/metrics.hpp"

namespace mc::anim::tools {
namespace {

struct Rgb { std::uint8_t r, g, b; };

void line(Image& img, int x0, int y0, int x1, int y1, Rgb c, int thick = 2) {
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  int err = dx + dy;
  for (;;) {
    for (int ox = 0; ox < thick; ++ox)
      for (int oy = 0; oy < thick; ++oy) img.set(x0 + ox, y0 + oy, c.r, c.g, c.b);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) { err += dy; x0 += sx; }
    if (e2 <= dx) { err += dx; y0 += sy; }
  }
}

void circle(Image& img, int cx, int cy, int r, Rgb c) {
  for (int a = 0; a < 64; ++a) {
    const float t0 = static_cast<float>(a) * 2 * kPi / 64, t1 = static_cast<float>(a + 1) * 2 * kPi / 64;
    line(img, cx + static_cast<int>(r * std::cos(t0)), cy + static_cast<int>(r * std::sin(t0)),
         cx + static_cast<int>(r * std::cos(t1)), cy + static_cast<int>(r * std::sin(t1)), c, 1);
  }
}

Rgb colour_of(const std::string& name) {
  if (name.rfind("r_", 0) == 0) return {200, 30, 30};
  if (name.rfind("l_", 0) == 0) return {30, 60, 200};
  return {30, 30, 30};
}

}  // namespace

void draw_pose_row(Image& img, int row, const SkeletonDef& skel, const std::vector<const PoseFrame*>& frames,
                   int slot, float view_heading) {
  const int ground = row * kRowPx + kRowPx - 15;
  line(img, 0, ground, img.width - 1, ground, {120, 160, 120}, 1);
  const float fc = std::cos(view_heading * kDeg), fs = std::sin(view_heading * kDeg);
  for (std::size_t c = 0; c < frames.size(); ++c) {
    const PoseFrame& f = *frames[c];
    const PlayerPose& pose = f.players[static_cast<std::size_t>(slot)];
    const int cx = static_cast<int>(c) * kCellPx + kCellPx / 2;
    // Side view: forward along view_heading to the right, height up.
    auto project = [&](glm::vec3 p, int& px, int& py) {
      const float fwd = (p.x - pose.x) * fc + (p.y - pose.y) * fs;
      px = cx + static_cast<int>(std::lround(fwd * kPxPerM));
      py = ground - static_cast<int>(std::lround(p.z * kPxPerM));
    };
    line(img, static_cast<int>(c) * kCellPx, row * kRowPx, static_cast<int>(c) * kCellPx, ground, {220, 220, 220}, 1);
    std::vector<glm::vec3> joints(skel.joints.size());
    for (std::size_t j = 0; j < skel.joints.size(); ++j)
      joints[j] = joint_point_field(skel, pose, static_cast<int>(j), glm::vec3(0));
    for (std::size_t j = 1; j < skel.joints.size(); ++j) {
      int x0, y0, x1, y1;
      project(joints[static_cast<std::size_t>(skel.joints[j].parent)], x0, y0);
      project(joints[j], x1, y1);
      line(img, x0, y0, x1, y1, colour_of(skel.joints[j].name));
    }
    for (int foot : {kRFoot, kLFoot, kRHand, kLHand}) {  // feet and hands as bones to their tips
      const bool is_foot = foot == kRFoot || foot == kLFoot;
      const glm::vec3 tip = joint_point_field(skel, pose, foot, is_foot ? glm::vec3(0.19f, -0.06f, 0) : glm::vec3(0, -0.16f, 0));
      int x0, y0, x1, y1;
      project(joints[static_cast<std::size_t>(foot)], x0, y0);
      project(tip, x1, y1);
      line(img, x0, y0, x1, y1, colour_of(skel.joints[static_cast<std::size_t>(foot)].name));
    }
    int hx, hy;
    project(joint_point_field(skel, pose, kHead, glm::vec3(0.02f, 0.10f, 0)), hx, hy);
    circle(img, hx, hy, static_cast<int>(0.11f * kPxPerM), {30, 30, 30});
    const glm::vec3 ball(f.ball.x, f.ball.y, f.ball.z);
    int bx, by;
    project(ball, bx, by);
    if (std::abs(bx - cx) < kCellPx / 2) circle(img, bx, by, std::max(3, static_cast<int>(0.085f * kPxPerM)), {20, 150, 20});
  }
}

}  // namespace mc::anim::tools
