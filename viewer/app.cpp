#include "viewer/app.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

#include "viewer/gl_util.hpp"  // before GLFW: the GL prototypes
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include "anim/ground_contact.hpp"
#include "viewer/hud.hpp"
#include "viewer/interpolate.hpp"
#include "viewer/log_source.hpp"
#include "viewer/png.hpp"
#include "viewer/recording_source.hpp"
#include "viewer/renderer.hpp"
#include "viewer/ws_source.hpp"

namespace mc::viewer {
namespace {

App* app_of(GLFWwindow* w) { return static_cast<App*>(glfwGetWindowUserPointer(w)); }

std::string slot_name(int slot) {
  if (slot < 0) return "";
  return (slot < kPlayersPerSide ? "L" : "R") + std::to_string(slot % kPlayersPerSide + 1);
}

}  // namespace

App::App(ViewerOptions options)
    : options_(std::move(options)), sample_(std::make_unique<Sample>()), frame_(std::make_unique<PoseFrame>()) {
  labels_ = options_.labels;
  camera_.set_mode(options_.camera);
  Side side;
  int unum;
  if (parse_player(options_.follow, side, unum)) selected_ = player_index(side, unum);
}

App::~App() {
  if (source_) source_->stop();
  renderer_.reset();
  hud_.reset();
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

bool App::make_source(bool screenshot, std::string& error) {
  if (options_.is_file) {
    RecordingOptions ro;
    ro.speed = options_.speed;
    ro.loop = options_.loop;
    if (screenshot) {
      ro.start_time = options_.at;
      ro.start_paused = true;
    }
    source_ = make_file_source(options_.source, buffer_, ro);  // a recording or a game log
  } else {
    WsUrl url;
    if (!parse_ws_url(options_.source, url, error)) return false;
    source_ = std::make_unique<WsSource>(url, buffer_);
  }
  source_->start();
  return true;
}

bool App::open_window(bool visible, std::string& error) {
  glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
  if (!glfwInit()) {
    error = "cannot open a window (no display? DISPLAY is \"" +
            std::string(std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "") +
            "\"); headless, run it under xvfb-run -a";
    return false;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  GLFWmonitor* monitor = options_.fullscreen && visible ? glfwGetPrimaryMonitor() : nullptr;
  int w = options_.width, h = options_.height;
  if (monitor) {
    const GLFWvidmode* mode = glfwGetVideoMode(monitor);
    w = mode->width;
    h = mode->height;
  }
  const auto create = [&](int samples) {
    glfwWindowHint(GLFW_SAMPLES, samples);
    window_ = glfwCreateWindow(w, h, "Matchcast", monitor, nullptr);
    if (window_) glfwMakeContextCurrent(window_);
    return window_ != nullptr;
  };
  if (!create(visible ? (options_.samples < 0 ? 4 : std::clamp(options_.samples, 0, 16)) : 0)) {
    error = "cannot create an OpenGL 3.3 core window (is Mesa's libgl1-mesa-dri installed?)";
    return false;
  }
  // A software renderer (Mesa llvmpipe) draws 4x faster without
  // multisampling (89 against 21 fps at 1280x720, viewer/README.md): unless
  // --samples says otherwise, the window is made again without it.
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string gl_name = renderer ? renderer : "";
  if (visible && options_.samples < 0 &&
      (gl_name.find("llvmpipe") != std::string::npos || gl_name.find("softpipe") != std::string::npos)) {
    glfwDestroyWindow(window_);
    if (!create(0)) {
      error = "cannot create an OpenGL 3.3 core window";
      return false;
    }
  }
  glfwSwapInterval(options_.vsync ? 1 : 0);
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, [](GLFWwindow* win, int key, int, int action, int mods) {
    if (action != GLFW_RELEASE) app_of(win)->on_key(key, mods);
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* win, int button, int action, int) {
    app_of(win)->on_mouse_button(button, action);
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* win, double x, double y) { app_of(win)->on_cursor(x, y); });
  glfwSetScrollCallback(window_, [](GLFWwindow* win, double, double dy) { app_of(win)->on_scroll(dy); });
  glfwSetDropCallback(window_, [](GLFWwindow* win, int count, const char** paths) {
    if (count > 0) app_of(win)->on_drop(paths[0]);
  });
  renderer_ = std::make_unique<Renderer>();
  hud_ = std::make_unique<Hud>();
  return renderer_->init(error) && hud_->init(error);
}

int App::run() {
  std::string error;
  const bool screenshot = !options_.screenshot.empty();
  if (!make_source(screenshot, error) || !open_window(!screenshot, error)) {
    std::fprintf(stderr, "matchcast-viewer: %s\n", error.c_str());
    return 1;
  }
  return screenshot ? run_screenshot() : run_window();
}

void App::check_hello() {
  meta_ = buffer_.meta();
  if (!meta_.hello || meta_.hello_generation == hello_generation_) return;
  hello_generation_ = meta_.hello_generation;
  model_ = std::make_unique<PlayerModel>(meta_.hello->skeleton);
  heads_ = std::make_unique<HeadSmoother>(meta_.hello->skeleton);
  feet_ = std::make_unique<anim::LegBlend>(meta_.hello->skeleton);
  fatigue_ = std::make_unique<FatiguePose>(meta_.hello->skeleton);
  renderer_->set_field(meta_.hello->field);
}

int App::nearest_to_ball(const PoseFrame& f) const {
  int best = -1;
  float bd = 1e9f;
  for (int i = 0; i < kMaxPlayers; ++i) {
    if (!player_visible(f.players[i])) continue;
    const float d = std::hypot(f.players[i].x - f.ball.x, f.players[i].y - f.ball.y);
    if (d < bd) {
      bd = d;
      best = i;
    }
  }
  return best;
}

CameraTarget App::camera_target(const PoseFrame& f) {
  CameraTarget t;
  t.ball = to_scene(f.ball.x, f.ball.y, f.ball.z);
  const bool needs_player = camera_.mode() == CameraMode::Player || camera_.mode() == CameraMode::Follow ||
                            camera_.mode() == CameraMode::Closeup;
  if (needs_player && (selected_ < 0 || !player_visible(f.players[selected_]))) selected_ = nearest_to_ball(f);
  if (selected_ >= 0 && player_visible(f.players[selected_]) && model_) {
    const PlayerPose& p = f.players[selected_];
    std::vector<glm::mat4> joints;
    if (model_->joints(p, joints)) {
      t.has_player = true;
      t.player_root = to_scene(p.x, p.y, 0.0f);
      t.player_heading = p.heading;
      const glm::mat4& head = joints[static_cast<std::size_t>(model_->head_joint())];
      t.head = glm::vec3(head[3]);
      t.head_forward = glm::normalize(glm::vec3(head[0]));
      for (std::size_t i = 0; i < f.players.size(); ++i)
        if (static_cast<int>(i) != selected_ && player_visible(f.players[i]))
          t.others.emplace_back(f.players[i].x, f.players[i].y);
    }
  }
  return t;
}

void App::draw(const PoseFrame& f, int width, int height, double dt, double at) {
  const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
  CameraTarget target = camera_target(f);
  target.at = at;
  if (const proto::DirectorCue* cue = director_.current(); cue && camera_.mode() == CameraMode::Director) {
    const ShotRig r = shot_rig(*cue, director_.angle(), f, meta_.hello->field, aspect);
    target.has_shot = true;
    target.shot_eye = r.eye;
    target.shot_look = r.look;
    target.shot_fov = r.fov;
    target.shot_cut = director_cut_;
  }
  director_cut_ = false;
  camera_.update(dt, target, aspect, meta_.hello->field);
  const int hidden = camera_.mode() == CameraMode::Player ? selected_ : -1;
  renderer_->draw(f, *meta_.hello, *model_, camera_, width, height, hidden, selected_);

  HudInfo info;
  const auto& hello = *meta_.hello;
  info.left_name = hello.left.name.empty() ? "LEFT" : hello.left.name;
  info.right_name = hello.right.name.empty() ? "RIGHT" : hello.right.name;
  info.left_color = team_kit(hello.left, Side::Left, false).shirt;
  info.right_color = team_kit(hello.right, Side::Right, false).shirt;
  info.score_left = f.score_left;
  info.score_right = f.score_right;
  info.pen_left = meta_.pen_left;
  info.pen_right = meta_.pen_right;
  info.time = f.time;
  info.play_mode = std::string(play_mode_name(f.play_mode));
  info.camera = std::string(camera_mode_name(camera_.mode())) + " [" + camera_mode_key(camera_.mode()) + "]";
  info.chosen = slot_name(selected_);
  if (source_->paused()) info.playback = "PAUSED";
  else if (source_->speed() != 1.0) info.playback = "x" + std::to_string(source_->speed()).substr(0, 4);
  if (director_.replaying() && camera_.mode() == CameraMode::Director) info.playback = "REPLAY";
  info.status = meta_.status;
  if (labels_) {
    std::vector<glm::mat4> joints;
    for (int i = 0; i < kMaxPlayers; ++i) {
      const PlayerPose& p = f.players[i];
      if (!player_visible(p) || i == hidden) continue;
      glm::vec2 px;
      if (!camera_.project(to_scene(p.x, p.y, p.z + 1.15f), width, height, px)) continue;
      const Kit kit = team_kit(p.side == Side::Right ? hello.right : hello.left, p.side,
                               (p.state & state_bits::kGoalie) != 0);
      // Lifted a little above the head so that it never hides the shirt.
      info.labels.push_back({px - glm::vec2(0.0f, 8.0f), p.unum, kit.shirt, kit.number});
    }
  }
  hud_->draw(info, width, height);
}

void App::follow_director(double live_seq, double dt, double rate) {
  if (buffer_.track().cues_added() != cues_seen_) {
    cues_seen_ = buffer_.track().cues_added();
    cues_ = buffer_.track().cues();
  }
  const DirectorView::Step step =
      director_.update(live_seq, dt, cues_, camera_.mode() == CameraMode::Director, history_, rate);
  if (step.cut) director_cut_ = true;
  // A replay draws the history instead of the live picture.
  if (step.replaying) history_.at(step.replay_seq, meta_.hello->skeleton.dof_count(), *frame_, feet_.get());
}

void App::draw_waiting(const std::string& status, int width, int height) {
  renderer_->clear(width, height);
  HudInfo info;
  info.waiting = true;
  info.camera = std::string(camera_mode_name(camera_.mode()));
  info.status = status;
  hud_->draw(info, width, height);
}

int App::run_window() {
  const double start = glfwGetTime();
  double last = start;
  // Figures printed with --quit-after: what a slow GPU or network did.
  long drawn = 0;
  std::uint64_t skips = 0;
  double lag_sum = 0, lag_max = 0, lag_last = 0;
  while (!glfwWindowShouldClose(window_)) {
    if (options_.quit_after_s > 0 && glfwGetTime() - start >= options_.quit_after_s) break;
    glfwPollEvents();
    const double now = glfwGetTime();
    const double dt = std::min(now - last, 0.5);
    last = now;
    check_hello();
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    if (width <= 0 || height <= 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));  // minimised
      continue;
    }
    // The playhead runs at the stream's rate (x speed for replays), apart
    // from the network: the source thread only fills the buffer.
    const double rate = source_->paused() ? 0.0 : source_->speed();
    if (model_ && buffer_.sample(playhead_, dt * meta_.hello->frame_rate * rate, *sample_)) {
      blend_frames(sample_->a, sample_->b, sample_->t, meta_.hello->skeleton.dof_count(), *frame_, feet_.get());
      history_.add(sample_->a);
      history_.add(sample_->b);
      follow_director(sample_->playhead, dt, rate);
      heads_->apply(*frame_, dt);
      const auto max = meta_.hello->server_params.find("stamina_max");
      fatigue_->apply(*frame_, dt, buffer_.track().stamina(),
                      max != meta_.hello->server_params.end() ? static_cast<float>(max->second) : 8000.0f);
      // Every pose drawn rests on the grass (proto/SPEC.md 4.7): a blend of
      // two frames can dip a sole a few centimetres under it.
      anim::rest_on_grass(meta_.hello->skeleton, *frame_);
      draw(*frame_, width, height, dt, sample_->playhead);
      ++drawn;
      skips += sample_->skipped;
      lag_last = sample_->newest - sample_->playhead;
      lag_sum += lag_last;
      lag_max = std::max(lag_max, lag_last);
    } else {
      draw_waiting(meta_.status.empty() ? "waiting for " + source_->describe() : meta_.status, width, height);
    }
    glfwSwapBuffers(window_);
    if (options_.simulate_slow_ms > 0)
      std::this_thread::sleep_for(std::chrono::milliseconds(options_.simulate_slow_ms));
  }
  if (options_.quit_after_s > 0) {
    const double seconds = glfwGetTime() - start;
    std::printf("matchcast-viewer: drew %ld frames in %.1f s (%.1f fps); playhead skips to a keyframe: %llu; "
                "frames behind the newest: mean %.1f, max %.1f, at the end %.1f; buffer drops: %llu\n",
                drawn, seconds, drawn / std::max(seconds, 1e-9), static_cast<unsigned long long>(skips),
                drawn ? lag_sum / drawn : 0.0, lag_max, lag_last,
                static_cast<unsigned long long>(buffer_.dropped()));
  }
  return 0;
}

int App::run_screenshot() {
  std::string error;
  gl::Framebuffer target;
  if (!target.create(options_.width, options_.height, error)) {
    std::fprintf(stderr, "matchcast-viewer: %s\n", error.c_str());
    return 1;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options_.timeout_s);
  std::optional<PoseFrame> found;
  while (std::chrono::steady_clock::now() < deadline) {
    check_hello();
    if (model_ && (found = buffer_.frame_at_time(options_.at))) break;
    if (source_->exhausted()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!found) {
    check_hello();
    const std::string why = "no frame at or after cycle " + std::to_string(options_.at) + " from " +
                            source_->describe() + (meta_.status.empty() ? "" : ": " + meta_.status);
    std::fprintf(stderr, "matchcast-viewer: %s\n", why.c_str());
    // The picture says it too: what the window would show.
    target.bind();
    draw_waiting(why, options_.width, options_.height);
    glFinish();
    Image image{options_.width, options_.height, target.read_rgb()};
    write_png(options_.screenshot, image, error);
    return 2;
  }
  check_hello();
  *frame_ = *found;
  history_.add(*frame_);
  follow_director(frame_->seq, 0.0, 1.0);
  target.bind();
  camera_.snap();
  draw(*frame_, options_.width, options_.height, 0.0);
  glFinish();
  Image image{options_.width, options_.height, target.read_rgb()};
  if (!write_png(options_.screenshot, image, error) || (!options_.report.empty() && !write_report(*frame_, error))) {
    std::fprintf(stderr, "matchcast-viewer: %s\n", error.c_str());
    return 1;
  }
  std::printf("matchcast-viewer: wrote %s (frame %u, cycle %d, camera %s)\n", options_.screenshot.c_str(),
              frame_->seq, frame_->time, std::string(camera_mode_name(camera_.mode())).c_str());
  return 0;
}

bool App::write_report(const PoseFrame& f, std::string& error) const {
  nlohmann::json j;
  j["seq"] = f.seq;
  j["time"] = f.time;
  j["substep"] = f.substep;
  j["camera"] = {{"mode", camera_mode_name(camera_.mode())},
                 {"eye", {camera_.eye().x, camera_.eye().y, camera_.eye().z}},
                 {"look", {camera_.look().x, camera_.look().y, camera_.look().z}},
                 {"fov", camera_.fov_deg()}};
  j["selected"] = selected_;
  j["width"] = options_.width;
  j["height"] = options_.height;
  std::ofstream out(options_.report);
  out << j.dump(1) << "\n";
  if (!out) {
    error = "cannot write " + options_.report;
    return false;
  }
  return true;
}

}  // namespace mc::viewer
