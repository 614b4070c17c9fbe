#include "server/director/shot_rules.hpp"

#include <cmath>

#include "anim/kick_planner.hpp"

namespace mc::director {

Moment moment_of(PlayMode mode) {
  switch (mode) {
    case PlayMode::PlayOn:
    case PlayMode::KickInL:
    case PlayMode::KickInR:
    case PlayMode::GoalKickL:
    case PlayMode::GoalKickR:
    case PlayMode::DropBall:
      return Moment::Play;
    case PlayMode::CornerKickL:
    case PlayMode::CornerKickR:
    case PlayMode::FreeKickL:
    case PlayMode::FreeKickR:
    case PlayMode::IndirectFreeKickL:
    case PlayMode::IndirectFreeKickR:
    case PlayMode::PenaltyKickL:
    case PlayMode::PenaltyKickR:
    case PlayMode::PenaltySetupL:
    case PlayMode::PenaltySetupR:
    case PlayMode::PenaltyReadyL:
    case PlayMode::PenaltyReadyR:
    case PlayMode::PenaltyTakenL:
    case PlayMode::PenaltyTakenR:
    case PlayMode::OffsideL:
    case PlayMode::OffsideR:
    case PlayMode::FoulChargeL:
    case PlayMode::FoulChargeR:
    case PlayMode::FoulPushL:
    case PlayMode::FoulPushR:
    case PlayMode::FoulMultipleAttackL:
    case PlayMode::FoulMultipleAttackR:
    case PlayMode::FoulBalloutL:
    case PlayMode::FoulBalloutR:
    case PlayMode::BackPassL:
    case PlayMode::BackPassR:
    case PlayMode::FreeKickFaultL:
    case PlayMode::FreeKickFaultR:
    case PlayMode::CatchFaultL:
    case PlayMode::CatchFaultR:
    case PlayMode::IllegalDefenseL:
    case PlayMode::IllegalDefenseR:
      return Moment::SetPiece;
    case PlayMode::GoalL:
    case PlayMode::GoalR:
    case PlayMode::PenaltyScoreL:
    case PlayMode::PenaltyScoreR:
      return Moment::Goal;
    default:
      return Moment::Overview;
  }
}

Side restarting_side(PlayMode mode) {
  switch (mode) {
    // The mode names the team that plays the ball.
    case PlayMode::KickOffL: case PlayMode::KickInL: case PlayMode::FreeKickL: case PlayMode::CornerKickL:
    case PlayMode::GoalKickL: case PlayMode::IndirectFreeKickL: case PlayMode::PenaltyKickL:
    case PlayMode::PenaltySetupL: case PlayMode::PenaltyReadyL: case PlayMode::PenaltyTakenL:
      return Side::Left;
    case PlayMode::KickOffR: case PlayMode::KickInR: case PlayMode::FreeKickR: case PlayMode::CornerKickR:
    case PlayMode::GoalKickR: case PlayMode::IndirectFreeKickR: case PlayMode::PenaltyKickR:
    case PlayMode::PenaltySetupR: case PlayMode::PenaltyReadyR: case PlayMode::PenaltyTakenR:
      return Side::Right;
    // The mode names the offender: the other team restarts.
    case PlayMode::OffsideL: case PlayMode::FoulChargeL: case PlayMode::FoulPushL:
    case PlayMode::FoulMultipleAttackL: case PlayMode::FoulBalloutL: case PlayMode::BackPassL:
    case PlayMode::FreeKickFaultL: case PlayMode::CatchFaultL: case PlayMode::IllegalDefenseL:
      return Side::Right;
    case PlayMode::OffsideR: case PlayMode::FoulChargeR: case PlayMode::FoulPushR:
    case PlayMode::FoulMultipleAttackR: case PlayMode::FoulBalloutR: case PlayMode::BackPassR:
    case PlayMode::FreeKickFaultR: case PlayMode::CatchFaultR: case PlayMode::IllegalDefenseR:
      return Side::Left;
    default:
      return Side::Neutral;
  }
}

std::optional<Touch> touch_in(const WorldState* prev, const WorldState& cur) {
  for (std::size_t i = 0; i < cur.players.size(); ++i) {
    const PlayerState& p = cur.players[i];
    if (!p.active()) continue;
    const PlayerState* before = prev != nullptr ? &prev->players[i] : nullptr;
    const bool kicked = anim::is_successful_kick(before, p);
    const bool tackled = (p.state & state_bits::kTackle) != 0;
    const bool caught = (p.state & state_bits::kCatch) != 0 && p.goalie();
    if (kicked || tackled || caught) return Touch{p.side, p.unum};
  }
  return std::nullopt;
}

std::optional<Nearest> nearest_to_ball(const WorldState& s, Side side) {
  std::optional<Nearest> best;
  for (const PlayerState& p : s.players) {
    if (!p.active() || (side != Side::Neutral && p.side != side)) continue;
    const double d = std::hypot(p.x - s.ball.x, p.y - s.ball.y);
    if (!best || d < best->distance) best = Nearest{Touch{p.side, p.unum}, d};
  }
  return best;
}

bool attack_on(const WorldState& s, Side attacking, double radius_m) {
  const int dir = attack_sign(attacking);
  if (dir == 0) return false;
  const double goal_x = dir * kHalfLength;
  if (std::hypot(s.ball.x - goal_x, s.ball.y) < radius_m) return true;
  // A shot: fast, towards that goal line, between the posts when it gets there.
  const double vx = s.ball.vx, vy = s.ball.vy;
  if (std::hypot(vx, vy) < 1.2 || vx * dir <= 0) return false;
  const double to_line = (goal_x - s.ball.x) / vx;  // cycles (> 0)
  const double y_at_line = s.ball.y + vy * to_line;
  const double run = std::hypot(goal_x - s.ball.x, y_at_line - s.ball.y);
  return std::fabs(y_at_line) < 14.02 / 2 + 3 && run < 30;
}

}  // namespace mc::director
