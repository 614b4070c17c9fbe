#include "viewer/fatigue_pose.hpp"

#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "viewer/player_model.hpp"
#include "viewer/source.hpp"
#include "viewer/frame_buffer.hpp"

namespace mc::viewer {
namespace {

constexpr int kTorsoZ = 4, kRArmZ = 12;

TEST(FatiguePose, TirednessScale) {
  EXPECT_EQ(tiredness(8000, 8000), 0.0f);
  EXPECT_EQ(tiredness(4400, 8000), 0.0f);
  EXPECT_EQ(tiredness(1600, 8000), 1.0f);
  EXPECT_NEAR(tiredness(3000, 8000), 0.5f, 1e-6f);
  EXPECT_EQ(tiredness(-1, 8000), 0.0f) << "unknown";
}

TEST(FatiguePose, TiredPlayersLeanAndRestTheirHandsOnTheirKneesAtAStoppage) {
  FatiguePose f(anim::human_skeleton());
  ASSERT_TRUE(f.active());
  std::array<int, kMaxPlayers> stamina{};
  stamina.fill(8000);
  stamina[3] = 800;  // left 4: exhausted
  PoseFrame frame;
  frame.play_mode = PlayMode::FoulChargeR;
  frame.ball = {30, 0, 0};
  for (auto& p : frame.players) {
    p.state = 1;
    p.unum = 1;
    p.z = 1.0f;
  }
  frame.players[3].angles[kRArmZ] = 40;
  PoseFrame drawn = frame;
  for (int i = 0; i < 40; ++i) {
    drawn = frame;
    f.apply(drawn, 1.0 / 60, stamina, 8000);
  }
  EXPECT_EQ(drawn.players[0].angles[kTorsoZ], 0) << "a fresh player as the stream says";
  EXPECT_EQ(drawn.players[0].z, 1.0f);
  const PlayerPose& t = drawn.players[3];
  EXPECT_NEAR(t.z, 1.0f - hands_on_knees_drop(), 1e-4) << "lowered: the soles on the grass";
  // The right hand near the right knee (forward kinematics of the drawn pose).
  PlayerModel model(anim::human_skeleton());
  std::vector<glm::mat4> joints;
  ASSERT_TRUE(model.joints(t, joints));
  const glm::vec3 knee(joints[11][3]);                                   // r_shin
  const glm::vec3 hand(joints[6] * glm::vec4(0.0f, -0.09f, 0.0f, 1.0f));  // r_hand
  EXPECT_LT(glm::length(knee - hand), 0.1f);
  const glm::vec3 sole(joints[12] * glm::vec4(0.0f, -0.08f, 0.0f, 1.0f));  // r_foot
  EXPECT_NEAR(sole.y, 0.0f, 0.02f);
  // Play on: he stands up again (after half a second), leaning only.
  frame.play_mode = PlayMode::PlayOn;
  for (int i = 0; i < 40; ++i) {
    drawn = frame;
    f.apply(drawn, 1.0 / 60, stamina, 8000);
  }
  EXPECT_EQ(drawn.players[3].z, 1.0f);
  EXPECT_LT(drawn.players[3].angles[kTorsoZ], -10) << "leaning";
  EXPECT_LT(drawn.players[3].angles[kRArmZ], 40) << "swinging less";
}

TEST(FatiguePose, TheStaminaMessageReachesTheTrack) {
  FrameBuffer buffer;
  EXPECT_EQ(buffer.track().stamina()[0], -1);
  apply_control_message(R"({"type":"stamina","seq":20,"time":10,"left":[1,2,3,4,5,6,7,8,9,10,11],"right":[12,13,14,15,16,17,18,19,20,21,-1]})",
                        buffer);
  EXPECT_EQ(buffer.track().stamina()[3], 4);
  EXPECT_EQ(buffer.track().stamina()[21], -1);
  apply_control_message(R"({"type":"director","seq":40,"time":20,"cut":true,"shot":"wide"})", buffer);
  ASSERT_EQ(buffer.track().cues().size(), 1u);
  EXPECT_EQ(buffer.track().cues()[0].shot, proto::Shot::Wide);
}

}  // namespace
}  // namespace mc::viewer
