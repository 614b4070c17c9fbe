// Camera maths: what each mode frames, projection to pixels.
#include "viewer/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mc::viewer {
namespace {

const proto::FieldGeometry kField;

TEST(Camera, ModeNamesAndKeysMatchThePage) {
  for (const char* name : {"broadcast", "orbit", "player", "follow", "top", "closeup", "director"}) {
    CameraMode m;
    ASSERT_TRUE(camera_mode_from_name(name, m)) << name;
    EXPECT_EQ(camera_mode_name(m), name);
  }
  CameraMode m;
  EXPECT_FALSE(camera_mode_from_name("free", m));
  EXPECT_EQ(camera_mode_key(CameraMode::Broadcast), '1');
  EXPECT_EQ(camera_mode_key(CameraMode::Top), '7');
  EXPECT_EQ(camera_mode_key(CameraMode::Closeup), '8');
}

TEST(Camera, TopDownShowsTheWholePitchWithTheTopTouchlineUp) {
  Camera cam;
  cam.set_mode(CameraMode::Top);
  cam.update(0.0, {}, 16.0f / 9.0f, kField);
  glm::vec2 c, tl, br;
  ASSERT_TRUE(cam.project({0, 0, 0}, 1280, 720, c));
  EXPECT_NEAR(c.x, 640, 1);
  EXPECT_NEAR(c.y, 360, 1);
  // Field (-52.5, -34) is the top-left corner: scene (x, 0, field y).
  ASSERT_TRUE(cam.project(to_scene(-52.5f, -34.0f, 0), 1280, 720, tl));
  ASSERT_TRUE(cam.project(to_scene(52.5f, 34.0f, 0), 1280, 720, br));
  EXPECT_GT(tl.x, 0);
  EXPECT_GT(tl.y, 0);
  EXPECT_LT(br.x, 1280);
  EXPECT_LT(br.y, 720);
  EXPECT_LT(tl.x, c.x);
  EXPECT_LT(tl.y, c.y);  // -y (top touchline) is up on the screen
  // Symmetric about the centre.
  EXPECT_NEAR(tl.x + br.x, 1280, 2);
  EXPECT_NEAR(tl.y + br.y, 720, 2);
}

TEST(Camera, BroadcastLooksAtTheBallFromTheMainStand) {
  Camera cam;
  CameraTarget t;
  t.ball = to_scene(20.0f, 5.0f, 0.0f);
  cam.update(0.0, t, 16.0f / 9.0f, kField);
  EXPECT_GT(cam.eye().z, 34.0f);  // beyond the +y touchline
  EXPECT_GT(cam.eye().y, 10.0f);
  glm::vec2 px;
  ASSERT_TRUE(cam.project(t.ball, 1280, 720, px));
  EXPECT_NEAR(px.x, 640, 40);
  EXPECT_NEAR(px.y, 360, 80);
  // +x is to the right on screen.
  glm::vec2 right;
  ASSERT_TRUE(cam.project(to_scene(25.0f, 5.0f, 0.0f), 1280, 720, right));
  EXPECT_GT(right.x, px.x);
}

TEST(Camera, EasesTowardsItsGoalUnlessSnapped) {
  Camera cam;
  CameraTarget t;
  cam.update(0.0, t, 1.5f, kField);
  const glm::vec3 before = cam.eye();
  t.ball = to_scene(40.0f, 0.0f, 0.0f);
  cam.update(0.1, t, 1.5f, kField);
  const float moved = cam.eye().x - before.x;
  EXPECT_GT(moved, 0.0f);
  EXPECT_LT(moved, 40.0f * 0.8f * 0.5f);  // part of the way
  cam.snap();
  cam.update(0.1, t, 1.5f, kField);
  EXPECT_NEAR(cam.eye().x, 32.0f, 1e-3);  // all the way (0.8 * ball x)
}

TEST(Camera, FollowSitsBehindThePlayerAndSeesHim) {
  Camera cam;
  cam.set_mode(CameraMode::Follow);
  CameraTarget t;
  t.has_player = true;
  t.player_root = to_scene(10.0f, -5.0f, 0.0f);
  t.player_heading = 90.0f;  // facing field +y = scene +Z
  cam.update(0.0, t, 1.5f, kField);
  EXPECT_NEAR(cam.eye().x, 10.0f, 1e-3);
  EXPECT_NEAR(cam.eye().z, -12.0f, 1e-3);  // 7 m behind
  glm::vec2 px;
  ASSERT_TRUE(cam.project(t.player_root + glm::vec3(0, 1, 0), 960, 640, px));
  EXPECT_NEAR(px.x, 480, 1);
  EXPECT_GT(px.y, 0);
  EXPECT_LT(px.y, 640);
  // A point behind the camera does not project.
  EXPECT_FALSE(cam.project(to_scene(10.0f, -30.0f, 1.0f), 960, 640, px));
}

TEST(Camera, CloseUpStandsBesideThePlayerAndHisWholeBodyFillsThePicture) {
  Camera cam;
  cam.set_mode(CameraMode::Closeup);
  CameraTarget t;
  t.has_player = true;
  t.player_root = to_scene(-20.0f, 8.0f, 0.0f);
  t.player_heading = 37.0f;  // not followed: the close-up does not swing with his heading
  cam.update(0.0, t, 16.0f / 9.0f, kField);
  // The page's framing (web/src/cameras.js 'closeup'), at once.
  EXPECT_NEAR(cam.eye().x, -21.2f, 1e-3);
  EXPECT_NEAR(cam.eye().y, 1.35f, 1e-3);
  EXPECT_NEAR(cam.eye().z, 12.6f, 1e-3);
  glm::vec2 head, feet;
  ASSERT_TRUE(cam.project(t.player_root + glm::vec3(0, 1.8f, 0), 960, 540, head));
  ASSERT_TRUE(cam.project(t.player_root, 960, 540, feet));
  // Head and feet on the screen, and the body over half its height: a close-up.
  EXPECT_GT(head.y, 0);
  EXPECT_LT(feet.y, 540);
  EXPECT_GT(feet.y - head.y, 270);
  EXPECT_NEAR(feet.x, 480, 40);
  // Held on him as he runs: the next frame is framed the same, no easing lag.
  t.player_root += glm::vec3(0.4f, 0, 0);
  cam.update(0.05, t, 16.0f / 9.0f, kField);
  EXPECT_NEAR(cam.eye().x, -20.8f, 1e-3);
  // No player chosen: the overview, not a close-up of the grass.
  t.has_player = false;
  cam.update(0.0, t, 16.0f / 9.0f, kField);
  EXPECT_GT(cam.eye().y, 20.0f);
}

TEST(Camera, PlayerViewLooksFromTheHeadAlongItsForwardAxis) {
  Camera cam;
  cam.set_mode(CameraMode::Player);
  CameraTarget t;
  t.has_player = true;
  t.head = {0.0f, 1.7f, 0.0f};
  t.head_forward = {1.0f, 0.0f, 0.0f};
  cam.update(0.0, t, 1.5f, kField);
  EXPECT_NEAR(cam.eye().x, 0.12f, 1e-4);
  EXPECT_NEAR(cam.eye().y, 1.7f, 1e-4);
  EXPECT_NEAR(cam.fov_deg(), 70.0f, 1e-4);
  glm::vec2 px;
  ASSERT_TRUE(cam.project({20.0f, 1.7f, 0.0f}, 900, 600, px));
  EXPECT_NEAR(px.x, 450, 1);
  EXPECT_NEAR(px.y, 300, 1);
  // Without a player it falls back to an overview instead of failing.
  cam.update(0.0, {}, 1.5f, kField);
  EXPECT_GT(cam.eye().y, 20.0f);
}

TEST(Camera, OrbitTurnsAndZoomsAboutItsTarget) {
  Camera cam;
  cam.set_mode(CameraMode::Orbit);
  cam.update(0.0, {}, 1.5f, kField);
  const float d0 = glm::length(cam.eye());
  cam.orbit_zoom(3.0f);
  cam.update(0.016, {}, 1.5f, kField);
  EXPECT_LT(glm::length(cam.eye()), d0);
  const glm::vec3 before = cam.eye();
  cam.orbit_drag(200.0f, 0.0f);
  cam.update(0.016, {}, 1.5f, kField);
  EXPECT_NEAR(glm::length(cam.eye()), glm::length(before), 1e-2);
  EXPECT_GT(glm::length(cam.eye() - before), 1.0f);
}

}  // namespace
}  // namespace mc::viewer
