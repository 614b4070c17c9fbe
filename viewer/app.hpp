// The viewer application: a GLFW window (or a hidden one for --screenshot),
// the source thread, and the render loop that samples the frame buffer at
// the display's rate, interpolates, moves the camera and draws the scene and
// the HUD. Keys and mouse steer cameras, player choice and playback.
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "viewer/camera.hpp"
#include "viewer/director_view.hpp"
#include "viewer/frame_buffer.hpp"
#include "viewer/fatigue_pose.hpp"
#include "viewer/head_smoother.hpp"
#include "viewer/options.hpp"
#include "viewer/player_model.hpp"
#include "viewer/source.hpp"

struct GLFWwindow;

namespace mc::viewer {

class Renderer;
class Hud;

class App {
 public:
  explicit App(ViewerOptions options);
  ~App();
  // The process exit code: 0 ok, 1 bad arguments or no OpenGL, 2 no frame
  // in time for --screenshot (the PNG then shows the reason).
  int run();

  // GLFW callbacks.
  void on_key(int key, int mods);
  void on_mouse_button(int button, int action);
  void on_cursor(double x, double y);
  void on_scroll(double dy);
  // A file dropped onto the window (a game log or a recording) is opened
  // in place of what is shown.
  void on_drop(const std::string& path);

 private:
  bool open_window(bool visible, std::string& error);
  bool make_source(bool screenshot, std::string& error);
  int run_window();
  int run_screenshot();
  void check_hello();
  // `at`: the stream position drawn (NaN: none; the close-up's cut counts
  // only while it moves).
  void draw(const PoseFrame& frame, int width, int height, double dt, double at = NAN);
  // No picture yet: the sky and the reason in the middle.
  void draw_waiting(const std::string& status, int width, int height);
  CameraTarget camera_target(const PoseFrame& frame);
  int nearest_to_ball(const PoseFrame& frame) const;
  void cycle_player(int step);
  bool write_report(const PoseFrame& frame, std::string& error) const;

  ViewerOptions options_;
  FrameBuffer buffer_;
  std::unique_ptr<Source> source_;
  GLFWwindow* window_ = nullptr;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<Hud> hud_;
  Camera camera_;
  StreamMeta meta_;
  std::unique_ptr<PlayerModel> model_;
  std::unique_ptr<anim::LegBlend> feet_;  // feet kept put between frames (SPEC 4.7 step 2)
  std::unique_ptr<HeadSmoother> heads_;  // heads at human speed where drawn
  std::unique_ptr<FatiguePose> fatigue_;  // tired players lean, hands on knees at stoppages
  // The director (issue 20): its cues, the frames drawn (to replay a goal), the shot.
  DirectorView director_;
  FrameHistory history_;
  std::vector<proto::DirectorCue> cues_;
  std::uint64_t cues_seen_ = ~0ull;
  bool director_cut_ = true;
  void follow_director(double live_seq, double dt, double rate);
  std::uint64_t hello_generation_ = 0;
  int selected_ = -1;       // player slot (player_index), -1 = none chosen
  bool labels_ = true;
  double playhead_ = kPlayheadUnset;
  std::unique_ptr<Sample> sample_;
  std::unique_ptr<PoseFrame> frame_;
  bool dragging_ = false;
  double drag_x_ = 0, drag_y_ = 0;
};

}  // namespace mc::viewer
