// Fatigue on the body where the viewer draws it (issue 20), as the page
// does (web/src/model/fatigue.js): from the stream's "stamina" message, a
// tired player leans forward, swings his arms less, and at a stoppage,
// standing away from the ball, puts his hands on his knees (the pelvis
// lowered so that the soles stay on the grass). Only for anim's skeleton
// (matchcast-human-16); the stream stays exact.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::viewer {

// 0 at 55 % of stamina_max and above, 1 at 20 % and below; 0 when unknown (< 0).
float tiredness(float stamina, float stamina_max);
// How far the hands-on-knees pose lowers the pelvis (m).
float hands_on_knees_drop();

class FatiguePose {
 public:
  explicit FatiguePose(const SkeletonDef& skeleton);
  bool active() const { return ok_; }
  // Changes the drawn frame in place: angles and pelvis height. `stamina`
  // by player slot (player_index), -1 unknown; dt seconds since the last call.
  void apply(PoseFrame& frame, double dt, const std::array<int, kMaxPlayers>& stamina, float stamina_max);

 private:
  struct State {
    bool seen = false;
    float x = 0, y = 0, speed = 0, w = 0;
  };
  bool ok_ = false;
  int torso_z_ = -1, neck_z_ = -1;
  std::array<int, 2> arms_{-1, -1}, elbows_{-1, -1};
  std::vector<std::pair<int, float>> pose_;  // angle index, degrees
  std::array<State, kMaxPlayers> state_{};
};

}  // namespace mc::viewer
