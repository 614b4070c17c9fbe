// Events and metadata changes: the JSON text messages that travel beside
// the binary pose frames (SPEC.md section 5). The hello is in hello.hpp.
//
// Every message is one JSON object with a "type". Events name the frame they
// belong to (`seq`, PoseFrame::seq) so a client can play a kick sound on the
// frame where the foot meets the ball; metadata changes apply from `seq` on.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "proto/director_cue.hpp"
#include "proto/hello.hpp"
#include "proto/world_state.hpp"

namespace mc::proto {

enum class Foot : std::uint8_t { Right = 0, Left = 1 };
enum class CardColor : std::uint8_t { Yellow = 1, Red = 2 };

// "kick": a foot touches the ball.
struct KickEvent {
  std::uint32_t seq = 0;
  int time = 0;                      // simulation cycle
  Side side = Side::Neutral;
  std::uint8_t unum = 0;
  Foot foot = Foot::Right;
  std::uint64_t contact_time_ms = 0; // stream time of the contact, ms since frame 0 (seq * 50 on a frame)
};

// "goal": a goal was scored by `side`; the score after it.
struct GoalEvent {
  std::uint32_t seq = 0;
  int time = 0;
  Side side = Side::Neutral;
  int score_left = 0, score_right = 0;
};

// "play_mode": the play mode changed.
struct PlayModeEvent {
  std::uint32_t seq = 0;
  int time = 0;
  PlayMode mode = PlayMode::Null;
};

// "card": a player was shown a card.
struct CardEvent {
  std::uint32_t seq = 0;
  int time = 0;
  Side side = Side::Neutral;
  std::uint8_t unum = 0;
  CardColor card = CardColor::Yellow;
};

// "score": metadata, the score (also sent after a goal and to late joiners).
struct ScoreUpdate {
  std::uint32_t seq = 0;
  int time = 0;
  int left = 0, right = 0;
  int pen_left = 0, pen_right = 0;   // penalty shoot-out goals
};

// "teams": metadata, team names and colours (a team connected late, or a new game).
struct TeamsUpdate {
  std::uint32_t seq = 0;
  TeamHello left, right;
};

// "feed": metadata, the live feed from rcssserver was lost or is back.
struct FeedStatus {
  bool lost = true;
  std::uint32_t seq = 0;             // the last frame sent before the change
  std::uint64_t server_time_ms = 0;  // Unix ms when the relay noticed
  std::string detail;                // human-readable reason
};

// "stamina": metadata, each player's stamina, once a second (rcssserver's
// units, 0..stamina_max of the hello's server parameters; -1 for a slot
// with no player). The pose frames do not carry it: it changes slowly.
struct StaminaUpdate {
  std::uint32_t seq = 0;
  int time = 0;
  std::array<int, 11> left{}, right{};  // by unum - 1
};

// "reach_map": optional analysis overlay (issue 9), a few times per second
// when the feed is asked for it: which team gets first to each cell of a grid
// over the pitch (anim/mocap's capability model), and who gets first to the
// ball. On the wire `cells` is run-length coded (SPEC.md section 5.4).
struct ReachMapUpdate {
  std::uint32_t seq = 0;
  int time = 0;
  int width = 0, height = 0;         // cells, at most 512 x 512
  double cell = 2;                   // m
  double x0 = -53, y0 = -34;         // m, lower corner of cell (0, 0) in field coordinates
  // width * height characters, row by row (y major, +y first as in the field
  // frame): 'n' nobody, 'l' left team first, 'r' right team first, 'c' contested.
  std::string cells;
  Side ball_side = Side::Neutral;    // who gets to the ball first (Neutral: nobody)
  std::uint8_t ball_unum = 0;
  double ball_time = 0;              // s from this frame
};

// The "stamina" message of a state: every player's stamina, -1 for an empty slot.
StaminaUpdate stamina_update(const WorldState& state);

// DirectorCue ("director", the broadcast director's track) is in director_cue.hpp.
using ControlMessage =
    std::variant<KickEvent, GoalEvent, PlayModeEvent, CardEvent, ScoreUpdate, TeamsUpdate, FeedStatus, ReachMapUpdate,
                 StaminaUpdate, DirectorCue>;

nlohmann::json control_to_json_value(const ControlMessage& message);
std::string to_json(const ControlMessage& message);  // one line

// False with `error` when the text is not a JSON object, has no "type", the
// type is not one of the above ("hello" included: use hello_from_json), or a
// field is missing or out of range. A client skips unknown types.
bool control_from_json(std::string_view text, ControlMessage& out, std::string& error);

// Moves a message `frames` frames along the stream: its seq, and a kick's
// contact time by frames * kFrameIntervalMs. A relay that renumbers frames
// (a looping feed, a replay) renumbers their events the same way.
void shift_frames(ControlMessage& message, std::int64_t frames);

// The "type" of any control message text (hello included), "" + error when
// there is none; for routing before parsing.
std::string control_type(std::string_view text, std::string& error);

}  // namespace mc::proto
