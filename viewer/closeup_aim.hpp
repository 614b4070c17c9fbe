// The close-up camera keeps its subject in sight, as the page's does
// (web/src/model/sightline.js, the same rules and figures): it stands
// beside him on the main stand's side; a player between the two, or just
// beside the camera in its picture, fills the frame with his back or an
// arm. The camera then cuts to the nearest of a few bearings about the
// subject from which no one is in the way, as a broadcast cuts to another
// camera. Pure functions of field positions (x, y in metres): no OpenGL.
#pragma once

#include <array>
#include <cmath>
#include <span>

#include <glm/vec2.hpp>

namespace mc::viewer {

// Bearings (deg) tried about the subject, from the straight-on view first.
inline constexpr std::array<float, 5> kCloseupBearingsDeg = {0.0f, -35.0f, 35.0f, -70.0f, 70.0f};
// A body in the way: its centre this near the line of sight (m).
inline constexpr float kBodyRadiusM = 0.45f;
// A body this near the camera (m) and in its picture is in the way too,
// the picture being kPictureHalfDeg either side of the line of sight.
inline constexpr float kNearCameraM = 2.5f;
inline constexpr float kPictureHalfDeg = 33.0f;
// Someone in the way for less than this (s of game time) is let pass.
inline constexpr double kCloseupPatienceS = 0.3;

// The camera's field position for a subject at `subject` and a bearing.
glm::vec2 closeup_spot(glm::vec2 subject, float bearing_deg);

// Whether `other` is in the way of a camera at `cam` filming `subject`.
bool closeup_blocks(glm::vec2 cam, glm::vec2 subject, glm::vec2 other, float radius = kBodyRadiusM);

// The bearing index to film from: `current` while no one blocks it, else
// the clear one nearest to it (by angle), else `current`.
int clear_bearing(glm::vec2 subject, std::span<const glm::vec2> others, int current = 0);

// The close-up's bearing over time: a cut once the line of sight has been
// blocked for kCloseupPatienceS while the game moves. `at` is the stream
// position drawn: while it stays the same (paused) nothing counts; NaN
// (none known): time alone counts.
class CloseupAim {
 public:
  glm::vec2 update(double dt, double at, glm::vec2 subject, std::span<const glm::vec2> others);
  int bearing() const { return bearing_; }

 private:
  int bearing_ = 0;
  double blocked_ = 0;
  double at_ = NAN;
};

}  // namespace mc::viewer
