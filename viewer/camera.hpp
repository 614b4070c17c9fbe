// The camera modes of the web page (web/src/cameras.js), in the same scene
// space, so that both clients frame a game the same way:
//   scene = (field x, height, field y): X along the pitch, Y up, Z towards
//   the main stand (the field's +y side, the bottom touchline).
// Each mode computes where the camera wants to be from the current
// (interpolated) frame; the camera eases towards it so that cuts inside a
// mode are smooth. snap() makes the next update jump there (a mode change,
// a screenshot). Orbit is steered by the user (drag, scroll).
// No OpenGL here: tests project points with the same maths as the renderer.
#pragma once

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "proto/hello.hpp"
#include "viewer/closeup_aim.hpp"

namespace mc::viewer {

enum class CameraMode { Broadcast, Orbit, Player, Follow, Top, Director, Closeup };

// Mode names as on the command line and in the web page ("broadcast",
// "orbit", "player", "follow", "top", "director": the server's director
// track, director_view.hpp; "closeup": beside the chosen player); false for
// another name.
bool camera_mode_from_name(std::string_view name, CameraMode& out);
std::string_view camera_mode_name(CameraMode mode);
// The web page's keys: 0 director, 1 broadcast, 2 orbit, 4 player, 5 follow, 7 top, 8 close-up.
char camera_mode_key(CameraMode mode);

// What the modes look at, in scene space.
struct CameraTarget {
  glm::vec3 ball{0.0f};
  bool has_player = false;       // a player is chosen (player, follow and close-up modes)
  glm::vec3 player_root{0.0f};   // his root on the grass
  float player_heading = 0;      // field degrees
  glm::vec3 head{0.0f};          // his head joint and its forward (+X) axis
  glm::vec3 head_forward{1.0f, 0.0f, 0.0f};
  // The other players on the pitch (field x, y), whom the close-up keeps
  // out of its picture (closeup_aim.hpp), and the stream position drawn
  // (NaN: none known; while it stays the same, the game is paused).
  std::vector<glm::vec2> others;
  double at = NAN;
  // The director's shot (director mode): where to stand and look; `shot_cut`
  // jumps there instead of moving.
  bool has_shot = false, shot_cut = false;
  glm::vec3 shot_eye{0.0f}, shot_look{0.0f};
  float shot_fov = 40.0f;
};

class Camera {
 public:
  static constexpr float kNear = 0.1f, kFar = 800.0f;
  static constexpr float kFieldMargin = 5.0f;  // grass beyond the lines (m), as the page

  void set_mode(CameraMode mode);
  CameraMode mode() const { return mode_; }
  void snap() { snap_ = true; }

  // Orbit controls: drag in pixels, zoom in wheel steps (positive = closer).
  void orbit_drag(float dx_px, float dy_px);
  void orbit_zoom(float steps);

  // Moves towards the mode's goal; `dt` in seconds of wall time.
  void update(double dt, const CameraTarget& target, float aspect, const proto::FieldGeometry& field);

  glm::vec3 eye() const { return eye_; }
  glm::vec3 look() const { return look_; }
  float fov_deg() const { return fov_; }
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  // Pixel (origin top-left, y down) of a scene point in a width x height
  // image; false when the point is behind the camera.
  bool project(const glm::vec3& scene, int width, int height, glm::vec2& px) const;

 private:
  CameraMode mode_ = CameraMode::Broadcast;
  bool snap_ = true;
  glm::vec3 eye_{0.0f, 45.0f, 79.0f}, look_{0.0f}, up_{0.0f, 1.0f, 0.0f};
  float fov_ = 40.0f;
  // Orbit: spherical coordinates about its target.
  glm::vec3 orbit_target_{0.0f};
  float orbit_yaw_ = 0, orbit_pitch_ = 0, orbit_distance_ = 0;
  CloseupAim closeup_aim_;  // the close-up's bearing, clear of other players
};

// Field (x, y, height) -> scene.
inline glm::vec3 to_scene(float x, float y, float z) { return {x, z, y}; }

}  // namespace mc::viewer
