// The real viewer, headless under Xvfb (Mesa llvmpipe), against a live
// matchcast-server started here on port 0 with the bundled game, and
// against the recording that server wrote. Each screenshot is checked:
// it is not blank, the players' shirts are where the frame puts them
// (their chests projected with the viewer's own camera maths), grass is
// where no player is, and two camera modes give different pictures.
// The screenshots are kept in test-output/viewer/ to be looked at.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "proto/control_messages.hpp"
#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"
#include "server/record/recording_reader.hpp"
#include "tests/relay/ws_test_client.hpp"
#include "viewer/camera.hpp"
#include "viewer/player_model.hpp"
#include "viewer/png.hpp"
#include "wasm/log_reference.hpp"
#include "tests/viewer/test_processes.hpp"

namespace mc::viewer {
namespace {

namespace fs = std::filesystem;
using namespace e2e;
constexpr int kWidth = 960, kHeight = 540;

// A spectator of our own: every frame the relay sends, decoded, by seq.
class Spectator {
 public:
  explicit Spectator(std::uint16_t port) : client_(port) {
    thread_ = std::thread([this] { run(); });
  }
  ~Spectator() {
    stop_ = true;
    thread_.join();
  }
  bool frame(std::uint32_t seq, PoseFrame& out) {
    std::lock_guard lock(mutex_);
    auto it = frames_.find(seq);
    if (it == frames_.end()) return false;
    out = it->second;
    return true;
  }
  int latest_time() {
    std::lock_guard lock(mutex_);
    return frames_.empty() ? -1 : frames_.rbegin()->second.time;
  }
  proto::Hello hello() {
    std::lock_guard lock(mutex_);
    return hello_;
  }

 private:
  void run() {
    std::unique_ptr<proto::FrameDecoder> decoder;
    auto f = std::make_unique<PoseFrame>();
    std::string error;
    while (!stop_) {
      relay::testing::Received m;
      try {
        m = client_.read(std::chrono::seconds(5));
      } catch (const std::exception&) {
        return;
      }
      if (!m.binary) {
        proto::Hello h;
        if (proto::control_type(m.data, error) == "hello" && proto::hello_from_json(m.data, h, error)) {
          std::lock_guard lock(mutex_);
          hello_ = h;
          decoder = std::make_unique<proto::FrameDecoder>(h.skeleton);
        }
      } else if (decoder && decoder->decode(m.data, *f, error)) {
        std::lock_guard lock(mutex_);
        frames_[f->seq] = *f;
      }
    }
  }
  relay::testing::WsTestClient client_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::map<std::uint32_t, PoseFrame> frames_;
  proto::Hello hello_;
};

struct Shot {
  Image image;
  nlohmann::json report;
};

// Runs the viewer under xvfb-run; the PNG and its report go to test-output/viewer/NAME.*.
Shot screenshot(const std::string& source, int at, const std::string& camera, const std::string& name,
                const std::vector<std::string>& extra = {}) {
  const std::string png = kOut + "/" + name + ".png", json = kOut + "/" + name + ".json";
  fs::remove(png);
  std::vector<std::string> args = xvfb(name);
  const std::vector<std::string> viewer = {MATCHCAST_VIEWER, source, "--screenshot", png, "--at", std::to_string(at),
                                           "--camera", camera, "--width", std::to_string(kWidth), "--height",
                                           std::to_string(kHeight), "--report", json, "--timeout", "60"};
  args.insert(args.end(), viewer.begin(), viewer.end());
  args.insert(args.end(), extra.begin(), extra.end());
  const Child c = spawn(args, kOut + "/" + name + ".log", false, kOut);
  Shot shot;
  EXPECT_GT(c.pid, 0);
  if (c.pid <= 0) return shot;
  const int code = wait_for(c.pid, 120);
  EXPECT_EQ(code, 0) << name << ": " << slurp(kOut + "/" + name + ".log");
  std::string error;
  EXPECT_TRUE(read_png(png, shot.image, error)) << error;
  std::ifstream in(json);
  shot.report = nlohmann::json::parse(in, nullptr, false);
  return shot;
}

// Not blank: many colours, none covering almost everything.
void expect_not_blank(const Image& image, const std::string& name) {
  std::map<std::uint32_t, std::size_t> counts;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
    ++counts[(image.rgb[i] >> 3) << 10 | (image.rgb[i + 1] >> 3) << 5 | (image.rgb[i + 2] >> 3)];
  std::size_t top = 0;
  for (const auto& [c, n] : counts) top = std::max(top, n);
  EXPECT_GE(counts.size(), 40u) << name << " has too few colours";
  EXPECT_LT(static_cast<double>(top) / (image.width * image.height), 0.8) << name << " is mostly one colour";
}

// A pixel in the kit colour `shirt` (0..1), lit between 40 % and 110 %.
bool looks_like(const std::uint8_t* p, glm::vec3 shirt) {
  const glm::vec3 s = shirt * 255.0f, q(p[0], p[1], p[2]);
  const float k = glm::dot(q, s) / glm::dot(s, s);
  return k >= 0.4f && k <= 1.1f && glm::length(q - k * s) <= 0.12f * glm::length(s) + 12.0f;
}

bool found_near(const Image& image, glm::vec2 px, glm::vec3 color, int radius) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int x = static_cast<int>(std::lround(px.x)) + dx, y = static_cast<int>(std::lround(px.y)) + dy;
      if (x >= 0 && y >= 0 && x < image.width && y < image.height && looks_like(image.at(x, y), color)) return true;
    }
  return false;
}

// Projects every field player's chest with the viewer's camera for this
// frame and looks for his shirt colour there; grass points away from every
// player must not look like a shirt (so the check can fail).
void expect_players_where_the_frame_puts_them(const Shot& shot, const PoseFrame& f, const proto::Hello& hello,
                                              CameraMode mode, const std::string& name) {
  Camera camera;
  camera.set_mode(mode);
  CameraTarget target;
  target.ball = to_scene(f.ball.x, f.ball.y, f.ball.z);
  camera.update(0.0, target, static_cast<float>(kWidth) / kHeight, hello.field);
  ASSERT_TRUE(shot.report.is_object()) << name;
  EXPECT_NEAR(shot.report["camera"]["eye"][0].get<float>(), camera.eye().x, 0.01) << name;
  EXPECT_NEAR(shot.report["camera"]["eye"][2].get<float>(), camera.eye().z, 0.01) << name;

  const PlayerModel model(hello.skeleton);
  std::vector<glm::mat4> joints;
  std::vector<glm::vec2> chest(kMaxPlayers, glm::vec2(-1000.0f));
  for (int i = 0; i < kMaxPlayers; ++i) {
    if (!player_visible(f.players[i]) || !model.joints(f.players[i], joints)) continue;
    camera.project(model.segment_center(joints, model.chest_joint()), kWidth, kHeight, chest[i]);
  }
  int eligible = 0, matched = 0, grass_checked = 0, grass_matched = 0;
  std::string missed;
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerPose& p = f.players[i];
    if (!player_visible(p) || (p.state & state_bits::kGoalie)) continue;
    if (chest[i].x < 10 || chest[i].y < 40 || chest[i].x > kWidth - 10 || chest[i].y > kHeight - 10) continue;
    bool alone = true;
    for (int j = 0; j < kMaxPlayers; ++j)
      if (j != i && glm::length(chest[j] - chest[i]) < 16.0f) alone = false;
    if (!alone) continue;
    const glm::vec3 shirt = team_kit(p.side == Side::Right ? hello.right : hello.left, p.side, false).shirt;
    ++eligible;
    if (found_near(shot.image, chest[i], shirt, 3))
      ++matched;
    else
      missed += " " + std::string(p.side == Side::Left ? "L" : "R") + std::to_string(p.unum);
    // Grass 6 m beside him, away on screen from every player and number label.
    const float gx = p.x + (p.x > 0 ? -6.0f : 6.0f), gy = p.y;
    glm::vec2 g;
    if (!camera.project(to_scene(gx, gy, 0.0f), kWidth, kHeight, g) || g.x < 5 || g.y < 60 || g.x > kWidth - 5 ||
        g.y > kHeight - 60)
      continue;
    bool empty = true;
    for (int j = 0; j < kMaxPlayers; ++j) {
      glm::vec2 label;
      const PlayerPose& q = f.players[j];
      if (!player_visible(q)) continue;
      if (glm::length(chest[j] - g) < 20.0f) empty = false;
      if (camera.project(to_scene(q.x, q.y, q.z + 1.15f), kWidth, kHeight, label) && glm::length(label - g) < 25.0f)
        empty = false;
    }
    if (!empty) continue;
    ++grass_checked;
    if (found_near(shot.image, g, shirt, 1)) ++grass_matched;
  }
  std::printf("%s: %d of %d field players' shirts where the frame puts them; %d of %d grass points look like a shirt\n",
              name.c_str(), matched, eligible, grass_matched, grass_checked);
  EXPECT_GE(eligible, 4) << name << ": too few players to check";
  EXPECT_GE(matched, eligible * 3 / 4 + (eligible * 3 % 4 ? 1 : 0)) << name << ": shirts missing at" << missed;
  EXPECT_GE(grass_checked, 2) << name;
  EXPECT_EQ(grass_matched, 0) << name << ": shirt colours where there is only grass";
}

double fraction_different(const Image& a, const Image& b) {
  if (a.rgb.size() != b.rgb.size() || a.rgb.empty()) return 0;
  std::size_t diff = 0;
  for (std::size_t i = 0; i + 2 < a.rgb.size(); i += 3)
    if (std::abs(a.rgb[i] - b.rgb[i]) + std::abs(a.rgb[i + 1] - b.rgb[i + 1]) + std::abs(a.rgb[i + 2] - b.rgb[i + 2]) > 40)
      ++diff;
  return static_cast<double>(diff) / (a.rgb.size() / 3);
}

TEST(Screenshot, LiveRelay) {
  Server server("");
  ASSERT_GT(server.port(), 0) << slurp(kOut + "/server.log");
  Spectator spectator(server.port());
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (spectator.latest_time() < 0 && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_GE(spectator.latest_time(), 0) << "no frame from the relay";
  // A moment ahead of the stream: the viewer draws the first frame at or after it.
  const int at = spectator.latest_time() + 20;
  const std::string url = "ws://127.0.0.1:" + std::to_string(server.port()) + "/ws";
  const Shot broadcast = screenshot(url, at, "broadcast", "live-broadcast");
  const Shot top = screenshot(url, at, "top", "live-top");
  for (const auto* shot : {&broadcast, &top}) {
    const std::string name = shot == &broadcast ? "live-broadcast" : "live-top";
    ASSERT_TRUE(shot->report.is_object()) << name;
    expect_not_blank(shot->image, name);
    PoseFrame f;
    ASSERT_TRUE(spectator.frame(shot->report["seq"].get<std::uint32_t>(), f)) << name << ": frame not seen";
    EXPECT_GE(f.time, at);
    expect_players_where_the_frame_puts_them(*shot, f, spectator.hello(),
                                             shot == &broadcast ? CameraMode::Broadcast : CameraMode::Top, name);
  }
  EXPECT_GT(fraction_different(broadcast.image, top.image), 0.2);
}

TEST(Screenshot, RecordingOfTheLiveGame) {
  const std::string dir = kOut + "/recordings";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    Server server(dir);
    ASSERT_GT(server.port(), 0) << slurp(kOut + "/server.log");
    std::this_thread::sleep_for(std::chrono::seconds(6));  // 12 s of the game at speed 2
    EXPECT_EQ(server.stop(), 0) << slurp(kOut + "/server.log");
  }
  std::string path;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".mcrec") path = e.path().string();
  ASSERT_FALSE(path.empty()) << "the server wrote no recording in " << dir;

  record::RecordingReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, error)) << error;
  EXPECT_FALSE(reader.recovered()) << "the server did not close its recording";
  PoseFrame f;
  std::vector<int> times;
  while (reader.next(f, error)) times.push_back(f.time);
  ASSERT_GE(times.size(), 100u) << error;
  const int at = times[times.size() / 2];
  ASSERT_TRUE(reader.seek(at, f, error)) << error;

  const Shot broadcast = screenshot(path, at, "broadcast", "recording-broadcast");
  const Shot top = screenshot(path, at, "top", "recording-top");
  const Shot follow = screenshot(path, at, "follow", "recording-follow", {"--follow", "l10"});
  for (const auto* shot : {&broadcast, &top, &follow}) {
    ASSERT_TRUE(shot->report.is_object());
    EXPECT_EQ(shot->report["seq"].get<std::uint32_t>(), f.seq);  // exactly the frame the file has there
    expect_not_blank(shot->image, "recording");
  }
  expect_players_where_the_frame_puts_them(broadcast, f, reader.hello(), CameraMode::Broadcast, "recording-broadcast");
  expect_players_where_the_frame_puts_them(top, f, reader.hello(), CameraMode::Top, "recording-top");
  EXPECT_GT(fraction_different(broadcast.image, top.image), 0.2);
  EXPECT_GT(fraction_different(broadcast.image, follow.image), 0.2);
}

// The bundled game as the server's pipeline makes it (the viewer animates a
// log in-process with the same pipeline): frames by seq and the kicks.
struct Broadcast {
  proto::Hello hello;
  std::map<std::uint32_t, PoseFrame> frames;
  std::vector<proto::KickEvent> kicks;
};

Broadcast broadcast_of(const std::string& log) {
  Broadcast b;
  std::string out, error;
  EXPECT_TRUE(wasm::broadcast_log_file(log, {}, out, error)) << error;
  std::unique_ptr<proto::FrameDecoder> decoder;
  for (std::size_t i = 0; i + 5 <= out.size();) {
    const char kind = out[i];
    std::uint32_t n = 0;
    for (int k = 0; k < 4; ++k) n |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(out[i + 1 + k])) << (8 * k);
    const std::string_view bytes = std::string_view(out).substr(i + 5, n);
    i += 5 + n;
    if (kind == 'h') {
      EXPECT_TRUE(proto::hello_from_json(bytes, b.hello, error)) << error;
      decoder = std::make_unique<proto::FrameDecoder>(b.hello.skeleton);
    } else if ((kind == 'k' || kind == 'f') && decoder) {
      PoseFrame f;
      if (decoder->decode(bytes, f, error)) b.frames[f.seq] = f;
    } else if (kind == 'c') {
      proto::ControlMessage m;
      if (proto::control_from_json(bytes, m, error))
        if (const auto* k = std::get_if<proto::KickEvent>(&m)) b.kicks.push_back(*k);
    }
  }
  return b;
}

std::string follow_arg(const PlayerPose& p) {
  return (p.side == Side::Right ? "r" : "l") + std::to_string(p.unum);
}

// A close-up: the viewer's camera stood where the page's close-up stands,
// beside the chosen player; his whole body, head to feet, fills over a
// third of the picture's height, his shirt is drawn at his chest, and (for
// a kick) the ball is in the picture with him.
void expect_close_up_of(const Shot& shot, const Broadcast& b, int slot, bool with_ball, const std::string& name) {
  ASSERT_TRUE(shot.report.is_object()) << name;
  expect_not_blank(shot.image, name);
  const auto it = b.frames.find(shot.report["seq"].get<std::uint32_t>());
  ASSERT_NE(it, b.frames.end()) << name << ": the viewer drew a frame the pipeline did not make";
  const PlayerPose& p = it->second.players[slot];
  ASSERT_TRUE(player_visible(p)) << name;
  Camera camera;
  camera.set_mode(CameraMode::Closeup);
  CameraTarget target;
  target.has_player = true;
  target.player_root = to_scene(p.x, p.y, 0.0f);
  camera.update(0.0, target, static_cast<float>(kWidth) / kHeight, b.hello.field);
  EXPECT_NEAR(shot.report["camera"]["eye"][0].get<float>(), camera.eye().x, 0.05) << name;
  EXPECT_NEAR(shot.report["camera"]["eye"][2].get<float>(), camera.eye().z, 0.05) << name;

  const PlayerModel model(b.hello.skeleton);
  std::vector<glm::mat4> joints;
  ASSERT_TRUE(model.joints(p, joints)) << name;
  glm::vec2 head, chest, lfoot, rfoot;
  ASSERT_TRUE(camera.project(model.segment_center(joints, model.head_joint()), kWidth, kHeight, head));
  ASSERT_TRUE(camera.project(model.segment_center(joints, model.chest_joint()), kWidth, kHeight, chest));
  ASSERT_TRUE(camera.project(glm::vec3(joints[b.hello.skeleton.find("l_foot")][3]), kWidth, kHeight, lfoot));
  ASSERT_TRUE(camera.project(glm::vec3(joints[b.hello.skeleton.find("r_foot")][3]), kWidth, kHeight, rfoot));
  const float feet_y = std::max(lfoot.y, rfoot.y);
  std::printf("%s: %s at (%.1f, %.1f), head at y %.0f px, feet at y %.0f px of %d\n", name.c_str(),
              follow_arg(p).c_str(), p.x, p.y, head.y, feet_y, kHeight);
  EXPECT_GT(head.y, 0) << name;
  EXPECT_LT(feet_y, kHeight) << name;
  EXPECT_GT(feet_y - head.y, kHeight / 3.0f) << name << ": not a close-up";
  const glm::vec3 shirt = team_kit(p.side == Side::Right ? b.hello.right : b.hello.left, p.side, false).shirt;
  EXPECT_TRUE(found_near(shot.image, chest, shirt, 6)) << name << ": no shirt at his chest";
  if (with_ball) {
    glm::vec2 ball;
    const BallPose& bl = it->second.ball;
    ASSERT_TRUE(camera.project(to_scene(bl.x, bl.y, bl.z), kWidth, kHeight, ball)) << name;
    EXPECT_TRUE(ball.x > 0 && ball.y > 0 && ball.x < kWidth && ball.y < kHeight) << name << ": the ball is off the picture";
  }
}

TEST(Screenshot, CloseUpsOfBodiesRunningAndKicking) {
  const Broadcast b = broadcast_of(kLog);
  ASSERT_GT(b.frames.size(), 1000u);
  ASSERT_FALSE(b.kicks.empty());
  // A field player running fast (6.5 m/s or more over the 0.5 s either
  // side, so not a set piece's jump) in open play, and a kick by a field
  // player, both well after the kick-off.
  int run_time = -1, run_slot = -1;
  PlayerPose runner;
  for (auto it = b.frames.begin(); it != b.frames.end() && run_time < 0; ++it) {
    const auto before = b.frames.find(it->first - 10), after = b.frames.find(it->first + 10);
    if (it->second.time < 300 || before == b.frames.end() || after == b.frames.end()) continue;
    for (int s = 0; s < kMaxPlayers; ++s) {
      const PlayerPose &p0 = before->second.players[s], &p1 = after->second.players[s];
      if (!player_visible(p0) || !player_visible(p1) || (p1.state & state_bits::kGoalie)) continue;
      const float v = std::hypot(p1.x - p0.x, p1.y - p0.y);  // m per second (20 frames)
      if (v >= 6.5f && v < 11.0f && std::abs(p1.y) < 30.0f) {
        run_time = it->second.time;
        run_slot = s;
        runner = it->second.players[s];
        break;
      }
    }
  }
  ASSERT_GE(run_time, 0) << "nobody runs at 6.5 m/s in the bundled game";
  const proto::KickEvent* kick = nullptr;
  for (const auto& k : b.kicks) {
    const auto f = b.frames.find(k.seq);
    if (k.time >= 300 && f != b.frames.end() && !(f->second.players[player_index(k.side, k.unum)].state & state_bits::kGoalie)) {
      kick = &k;
      break;
    }
  }
  ASSERT_NE(kick, nullptr);
  const int kick_slot = player_index(kick->side, kick->unum);
  const PlayerPose& kicker = b.frames.at(kick->seq).players[kick_slot];

  const Shot run = screenshot(kLog, run_time, "closeup", "closeup-running",
                              {"--follow", follow_arg(runner)});
  const Shot kicking = screenshot(kLog, kick->time, "closeup", "closeup-kicking", {"--follow", follow_arg(kicker)});
  expect_close_up_of(run, b, run_slot, false, "closeup-running");
  expect_close_up_of(kicking, b, kick_slot, true, "closeup-kicking");
  // Two moments, two players: not the same picture (sky and grass fill most of both).
  EXPECT_GT(fraction_different(run.image, kicking.image), 0.04);
}

TEST(Screenshot, ARefusedRelayOrACorruptRecordingFailsWithAClearMessage) {
  fs::create_directories(kOut);
  const std::string bad = kOut + "/corrupt.mcrec";
  std::ofstream(bad, std::ios::binary) << std::string(3000, '\x42');
  for (const auto& [source, expected] : std::vector<std::pair<std::string, std::string>>{
           {bad, "cannot open recording"}, {"ws://127.0.0.1:1/ws", "refused"}}) {
    const std::string name = source == bad ? "failed-corrupt-recording" : "failed-refused-relay";
    const std::string png = kOut + "/" + name + ".png", log = kOut + "/" + name + ".log";
    fs::remove(png);
    std::vector<std::string> args = xvfb(name);
    for (const std::string& a : {std::string(MATCHCAST_VIEWER), source, std::string("--screenshot"), png,
                                 std::string("--at"), std::string("0"), std::string("--timeout"), std::string("3")})
      args.push_back(a);
    const Child c = spawn(args, log, false, kOut);
    ASSERT_GT(c.pid, 0);
    EXPECT_EQ(wait_for(c.pid, 60), 2) << slurp(log);
    EXPECT_NE(slurp(log).find(expected), std::string::npos) << slurp(log);
    // The picture shows the reason instead of a game.
    Image image;
    std::string error;
    ASSERT_TRUE(read_png(png, image, error)) << error;
    std::size_t text = 0;  // the HUD's yellow status text
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
      text += image.rgb[i] > 200 && image.rgb[i + 1] > 180 && image.rgb[i + 2] < 120;
    EXPECT_GT(text, 500u) << name << ": no message on the picture";
  }
}

}  // namespace
}  // namespace mc::viewer
