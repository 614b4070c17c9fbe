#include "viewer/closeup_aim.hpp"

#include <algorithm>

namespace mc::viewer {
namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;
// The camera's offset from its subject at bearing 0 (field m): a little
// behind him towards -x, 4.6 m towards the main stand (+y).
constexpr glm::vec2 kOffset{-1.2f, 4.6f};

bool blocked_at(glm::vec2 subject, std::span<const glm::vec2> others, int index) {
  const glm::vec2 cam = closeup_spot(subject, kCloseupBearingsDeg[static_cast<std::size_t>(index)]);
  return std::any_of(others.begin(), others.end(), [&](glm::vec2 o) { return closeup_blocks(cam, subject, o); });
}

}  // namespace

glm::vec2 closeup_spot(glm::vec2 subject, float bearing_deg) {
  const float c = std::cos(bearing_deg * kDeg), s = std::sin(bearing_deg * kDeg);
  return {subject.x + kOffset.x * c - kOffset.y * s, subject.y + kOffset.x * s + kOffset.y * c};
}

bool closeup_blocks(glm::vec2 cam, glm::vec2 subject, glm::vec2 other, float radius) {
  const glm::vec2 v = subject - cam, o = other - cam;
  const float len2 = v.x * v.x + v.y * v.y;
  if (!(len2 > 1e-6f)) return false;
  const float t = (o.x * v.x + o.y * v.y) / len2;
  if (!(t > 0)) return false;  // behind the camera (or no position)
  const float near = std::hypot(o.x, o.y);
  if (near < kNearCameraM) {
    // The angle off the line of sight, less the body's own half width as
    // seen from the camera.
    const float off = std::acos(std::min(1.0f, (o.x * v.x + o.y * v.y) / (near * std::sqrt(len2))));
    const float half = std::asin(std::min(1.0f, radius / near));
    if ((off - half) / kDeg < kPictureHalfDeg) return true;
  }
  if (!(t < 1)) return false;  // beyond the subject
  const glm::vec2 p = cam + v * t - other;
  return p.x * p.x + p.y * p.y < radius * radius;
}

int clear_bearing(glm::vec2 subject, std::span<const glm::vec2> others, int current) {
  const int n = static_cast<int>(kCloseupBearingsDeg.size());
  const int cur = current >= 0 && current < n ? current : 0;
  if (!blocked_at(subject, others, cur)) return cur;
  int best = cur;
  float best_turn = INFINITY;
  for (int i = 0; i < n; ++i) {
    const float turn = std::fabs(kCloseupBearingsDeg[static_cast<std::size_t>(i)] -
                                 kCloseupBearingsDeg[static_cast<std::size_t>(cur)]);
    if (i != cur && turn < best_turn && !blocked_at(subject, others, i)) {
      best = i;
      best_turn = turn;
    }
  }
  return best;
}

glm::vec2 CloseupAim::update(double dt, double at, glm::vec2 subject, std::span<const glm::vec2> others) {
  const bool moving = std::isnan(at) || at != at_;
  at_ = at;
  const int clear = clear_bearing(subject, others, bearing_);
  blocked_ = clear == bearing_ ? 0.0 : blocked_ + (moving && dt > 0 ? dt : 0.0);
  if (blocked_ > kCloseupPatienceS) {
    bearing_ = clear;
    blocked_ = 0;
  }
  return closeup_spot(subject, kCloseupBearingsDeg[static_cast<std::size_t>(bearing_)]);
}

}  // namespace mc::viewer
