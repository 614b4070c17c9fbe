#include "anim/classifier.hpp"

#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/portable_math.hpp"

namespace mc::anim {

const char* action_name(Action a) {
  static constexpr const char* kNames[kActionCount] = {
      "stand", "walk", "run", "backpedal", "side-step", "turn",
      "kick", "tackle", "catch", "dive", "teleport", "disconnected"};
  const int i = static_cast<int>(a);
  return i >= 0 && i < kActionCount ? kNames[i] : "?";
}

Action classify_raw(const ClassifyInput& in, const ClassifyParams& p) {
  const PlayerState& c = *in.cur;
  if (!c.active()) return Action::Disconnected;
  if (in.prev != nullptr && in.prev->active()) {
    const double jump = pm::hypot(c.x - in.prev->x, c.y - in.prev->y);
    const bool moved_cmd = c.counters.count > 0 && c.counters.move > in.prev->counters.move;
    if (jump > p.teleport_m || (moved_cmd && jump > 0.05)) return Action::Teleport;
  }
  if ((c.state & (state_bits::kTackle | state_bits::kTackleFault)) != 0) return Action::Tackle;
  if ((c.state & state_bits::kCatch) != 0 && c.goalie()) {
    if (in.ball != nullptr) {
      const BodyFrame body(static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.body));
      float bx, bz;
      body.to_body(static_cast<float>(in.ball->x), static_cast<float>(in.ball->y), bx, bz);
      if (std::fabs(bz) > p.dive_lateral_m) return Action::Dive;
    }
    return Action::Catch;
  }
  if ((c.state & state_bits::kKick) != 0 && (c.state & state_bits::kKickFault) == 0) {
    // With counters, a kick bit must come with a new kick command (a delayed
    // long kick keeps the bit without one).
    const bool counted = c.counters.count == 0 || in.prev == nullptr ||
                         c.counters.kick > in.prev->counters.kick;
    if (counted) return Action::Kick;
  }
  // Locomotion: centred velocity over the neighbours.
  const PlayerState& a = in.prev != nullptr && in.prev->active() ? *in.prev : c;
  const PlayerState& b = in.next != nullptr && in.next->active() ? *in.next : c;
  const double span = (&a != &c) + (&b != &c);
  double vx = 0, vy = 0;
  if (span > 0) {
    vx = (b.x - a.x) / span;
    vy = (b.y - a.y) / span;
  }
  const double v = pm::hypot(vx, vy);
  if (v < p.stand_speed) {
    const float turn = std::fabs(delta_deg(static_cast<float>(b.body), static_cast<float>(a.body)));
    return turn > p.turn_deg ? Action::Turn : Action::Stand;
  }
  const float dir = static_cast<float>(pm::atan2(vy, vx) / kDeg);
  const float off = std::fabs(delta_deg(dir, static_cast<float>(c.body)));
  if (off > 125.0f) return Action::Backpedal;
  if (off > 55.0f) return Action::SideStep;
  const double top = in.type != nullptr ? in.type->real_speed_max() : 1.0;
  return v < p.run_fraction * top ? Action::Walk : Action::Run;
}

Action smooth_action(std::span<const Action> w, std::size_t i) {
  if (i >= w.size()) return Action::Stand;
  const Action a = w[i];
  if (!is_locomotion(a) || i == 0 || i + 1 >= w.size()) return a;
  const Action l = w[i - 1], r = w[i + 1];
  if (l == r && is_locomotion(l) && l != a) return l;
  return a;
}

}  // namespace mc::anim
