// The head and neck at human speed where the viewer draws them (issue 20),
// as the page does (web/src/model/neck.js): the stream carries the agent's
// neck exactly, and rcssserver turns a neck up to 180 degrees in a cycle.
// The drawn neck and head angles follow the stream's with a short lag, and
// their combined turn about each axis never exceeds 600 deg/s; they arrive
// where the stream says, so the head still shows where the agent looks.
#pragma once

#include <array>
#include <vector>

#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::viewer {

inline constexpr float kMaxHeadDegPerS = 600.0f;

// One step of `cur` towards `target` over dt seconds, in place, on the
// angle indices of `groups` (each group's summed change is what is
// limited; every index moves by the same fraction). A first-order lag of
// `tau` seconds eases the end of a turn. Returns the fraction moved.
float limit_turn(float* cur, const float* target, const std::vector<std::vector<int>>& groups, double dt,
                 float max_deg_per_s = kMaxHeadDegPerS, float tau = 0.05f);

class HeadSmoother {
 public:
  explicit HeadSmoother(const SkeletonDef& skeleton);

  // Replaces the neck and head angles of every player of `frame` (the
  // blended frame about to be drawn) by the drawn ones, dt seconds after
  // the last call. A first sight, a pause over 0.5 s or a teleport (over
  // 3 m: a kick-off move, a seek) snaps to the stream.
  void apply(PoseFrame& frame, double dt);

 private:
  struct Drawn {
    bool valid = false;
    float x = 0, y = 0;
    std::array<float, kMaxDof> angles{};
  };
  std::vector<std::vector<int>> groups_;  // angle indices of the neck and head, by axis
  std::vector<int> indices_;
  std::array<Drawn, kMaxPlayers> drawn_{};
};

}  // namespace mc::viewer
