// The 2D overlay: a scoreboard (team names in their colours, score, clock,
// play mode), the numbers above the players, the camera and playback state,
// and the status line that says what is wrong (refused connection, feed
// lost, damaged recording). Pixel coordinates, origin top-left; text is the
// built-in bitmap font (font.hpp) drawn as quads.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "viewer/gl_util.hpp"

namespace mc::viewer {

struct PlayerLabel {
  glm::vec2 px;             // above the head, in pixels
  int number = 0;
  glm::vec3 shirt, text;    // label background and digits
};

struct HudInfo {
  std::string left_name, right_name;
  glm::vec3 left_color{1.0f}, right_color{1.0f};
  int score_left = 0, score_right = 0, pen_left = 0, pen_right = 0;
  int time = 0;                       // simulation cycle
  std::string play_mode;              // rcssserver's name ("play_on")
  std::string camera;                 // "broadcast [1]"
  std::string chosen;                 // "L10" or ""
  std::string playback;               // "PAUSED", "x2", "LIVE"
  std::string status;                 // "" or the problem, shown in yellow
  bool waiting = false;               // no picture yet: the status goes in the middle
  std::vector<PlayerLabel> labels;
};

// "MM:SS" from a simulation cycle (100 ms cycles).
std::string clock_text(int time);
// "play_on" -> "PLAY ON".
std::string play_mode_text(std::string_view name);

class Hud {
 public:
  ~Hud();
  bool init(std::string& error);
  void draw(const HudInfo& info, int width, int height);

 private:
  void rect(float x, float y, float w, float h, glm::vec4 color);
  void text(float x, float y, std::string_view s, float scale, glm::vec4 color);
  void flush(int width, int height);
  void scoreboard(const HudInfo& info, float scale, float line);

  GLuint program_ = 0;
  GLint u_size_ = -1;
  gl::Mesh mesh_;
  std::vector<float> quads_;
};

}  // namespace mc::viewer
