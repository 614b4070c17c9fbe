// "director": one entry of the broadcast director's track (issue 20,
// SPEC.md section 5.5). The server sees the game a little ahead (the
// animator's look-ahead) and knows its events; from them it chooses the
// shot every client shows: which camera, on whom, framed how, and when to
// cut. Clients follow the track as TV viewers follow one broadcast; a
// spectator who picks a camera by hand leaves it until he asks it back.
//
// A cue holds from its frame (`seq`) until the next one. `cut` says whether
// the picture cuts there (a new shot) or the running shot only changes its
// subject or framing (the camera moves there smoothly); a repeated cue (the
// same shot, for late joiners) is a reframe with nothing changed.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "proto/world_state.hpp"

namespace mc::proto {

// The shots, each a camera rig the clients implement with the framing numbers.
enum class Shot : std::uint8_t {
  Wide = 0,      // the whole play from the main stand, high: kick-offs, ends
  Tracking = 1,  // from the main stand on the ball, the play ahead of it in view
  SetPiece = 2,  // behind the taker, looking at the goal he attacks (corners, free kicks)
  Attack = 3,    // tighter, on the ball and the goal it goes at (a shot developing)
  Scorer = 4,    // a close-up of the scorer, from in front of him
  Replay = 5,    // an instant replay of what just happened, from the segments' angles
};
std::string_view shot_name(Shot s);
std::optional<Shot> shot_from_name(std::string_view name);

// Where a replay segment is seen from.
enum class ReplayAngle : std::uint8_t {
  BehindGoal = 0,  // behind the net of `goal`, above the crossbar, looking out at the play
  LowSide = 1,     // at the touchline, at eye height, level with the ball
  High = 2,        // high above the main stand, the whole move in view
};
std::string_view replay_angle_name(ReplayAngle a);
std::optional<ReplayAngle> replay_angle_from_name(std::string_view name);

// A stretch of the stream to show again. `from` and `to` count frames from
// the cue's own frame (negative: before it), so that renumbering the stream
// (a looping feed, a replay of a recording) leaves them right.
struct ReplaySegment {
  int from = 0, to = 0;  // from < to
  ReplayAngle angle = ReplayAngle::BehindGoal;
  double speed = 1;      // 0.1 .. 4 times the stream's rate
};

// How a shot frames its subject (advice to a client; the server sends it
// with every shot but a replay, whose angles are fixed rigs). Metres and degrees.
struct Framing {
  double distance = 0;  // horizontal distance from the camera to the point it looks at
  double height = 0;    // camera height above the grass
  double fov = 0;       // vertical field of view
  double lead = 0;      // the point looked at is this far ahead of the subject, towards the goal `attack` attacks
};

struct DirectorCue {
  std::uint32_t seq = 0;  // the frame the cue holds from
  int time = 0;           // that frame's cycle
  bool cut = true;        // a cut to a new shot; false: the running shot moves smoothly
  Shot shot = Shot::Wide;
  // The subject: a player, or the ball when unum is 0.
  Side subject_side = Side::Neutral;
  std::uint8_t subject_unum = 0;
  // The team whose attack the framing leads (Neutral: none). rcssserver
  // never swaps ends: the left team attacks +x all game.
  Side attack = Side::Neutral;
  // The goal the shot looks at, by the team that defends it (Left: the goal
  // at x = -length/2); Neutral: none.
  Side goal = Side::Neutral;
  Framing framing;
  std::vector<ReplaySegment> replay;  // Shot::Replay only: shown in order, then back to live
};

// Bounds the parser enforces: at most 4 segments, each within 2 minutes of
// the cue and at most 1 minute long.
inline constexpr std::size_t kMaxReplaySegments = 4;
inline constexpr int kMaxReplayReachFrames = 2400;
inline constexpr int kMaxReplaySegmentFrames = 1200;

nlohmann::json director_cue_to_json(const DirectorCue& cue);
// Throws std::runtime_error with a reason when a field is missing or out of range.
DirectorCue director_cue_from_json(const nlohmann::json& j);

}  // namespace mc::proto
