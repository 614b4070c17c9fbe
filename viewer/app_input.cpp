// The viewer's keys and mouse (viewer/README.md lists them): cameras, the
// chosen player, playback, orbit drag and zoom. The same keys as the page.
#include "viewer/app.hpp"

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "viewer/log_source.hpp"

#include "viewer/gl_util.hpp"  // before GLFW: the GL prototypes
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace mc::viewer {

void App::cycle_player(int step) {
  const PoseFrame& f = *frame_;
  int slot = selected_ < 0 ? (step > 0 ? -1 : kMaxPlayers) : selected_;
  for (int n = 0; n < kMaxPlayers; ++n) {
    slot = (slot + step + kMaxPlayers) % kMaxPlayers;
    if (player_visible(f.players[slot])) {
      selected_ = slot;
      if (camera_.mode() != CameraMode::Player && camera_.mode() != CameraMode::Follow &&
          camera_.mode() != CameraMode::Closeup)
        camera_.set_mode(CameraMode::Follow);
      return;
    }
  }
}

void App::on_key(int key, int mods) {
  const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
  switch (key) {
    case GLFW_KEY_0: camera_.set_mode(CameraMode::Director); break;  // back to the director's cut
    case GLFW_KEY_1: camera_.set_mode(CameraMode::Broadcast); break;
    case GLFW_KEY_2: camera_.set_mode(CameraMode::Orbit); break;
    case GLFW_KEY_4: camera_.set_mode(CameraMode::Player); break;
    case GLFW_KEY_5: camera_.set_mode(CameraMode::Follow); break;
    case GLFW_KEY_7: camera_.set_mode(CameraMode::Top); break;
    case GLFW_KEY_8: camera_.set_mode(CameraMode::Closeup); break;
    case GLFW_KEY_C: {
      const CameraMode order[] = {CameraMode::Broadcast, CameraMode::Orbit, CameraMode::Player,
                                  CameraMode::Follow, CameraMode::Top, CameraMode::Closeup};
      constexpr int n = static_cast<int>(std::size(order));
      int i = 0;
      while (i < n && order[i] != camera_.mode()) ++i;
      if (i == n)  // from the director's camera: the first (or, backwards, the last)
        camera_.set_mode(order[shift ? n - 1 : 0]);
      else
        camera_.set_mode(order[(i + (shift ? n - 1 : 1)) % n]);
      break;
    }
    case GLFW_KEY_TAB: cycle_player(shift ? -1 : 1); break;
    case GLFW_KEY_RIGHT_BRACKET: cycle_player(1); break;
    case GLFW_KEY_LEFT_BRACKET: cycle_player(-1); break;
    case GLFW_KEY_ESCAPE: selected_ = -1; break;
    case GLFW_KEY_N: labels_ = !labels_; break;
    case GLFW_KEY_SPACE:
    case GLFW_KEY_P: source_->toggle_pause(); break;
    case GLFW_KEY_LEFT: source_->seek_by(shift ? -60 : -10); break;
    case GLFW_KEY_RIGHT: source_->seek_by(shift ? 60 : 10); break;
    case GLFW_KEY_UP: source_->set_speed(std::min(8.0, source_->speed() * 2)); break;
    case GLFW_KEY_DOWN: source_->set_speed(std::max(0.25, source_->speed() / 2)); break;
    case GLFW_KEY_Q: glfwSetWindowShouldClose(window_, GLFW_TRUE); break;
    default: break;
  }
}

void App::on_mouse_button(int button, int action) {
  if (button == GLFW_MOUSE_BUTTON_LEFT) {
    dragging_ = action == GLFW_PRESS;
    glfwGetCursorPos(window_, &drag_x_, &drag_y_);
  }
}

void App::on_cursor(double x, double y) {
  if (!dragging_) return;
  if (camera_.mode() != CameraMode::Orbit) camera_.set_mode(CameraMode::Orbit);
  camera_.orbit_drag(static_cast<float>(x - drag_x_), static_cast<float>(y - drag_y_));
  drag_x_ = x;
  drag_y_ = y;
}

void App::on_drop(const std::string& path) {
  std::fprintf(stderr, "matchcast-viewer: opening %s (dropped onto the window)\n", path.c_str());
  if (source_) source_->stop();
  RecordingOptions ro;
  ro.speed = options_.speed;
  ro.loop = options_.loop;
  buffer_.set_status("opening " + path);
  source_ = make_file_source(path, buffer_, ro);
  source_->start();
  playhead_ = kPlayheadUnset;
  const auto slash = path.find_last_of('/');
  glfwSetWindowTitle(window_, ("Matchcast: " + path.substr(slash == std::string::npos ? 0 : slash + 1)).c_str());
}

void App::on_scroll(double dy) {
  if (camera_.mode() != CameraMode::Orbit) camera_.set_mode(CameraMode::Orbit);
  camera_.orbit_zoom(static_cast<float>(dy));
}

}  // namespace mc::viewer
