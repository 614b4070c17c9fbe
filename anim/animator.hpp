// The animator: 10 Hz 2D world states in, 20 Hz 3D pose frames out.
//
// It is a pure function of the states pushed so far and of the settings:
// the animation never waits for rendering, and equal input gives byte-equal
// output. Each state is held back until `lookahead_cycles` following states
// have arrived (the paper's delayed timeline), then its two frames leave:
// substep 0 exactly at the cycle (the root lies on the 2D position), substep
// 1 half-way to the next cycle (the root interpolated; a kick's contact falls
// here, see kick_planner.hpp).
//
// Frames leave with server_time_ms = 0; the relay stamps it. Player poses
// follow human_skeleton.hpp's placement convention: x, y in field metres, z
// the pelvis height, heading in field degrees, angles per the skeleton.
//
// Per cycle and player: the classifier (classifier.hpp) decides what the
// player does, smoothed over the neighbouring cycles; kicks, tackles, catches
// and dives seen in the look-ahead are planned (kick_planner.hpp) so that a
// kick's preparation starts before its contact; then every frame poses the
// player (player_animation.hpp). Detail levels (AnimConfig::detail) switch
// locomotion and actions off; events are reported at every level.
//
// Events: PlayMode, Goal and Card on the first frame of the cycle that shows
// them; Kick on its contact frame (the half-way frame before the cycle whose
// state carries the kick). event_messages.hpp turns them into the stream's
// control messages.
//
// Memory: the constructor sizes every buffer; push() and finish() allocate
// only when the caller's output vectors grow.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "anim/anim_config.hpp"
#include "anim/anim_events.hpp"
#include "anim/classifier.hpp"
#include "anim/leg_blend.hpp"
#include "proto/game_params.hpp"
#include "proto/pose_frame.hpp"
#include "proto/quantizer.hpp"
#include "proto/skeleton.hpp"
#include "proto/world_state.hpp"

namespace mc::anim {

struct PlayerAnim;  // per-player animation context (player_animation.hpp)

// What the animator decided for one player at one frame: for the quality
// tool and tests, not for clients.
struct PlayerFrameInfo {
  Action action = Action::Stand;  // smoothed decision of the frame's cycle
  bool in_action = false;         // a kick, tackle, catch or dive motion is playing
  bool reset = false;             // teleported or (re)connected: the pose jumped on purpose
  bool planted[2] = {false, false};  // feet the animator keeps fixed on the grass: [0] right, [1] left
};
struct FrameInfo {
  std::uint32_t seq = 0;
  std::array<PlayerFrameInfo, kMaxPlayers> players{};
};

class Animator {
 public:
  // `skeleton` must be human_skeleton() (the motion code knows its joints) and
  // outlive the animator. lookahead_cycles below 1 is raised to 1.
  Animator(const SkeletonDef& skeleton, const GameParams& params, AnimConfig config = {});
  ~Animator();
  Animator(const Animator&) = delete;
  Animator& operator=(const Animator&) = delete;

  // Feed the next 10 Hz state in stream order. Appends the 20 Hz frames that
  // became final (two per state once the look-ahead is filled), and, when
  // `events` is given, the events of those frames.
  void push(const WorldState& state, std::vector<PoseFrame>& out,
            std::vector<AnimEvent>* events = nullptr);
  // End of input: appends the frames still held back by the look-ahead (two
  // per state; the last state's half-way frame holds still).
  void finish(std::vector<PoseFrame>& out, std::vector<AnimEvent>* events = nullptr);

  // Optional: also append one FrameInfo per emitted frame to `sink` (null
  // to stop). The sink must outlive the pushes that use it.
  void set_frame_info_sink(std::vector<FrameInfo>* sink) { info_sink_ = sink; }

  const AnimConfig& config() const { return config_; }
  // The smoothed decision for one player at the last emitted cycle (for
  // tools and tests); Stand before any frame left.
  Action last_action(int player_slot) const;

 private:
  const WorldState& state_at(std::uint64_t pos) const;
  Action raw_action(std::uint64_t pos, int slot) const;
  Action action_at(std::uint64_t pos, int slot) const;
  float smoothed_heading(std::uint64_t pos, int slot) const;
  void emit_cycle(std::uint64_t pos, std::vector<PoseFrame>& out, std::vector<AnimEvent>* events);
  void emit_events(std::uint64_t pos, std::vector<AnimEvent>& events) const;
  void plan_actions(std::uint64_t pos, int slot);

  const SkeletonDef& skeleton_;
  GameParams params_;
  // The server parameters the frames use, looked up once: each lookup is a
  // map search by name, and they were 3 % of the animation's time.
  struct Constants {
    double step_ms = 100, ball_size = 0.085, tackle_cycles = 10, stamina_max = 8000;
  } k_;
  AnimConfig config_;
  proto::Quantizer grid_;         // the stream's: frames leave on it (grid_rounding.hpp)
  LegBlend drawn_legs_;           // the clients' step between frames (drawn_leg_clearance.hpp)
  std::vector<WorldState> ring_;  // the last ring_.size() states, by stream position
  // Per ring slot and player, the cosine and sine of the body's heading,
  // taken once as the state arrives: smoothed_heading reads each state's
  // over a window, several times a cycle (0.8 % of the animation's
  // instructions).
  struct HeadingUnit {
    double c = 1, s = 0;
  };
  std::vector<HeadingUnit> heading_unit_;
  // raw_action's last answer per ring slot and player, and what it was made from.
  struct RawDecision {
    std::uint64_t pos = ~std::uint64_t{0};
    bool has_prev = false, has_next = false;
    Action action = Action::Stand;
  };
  mutable std::vector<RawDecision> raw_memo_;
  std::uint64_t pushed_ = 0;      // states received
  std::uint64_t emitted_ = 0;     // cycles whose frames have left
  std::unique_ptr<std::array<PlayerAnim, kMaxPlayers>> players_;
  std::vector<FrameInfo>* info_sink_ = nullptr;
};

}  // namespace mc::anim
