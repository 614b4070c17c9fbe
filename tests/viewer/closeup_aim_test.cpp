// The viewer's close-up keeps its subject in sight by the page's rules
// (viewer/closeup_aim.hpp, web/src/model/sightline.js; the same cases as
// tests/web/sightline.test.mjs): a player between the camera and its
// subject, or just beside the camera in its picture, is in the way, and
// the camera cuts to the nearest clear bearing once he stays there for a
// while as the game moves.
#include "viewer/closeup_aim.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "viewer/camera.hpp"

namespace mc::viewer {
namespace {

const glm::vec2 kSubject{10.0f, -5.0f};

glm::vec2 in_the_way(int bearing) {
  const glm::vec2 cam = closeup_spot(kSubject, kCloseupBearingsDeg[static_cast<std::size_t>(bearing)]);
  return 0.5f * (cam + kSubject);
}

// `ahead` m along the camera's line of sight and `aside` m across it.
glm::vec2 from_camera(glm::vec2 cam, float ahead, float aside) {
  const glm::vec2 u = (kSubject - cam) / std::hypot(kSubject.x - cam.x, kSubject.y - cam.y);
  return cam + u * ahead + glm::vec2(-u.y, u.x) * aside;
}

TEST(CloseupAim, TheCameraStandsWhereThePagesDoes) {
  const glm::vec2 cam = closeup_spot(kSubject, 0.0f);
  EXPECT_NEAR(cam.x, kSubject.x - 1.2f, 1e-5f);
  EXPECT_NEAR(cam.y, kSubject.y + 4.6f, 1e-5f);
  for (float deg : kCloseupBearingsDeg) EXPECT_GT(closeup_spot(kSubject, deg).y, kSubject.y) << deg;
}

TEST(CloseupAim, APlayerOnTheLineOfSightOrBesideTheCameraIsInTheWay) {
  const glm::vec2 cam = closeup_spot(kSubject, 0.0f);
  EXPECT_TRUE(closeup_blocks(cam, kSubject, in_the_way(0)));
  EXPECT_FALSE(closeup_blocks(cam, kSubject, {kSubject.x, kSubject.y - 1.5f})) << "behind the subject";
  EXPECT_FALSE(closeup_blocks(cam, kSubject, {cam.x, cam.y + 1.0f})) << "behind the camera";
  EXPECT_FALSE(closeup_blocks(cam, kSubject, in_the_way(0) + glm::vec2(1.0f, 0.0f))) << "a metre to the side";
  EXPECT_FALSE(closeup_blocks(kSubject, kSubject, in_the_way(0))) << "no line of sight";
  EXPECT_FALSE(closeup_blocks(cam, kSubject, {NAN, 0.0f})) << "no position";
  // Beside the camera, in its picture, on either side.
  EXPECT_TRUE(closeup_blocks(cam, kSubject, from_camera(cam, 1.3f, 1.0f)));
  EXPECT_TRUE(closeup_blocks(cam, kSubject, from_camera(cam, 1.3f, -1.0f)));
  // Level with the camera, or behind it, or further off at the picture's edge.
  EXPECT_FALSE(closeup_blocks(cam, kSubject, from_camera(cam, 0.3f, 1.5f)));
  EXPECT_FALSE(closeup_blocks(cam, kSubject, from_camera(cam, -0.5f, 0.6f)));
  const float far = kNearCameraM + 0.5f;
  EXPECT_FALSE(closeup_blocks(cam, kSubject, from_camera(cam, far * std::cos(0.4f), far * std::sin(0.4f))));
}

TEST(CloseupAim, AClearBearingIsKeptAndABlockedOneGivesWayToTheNearestClearOne) {
  EXPECT_EQ(clear_bearing(kSubject, {}), 0);
  const std::vector<glm::vec2> one = {in_the_way(0)};
  const int chosen = clear_bearing(kSubject, one, 0);
  ASSERT_NE(chosen, 0);
  EXPECT_EQ(std::fabs(kCloseupBearingsDeg[static_cast<std::size_t>(chosen)]), 35.0f);
  EXPECT_EQ(clear_bearing(kSubject, {}, 2), 2) << "not back to straight-on while clear";
  const std::vector<glm::vec2> three = {in_the_way(0), in_the_way(1), in_the_way(2)};
  EXPECT_EQ(std::fabs(kCloseupBearingsDeg[static_cast<std::size_t>(clear_bearing(kSubject, three, 0))]), 70.0f);
  std::vector<glm::vec2> all;
  for (int i = 0; i < static_cast<int>(kCloseupBearingsDeg.size()); ++i) all.push_back(in_the_way(i));
  EXPECT_EQ(clear_bearing(kSubject, all, 1), 1) << "everyone in the way: no cut helps";
  EXPECT_EQ(clear_bearing(kSubject, {}, 99), 0);
  EXPECT_EQ(clear_bearing(kSubject, {}, -1), 0);
  // Someone beside the camera: a bearing from which he is out of the picture.
  const glm::vec2 beside = from_camera(closeup_spot(kSubject, 0.0f), 1.3f, 1.0f);
  const std::vector<glm::vec2> near = {beside};
  const int away = clear_bearing(kSubject, near, 0);
  ASSERT_NE(away, 0);
  EXPECT_FALSE(closeup_blocks(closeup_spot(kSubject, kCloseupBearingsDeg[static_cast<std::size_t>(away)]), kSubject,
                              beside));
}

TEST(CloseupAim, TheCutComesAfterTheWayStaysBlockedAndNeverWhilePaused) {
  const std::vector<glm::vec2> blocker = {in_the_way(0)};
  const glm::vec2 straight = closeup_spot(kSubject, 0.0f);
  CloseupAim aim;
  for (int i = 0; i < 100; ++i) EXPECT_EQ(aim.update(0.05, 500.0, kSubject, blocker), straight) << "paused";
  aim.update(0.05, 501.0, kSubject, blocker);
  EXPECT_EQ(aim.update(0.05, 502.0, kSubject, {}), straight) << "a moment in the way is let pass";
  double at = 502.0;
  glm::vec2 spot = straight;
  for (double t = 0; t <= kCloseupPatienceS + 0.1; t += 0.05) spot = aim.update(0.05, ++at, kSubject, blocker);
  EXPECT_NE(spot, straight);
  EXPECT_FALSE(closeup_blocks(spot, kSubject, blocker[0]));
  CloseupAim plain;  // no stream position: time alone counts
  for (double t = 0; t <= kCloseupPatienceS + 0.1; t += 0.05) spot = plain.update(0.05, NAN, kSubject, blocker);
  EXPECT_NE(spot, straight);
}

TEST(CloseupAim, TheViewersCloseUpCutsAwayFromAPlayerBesideItsCamera) {
  Camera cam;
  cam.set_mode(CameraMode::Closeup);
  proto::FieldGeometry field;
  CameraTarget t;
  t.has_player = true;
  t.player_root = to_scene(kSubject.x, kSubject.y, 0.0f);
  t.others = {from_camera(closeup_spot(kSubject, 0.0f), 1.3f, 1.0f)};
  t.at = 0;
  cam.update(0.0, t, 16.0f / 9.0f, field);
  EXPECT_NEAR(cam.eye().x, kSubject.x - 1.2f, 1e-4f) << "straight-on at first";
  for (int i = 1; i <= 10; ++i) {
    t.at = i;
    cam.update(0.05, t, 16.0f / 9.0f, field);
  }
  EXPECT_GT(std::hypot(cam.eye().x - (kSubject.x - 1.2f), cam.eye().z - (kSubject.y + 4.6f)), 1.0f) << "cut away";
  EXPECT_FALSE(closeup_blocks({cam.eye().x, cam.eye().z}, kSubject, t.others[0]));
}

}  // namespace
}  // namespace mc::viewer
