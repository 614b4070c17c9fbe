// The viewer's command line:
//   matchcast-viewer SOURCE [options]
// SOURCE is a relay (ws://HOST:PORT/ws, ?channel=NAME or ?recording=NAME,
// or the page's http:// address), a recording file (.mcrec) or a game log
// (.rcg, .rcg.gz, any version: the pipeline runs in-process).
#pragma once

#include <optional>
#include <string>

#include "proto/world_state.hpp"
#include "viewer/camera.hpp"

namespace mc::viewer {

struct ViewerOptions {
  std::string source;               // URL or file
  bool is_file = false;             // SOURCE is a file: a recording or a game log
  int width = 1280, height = 720;   // window or screenshot size (px)
  CameraMode camera = CameraMode::Director;
  std::string follow;               // "l10", "r1": the chosen player ("" = nearest the ball)
  double speed = 1.0;               // recordings: playback speed
  bool loop = false;                // recordings: start again at the end
  bool fullscreen = false;
  bool vsync = true;
  int samples = -1;                 // window: multisample anti-aliasing; -1 = 4, or off on a software renderer
  // --screenshot FILE --at SIMTIME: render the frame at that simulation
  // cycle offscreen, write a PNG, exit (0 ok, 2 no frame in time).
  std::string screenshot;
  int at = -1;
  double timeout_s = 60;            // screenshot: longest wait for the frame
  std::string report;               // screenshot: JSON sidecar (frame seq/time, camera)
  bool labels = true;
  // Window mode: close after this many seconds and print what was drawn
  // (frames, rate, skips, lag behind the newest frame); 0 = run until closed.
  double quit_after_s = 0;
  // Testing: sleep this long after every drawn frame, as a very slow GPU would.
  int simulate_slow_ms = 0;
};

// Parses argv. nullopt with `message` for --help (exit 0) or an error (exit 1);
// `exit_code` says which.
std::optional<ViewerOptions> parse_options(int argc, char** argv, std::string& message, int& exit_code);

// "l10" / "r1" / "L10" -> side and unum; false otherwise.
bool parse_player(const std::string& text, Side& side, int& unum);

}  // namespace mc::viewer
