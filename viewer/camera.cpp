#include "viewer/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace mc::viewer {
namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;

struct ModeName {
  CameraMode mode;
  const char* name;
  char key;
};
constexpr ModeName kModes[] = {{CameraMode::Broadcast, "broadcast", '1'},
                               {CameraMode::Orbit, "orbit", '2'},
                               {CameraMode::Player, "player", '4'},
                               {CameraMode::Follow, "follow", '5'},
                               {CameraMode::Top, "top", '7'},
                               {CameraMode::Closeup, "closeup", '8'},
                               {CameraMode::Director, "director", '0'}};

}  // namespace

bool camera_mode_from_name(std::string_view name, CameraMode& out) {
  for (const auto& m : kModes)
    if (name == m.name) {
      out = m.mode;
      return true;
    }
  return false;
}

std::string_view camera_mode_name(CameraMode mode) {
  for (const auto& m : kModes)
    if (m.mode == mode) return m.name;
  return "?";
}

char camera_mode_key(CameraMode mode) {
  for (const auto& m : kModes)
    if (m.mode == mode) return m.key;
  return '?';
}

void Camera::set_mode(CameraMode mode) {
  if (mode == mode_) return;
  mode_ = mode;
  snap_ = true;
  if (mode == CameraMode::Orbit) {
    // Start wide, the whole pitch in view from the main stand (as the page).
    orbit_target_ = glm::vec3(0.0f);
    orbit_yaw_ = 0.0f;
    orbit_distance_ = std::hypot(60.0f, 34.0f + 55.0f);
    orbit_pitch_ = std::atan2(60.0f, 34.0f + 55.0f);
  }
}

void Camera::orbit_drag(float dx_px, float dy_px) {
  orbit_yaw_ -= dx_px * 0.005f;
  orbit_pitch_ = std::clamp(orbit_pitch_ + dy_px * 0.005f, 2.0f * kDeg, 88.0f * kDeg);
}

void Camera::orbit_zoom(float steps) {
  orbit_distance_ = std::clamp(orbit_distance_ * std::pow(0.9f, steps), 3.0f, 250.0f);
}

void Camera::update(double dt, const CameraTarget& target, float aspect,
                    const proto::FieldGeometry& field) {
  const float L = static_cast<float>(field.length), W = static_cast<float>(field.width);
  glm::vec3 goal = eye_, look_goal = look_;
  float fov_goal = fov_;
  glm::vec3 up(0.0f, 1.0f, 0.0f);
  const auto overview = [&] {
    goal = {0.0f, 45.0f, W / 2 + 45.0f};
    look_goal = glm::vec3(0.0f);
    fov_goal = aspect < 1 ? 60.0f : 40.0f;
  };
  switch (mode_) {
    case CameraMode::Broadcast: {
      // From the main stand on the +y side, level with the ball, zoomed.
      const float bx = std::clamp(target.ball.x, -L / 2, L / 2);
      const float bz = std::clamp(target.ball.z, -W / 2, W / 2);
      goal = aspect < 1 ? glm::vec3(bx * 0.9f, 30.0f, W / 2 + 22.0f)
                        : glm::vec3(bx * 0.8f, 22.0f, W / 2 + 40.0f);
      look_goal = {bx, 0.0f, bz * 0.7f};
      fov_goal = aspect < 1 ? 50.0f : 24.0f;
      break;
    }
    case CameraMode::Orbit: {
      if (orbit_distance_ <= 0) {
        mode_ = CameraMode::Broadcast;  // set_mode() initialises the orbit
        set_mode(CameraMode::Orbit);
      }
      const float c = std::cos(orbit_pitch_);
      goal = orbit_target_ + orbit_distance_ * glm::vec3(std::sin(orbit_yaw_) * c, std::sin(orbit_pitch_),
                                                         std::cos(orbit_yaw_) * c);
      look_goal = orbit_target_;
      fov_goal = 40.0f;
      snap_ = true;  // the user moves it directly
      break;
    }
    case CameraMode::Player: {
      if (!target.has_player) {
        overview();
        break;
      }
      // From the head, looking along the head's forward axis; no lag.
      goal = target.head + target.head_forward * 0.12f;
      look_goal = target.head + target.head_forward * 10.0f;
      look_goal.y = std::min(look_goal.y, target.head.y);
      fov_goal = 70.0f;
      eye_ = goal;
      break;
    }
    case CameraMode::Follow: {
      if (!target.has_player) {
        overview();
        break;
      }
      const float h = -target.player_heading * kDeg;
      const glm::vec3 dir(std::cos(h), 0.0f, -std::sin(h));
      const glm::vec3 p(target.player_root.x, 0.0f, target.player_root.z);
      goal = p - dir * 7.0f;
      goal.y = 3.5f;
      look_goal = p + dir * 5.0f;
      look_goal.y = 0.8f;
      fov_goal = 50.0f;
      break;
    }
    case CameraMode::Closeup: {
      if (!target.has_player) {
        overview();
        break;
      }
      // The page's close-up (web/src/cameras.js): beside the chosen player,
      // from the main stand's side at chest height, so that his whole body
      // and his kicks fill the picture. Not hung on his heading, which
      // turns too often; held on him (his interpolated pose is smooth).
      // Someone in the way for a moment is let pass; for longer, a cut to a
      // bearing from which no one is (closeup_aim.hpp).
      const glm::vec3 p = target.player_root;
      const glm::vec2 at = closeup_aim_.update(dt, target.at, {p.x, p.z}, target.others);
      goal = {at.x, 1.35f, at.y};
      look_goal = {p.x, 0.8f, p.z};
      fov_goal = aspect < 1 ? 55.0f : 38.0f;
      snap_ = true;
      break;
    }
    case CameraMode::Director: {
      if (!target.has_shot) {
        overview();
        break;
      }
      goal = target.shot_eye;
      look_goal = target.shot_look;
      fov_goal = target.shot_fov;
      if (target.shot_cut) snap_ = true;
      break;
    }
    case CameraMode::Top: {
      // The monitor's view: the top touchline (-Z) up on the screen.
      const float vfov = 40.0f;
      const float need = std::max(W + 2 * kFieldMargin, (L + 2 * kFieldMargin) / std::max(aspect, 0.1f));
      const float height = need / 2 / std::tan(vfov / 2 * kDeg);
      goal = {0.0f, height, 0.001f};
      look_goal = glm::vec3(0.0f);
      fov_goal = vfov;
      up = {0.0f, 0.0f, -1.0f};
      break;
    }
  }
  if (snap_ || dt <= 0) {
    eye_ = goal;
    look_ = look_goal;
    fov_ = fov_goal;
  } else {
    const float k = 1.0f - static_cast<float>(std::exp(-dt * 3.0));
    const float kl = 1.0f - static_cast<float>(std::exp(-dt * (mode_ == CameraMode::Player ? 10.0 : 5.0)));
    eye_ += (goal - eye_) * k;
    look_ += (look_goal - look_) * kl;
    fov_ += (fov_goal - fov_) * k;
  }
  up_ = up;
  snap_ = false;
}

glm::mat4 Camera::view() const { return glm::lookAt(eye_, look_, up_); }

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(fov_ * kDeg, aspect, kNear, kFar);
}

bool Camera::project(const glm::vec3& scene, int width, int height, glm::vec2& px) const {
  const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
  const glm::vec4 clip = projection(aspect) * view() * glm::vec4(scene, 1.0f);
  if (clip.w <= 1e-6f) return false;
  const float nx = clip.x / clip.w, ny = clip.y / clip.w;
  px = {(nx * 0.5f + 0.5f) * static_cast<float>(width), (0.5f - ny * 0.5f) * static_cast<float>(height)};
  return true;
}

}  // namespace mc::viewer
