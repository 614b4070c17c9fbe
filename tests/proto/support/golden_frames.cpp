#include "tests/proto/support/golden_frames.hpp"

#include "tests/proto/support/synthetic.hpp"

namespace mc::proto::testing {

Hello golden_hello() {
  Hello h;
  h.skeleton = humanoid_skeleton();
  h.keyframe_interval = kGoldenKeyframeInterval;
  h.left = {"HELIOS_A", "#ffd700", "#000000"};
  h.right = {"HELIOS_B", "#1e90ff", "#ffffff"};
  h.match_id = "golden";
  h.server_params = {{"half_time", 300}, {"simulator_step", 100}, {"ball_size", 0.085}, {"player_size", 0.3}};
  return h;
}

std::vector<PoseFrame> golden_frames(const SkeletonDef& skeleton) {
  std::vector<PoseFrame> f = scripted_frames(skeleton, kGoldenFrameCount, 3);
  f[5].players[3].state |= state_bits::kKick;            // meta change
  f[7].ball = {50.0f, 30.0f, 1.5f};                      // ball far away: escape code
  f[10].players[5].x += 40.0f;                           // teleport
  f[13].players[8].state = 0;                            // player leaves, parked
  f[13].players[8].y = -37.0f;
  for (int i = 13; i < kGoldenFrameCount; ++i) {
    f[static_cast<std::size_t>(i)].players[8] = f[13].players[8];
    f[static_cast<std::size_t>(i)].score_left = 1;
  }
  f[15].players[2].heading = 179.5f;                     // heading wraps around +-180
  f[16].players[2].heading = -179.0f;
  f[17].players[2].heading = -176.0f;
  return f;
}

}  // namespace mc::proto::testing
