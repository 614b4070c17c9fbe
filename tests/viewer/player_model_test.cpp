// A player on the pitch: forward kinematics placed in scene space, kits.
#include "viewer/player_model.hpp"

#include <gtest/gtest.h>

#include "anim/human_skeleton.hpp"
#include "viewer/camera.hpp"

namespace mc::viewer {
namespace {

PlayerPose standing(float x, float y, float heading) {
  PlayerPose p;
  p.side = Side::Left;
  p.unum = 7;
  p.state = 1;
  p.x = x;
  p.y = y;
  p.z = 0.95f;
  p.heading = heading;
  return p;
}

TEST(PlayerModel, ThePelvisSitsAtTheFramesRootPosition) {
  const PlayerModel model(anim::human_skeleton());
  std::vector<glm::mat4> joints;
  ASSERT_TRUE(model.joints(standing(12.0f, -7.0f, 30.0f), joints));
  ASSERT_EQ(joints.size(), anim::human_skeleton().joints.size());
  const glm::vec3 pelvis(joints[0][3]);
  EXPECT_NEAR(pelvis.x, 12.0f, 1e-4);
  EXPECT_NEAR(pelvis.y, 0.95f, 1e-4);
  EXPECT_NEAR(pelvis.z, -7.0f, 1e-4);
  // The head is above the pelvis, the feet near the grass.
  const glm::vec3 head(joints[static_cast<std::size_t>(model.head_joint())][3]);
  EXPECT_GT(head.y, pelvis.y + 0.5f);
  const int foot = anim::human_skeleton().find("r_foot");
  ASSERT_GE(foot, 0);
  EXPECT_LT(joints[static_cast<std::size_t>(foot)][3].y, 0.3f);
}

TEST(PlayerModel, TheHeadingTurnsTheBodyLikeTheField) {
  const PlayerModel model(anim::human_skeleton());
  std::vector<glm::mat4> joints;
  // Heading 90: facing field +y, which is scene +Z; body +X must point there.
  ASSERT_TRUE(model.joints(standing(0.0f, 0.0f, 90.0f), joints));
  const glm::vec3 forward = glm::vec3(joints[0] * glm::vec4(1, 0, 0, 0));
  EXPECT_NEAR(forward.x, 0.0f, 1e-5);
  EXPECT_NEAR(forward.z, 1.0f, 1e-5);
  ASSERT_TRUE(model.joints(standing(0.0f, 0.0f, 0.0f), joints));
  EXPECT_NEAR(glm::vec3(joints[0] * glm::vec4(1, 0, 0, 0)).x, 1.0f, 1e-5);
}

TEST(PlayerModel, SegmentsAndTheChestAreFoundFromTheSkeleton) {
  const PlayerModel model(anim::human_skeleton());
  EXPECT_EQ(model.chest_joint(), anim::human_skeleton().find("torso"));
  EXPECT_EQ(model.head_joint(), anim::human_skeleton().find("head"));
  std::vector<glm::mat4> joints;
  std::vector<SegmentInstance> segments;
  ASSERT_TRUE(model.joints(standing(0, 0, 0), joints));
  model.segments(joints, segments);
  EXPECT_EQ(segments.size(), anim::human_skeleton().joints.size());
  int spheres = 0;
  for (const auto& s : segments) spheres += s.sphere;
  EXPECT_EQ(spheres, 1);  // the head
  const glm::vec3 chest = model.segment_center(joints, model.chest_joint());
  EXPECT_GT(chest.y, 1.0f);
  EXPECT_LT(chest.y, 1.6f);
}

TEST(PlayerModel, AMalformedSkeletonIsRefusedNotPosed) {
  SkeletonDef bad;
  bad.joints.push_back({"a", 1, {0, 0, 0}, "", {}, {}});  // parent after child
  bad.joints.push_back({"b", 0, {0, 0, 0}, "", {}, {}});
  const PlayerModel model(bad);
  std::vector<glm::mat4> joints;
  EXPECT_FALSE(model.joints(standing(0, 0, 0), joints));
  const PlayerModel empty{SkeletonDef{}};
  EXPECT_FALSE(empty.joints(standing(0, 0, 0), joints));
}

TEST(PlayerModel, PartsColoursAndKits) {
  EXPECT_EQ(part_of("head"), Part::Skin);
  EXPECT_EQ(part_of("r_lower_arm"), Part::Skin);
  EXPECT_EQ(part_of("l_foot"), Part::Boot);
  EXPECT_EQ(part_of("r_shin"), Part::Sock);
  EXPECT_EQ(part_of("pelvis"), Part::Shorts);
  EXPECT_EQ(part_of("torso"), Part::Shirt);
  const glm::vec3 red = parse_color("#d62828", glm::vec3(0.0f));
  EXPECT_NEAR(red.r, 214 / 255.0f, 1e-6);
  EXPECT_NEAR(red.g, 40 / 255.0f, 1e-6);
  EXPECT_EQ(parse_color("#fff", glm::vec3(0.0f)), glm::vec3(1.0f));
  EXPECT_EQ(parse_color("red", glm::vec3(0.5f)), glm::vec3(0.5f));
  EXPECT_EQ(parse_color("#12345g", glm::vec3(0.5f)), glm::vec3(0.5f));
  proto::TeamHello team;
  team.color = "#d62828";
  const Kit kit = team_kit(team, Side::Left, false);
  EXPECT_EQ(kit.shirt, red);
  EXPECT_EQ(kit.number, glm::vec3(1.0f));  // white on a dark red shirt
  const Kit keeper = team_kit(team, Side::Left, true);
  EXPECT_NE(keeper.shirt, red);
}

}  // namespace
}  // namespace mc::viewer
