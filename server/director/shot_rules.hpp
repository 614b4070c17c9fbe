// The director's reading of one 2D state: what kind of moment it is (play,
// a set piece, a stoppage), who restarts play, who touched the ball, whether
// an attack is on. Pure functions of the states; the Director (director.hpp)
// turns them into shots and cuts.
#pragma once

#include <cstdint>
#include <optional>

#include "proto/director_cue.hpp"
#include "proto/world_state.hpp"

namespace mc::director {

// rcssserver's pitch (serverparam.h: PITCH_LENGTH 105, PITCH_WIDTH 68,
// goal_width 14.02): fixed by the server, not announced.
inline constexpr double kHalfLength = 52.5;
inline constexpr double kHalfWidth = 34.0;

// What a play mode asks of the camera.
enum class Moment : std::uint8_t {
  Overview,  // before a kick-off, a kick-off, half time, time over: the wide shot
  Play,      // play on, and the quick restarts (kick-in, goal kick, drop ball)
  SetPiece,  // corners, free kicks, penalties, and the fouls and offsides that lead to them
  Goal,      // the goal play mode (the goal sequence is the Director's)
};
Moment moment_of(PlayMode mode);

// The team that restarts play in `mode` (the free kick's team after a foul
// of the other), Neutral when the mode names none.
Side restarting_side(PlayMode mode);

// The direction a team attacks: +1 for the left team (towards +x), -1 for
// the right one, 0 for Neutral. rcssserver never swaps ends.
inline int attack_sign(Side s) { return s == Side::Left ? 1 : s == Side::Right ? -1 : 0; }
inline Side opponent(Side s) { return s == Side::Left ? Side::Right : s == Side::Right ? Side::Left : Side::Neutral; }

// A player who touched the ball in `cur`: a successful kick (anim's rule,
// kick_planner.hpp), a tackle or a goalie's catch. The first found, left
// team first; nullopt when nobody did.
struct Touch {
  Side side = Side::Neutral;
  std::uint8_t unum = 0;
};
std::optional<Touch> touch_in(const WorldState* prev, const WorldState& cur);

// The active player of `side` (any side when Neutral) nearest the ball,
// with his distance; nullopt when there is none.
struct Nearest {
  Touch who;
  double distance = 0;
};
std::optional<Nearest> nearest_to_ball(const WorldState& s, Side side);

// An attack on the goal `attacking` attacks: the ball within `radius_m` of
// that goal's centre, or a ball fast (> 1.2 m/cycle) on a line that crosses
// the goal line between the posts (with 3 m to spare) within 30 m.
bool attack_on(const WorldState& s, Side attacking, double radius_m);

}  // namespace mc::director
