// The 2D world state: one snapshot of a RoboCup Soccer Simulation 2D game,
// as rcssserver describes it once per 100 ms simulation cycle.
//
// This is the vocabulary shared by every stage: ingest produces it (from
// logs or the live monitor feed), anim consumes it. It lives at the bottom of
// the dependency graph so that anim never reaches up into server/.
//
// Units and frames are rcssserver's own (see server/ingest/rcss-protocol.md
// section 1): metres, field origin at the centre spot, +x towards the right
// team's goal, +y towards the bottom touchline; angles in degrees from +x
// towards +y; velocities in metres per cycle. Nothing is mirrored.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace mc {

enum class Side : std::int8_t { Neutral = 0, Left = 1, Right = -1 };

// Player state bits, rcssserver src/types.h `enum PlayerState`.
namespace state_bits {
inline constexpr std::uint32_t kDisable = 0x00000000;
inline constexpr std::uint32_t kStand = 0x00000001;
inline constexpr std::uint32_t kKick = 0x00000002;
inline constexpr std::uint32_t kKickFault = 0x00000004;
inline constexpr std::uint32_t kGoalie = 0x00000008;
inline constexpr std::uint32_t kCatch = 0x00000010;
inline constexpr std::uint32_t kCatchFault = 0x00000020;
inline constexpr std::uint32_t kBallToPlayer = 0x00000040;
inline constexpr std::uint32_t kPlayerToBall = 0x00000080;
inline constexpr std::uint32_t kDiscard = 0x00000100;
inline constexpr std::uint32_t kLost = 0x00000200;
inline constexpr std::uint32_t kBallCollide = 0x00000400;
inline constexpr std::uint32_t kPlayerCollide = 0x00000800;
inline constexpr std::uint32_t kTackle = 0x00001000;
inline constexpr std::uint32_t kTackleFault = 0x00002000;
inline constexpr std::uint32_t kBackPass = 0x00004000;
inline constexpr std::uint32_t kFreeKickFault = 0x00008000;
inline constexpr std::uint32_t kPostCollide = 0x00010000;
inline constexpr std::uint32_t kFoulCharged = 0x00020000;
inline constexpr std::uint32_t kYellowCard = 0x00040000;
inline constexpr std::uint32_t kRedCard = 0x00080000;
inline constexpr std::uint32_t kIllegalDefense = 0x00100000;
}  // namespace state_bits

// Play modes, rcssserver src/types.h `PLAYMODE_STRINGS`; the numbering is
// stable across server versions (the list only grew at the end).
enum class PlayMode : std::uint8_t {
  Null = 0, BeforeKickOff, TimeOver, PlayOn, KickOffL, KickOffR, KickInL, KickInR,
  FreeKickL, FreeKickR, CornerKickL, CornerKickR, GoalKickL, GoalKickR, GoalL, GoalR,
  DropBall, OffsideL, OffsideR, PenaltyKickL, PenaltyKickR, FirstHalfOver, Pause,
  HumanJudge, FoulChargeL, FoulChargeR, FoulPushL, FoulPushR, FoulMultipleAttackL,
  FoulMultipleAttackR, FoulBalloutL, FoulBalloutR, BackPassL, BackPassR,
  FreeKickFaultL, FreeKickFaultR, CatchFaultL, CatchFaultR, IndirectFreeKickL,
  IndirectFreeKickR, PenaltySetupL, PenaltySetupR, PenaltyReadyL, PenaltyReadyR,
  PenaltyTakenL, PenaltyTakenR, PenaltyMissL, PenaltyMissR, PenaltyScoreL,
  PenaltyScoreR, IllegalDefenseL, IllegalDefenseR,
};
inline constexpr int kPlayModeCount = 52;

// rcssserver's name for a play mode ("play_on"); "" for Null.
std::string_view play_mode_name(PlayMode mode);
// The inverse; nullopt for a name rcssserver does not define.
std::optional<PlayMode> play_mode_from_name(std::string_view name);

struct BallState {
  double x = 0, y = 0;    // m
  double vx = 0, vy = 0;  // m/cycle
};

// Cumulative command counters since the start of the game. Logs v4/v5 and
// monitor v3/v4 carry 11, ULG6 and monitor v5 carry 12 (change_focus), JSON
// monitor shows none: `count` says how many were present.
struct CommandCounters {
  std::uint32_t kick = 0, dash = 0, turn = 0, catch_ = 0, move = 0, turn_neck = 0,
                change_view = 0, say = 0, tackle = 0, pointto = 0, attentionto = 0,
                change_focus = 0;
  std::uint8_t count = 0;
};

struct PlayerState {
  Side side = Side::Neutral;
  std::uint8_t unum = 0;       // 1..11
  std::int16_t type = 0;       // heterogeneous player type id
  std::uint32_t state = 0;     // state_bits
  double x = 0, y = 0;         // m, global
  double vx = 0, vy = 0;       // m/cycle
  double body = 0;             // deg, global
  double neck = 0;             // deg, relative to body
  std::optional<std::array<double, 2>> point;  // global point the arm points at
  char view_quality = 'h';     // 'h' high, 'l' low
  double view_width = 0;       // deg
  std::optional<std::array<double, 2>> focus_point;  // (dist m, dir deg), ULG6/monitor v5
  double stamina = 0, effort = 0, recovery = 0;
  std::optional<double> capacity;  // ULG5+/monitor v4+
  std::optional<std::pair<Side, std::uint8_t>> attention;  // (f SIDE UNUM)
  CommandCounters counters;

  // On the pitch and playing (rcss-protocol.md section 7, rule of thumb).
  bool active() const { return (state & state_bits::kStand) != 0; }
  bool goalie() const { return (state & state_bits::kGoalie) != 0; }
};

struct TeamInfo {
  std::string name;  // "" when unknown; rcssserver writes "null" for no team
  int score = 0;
  int pen_score = 0, pen_miss = 0;
};

inline constexpr int kPlayersPerSide = 11;
inline constexpr int kMaxPlayers = 2 * kPlayersPerSide;

// Player slot in WorldState::players: left 1..11 then right 1..11, the order
// rcssserver uses in every show.
constexpr int player_index(Side side, int unum) {
  return (side == Side::Left ? 0 : kPlayersPerSide) + (unum - 1);
}

struct WorldState {
  // Position in the stream, counting from 0. Shows repeat `time` during
  // stoppages (about 50 shows after a goal), so order is the only key.
  std::uint64_t index = 0;
  int time = 0;       // game cycle as printed by the server
  int stoppage = 0;   // shows seen at this same `time` before this one
  PlayMode play_mode = PlayMode::Null;
  TeamInfo left, right;
  BallState ball;
  std::array<PlayerState, kMaxPlayers> players{};
};

}  // namespace mc
