// Time shift on loopback: a live spectator rewinds its channel into the
// channel's own recording while it is still being written, moves to a point
// recorded after the shift began, and comes back to live; another spectator
// of the same channel sees an unbroken live stream all along.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>

#include "proto/frame_codec.hpp"
#include "proto/frame_header.hpp"
#include "server/app/log_feed.hpp"
#include "server/app/recorder.hpp"
#include "server/relay/relay_server.hpp"
#include "server/replay/replay_catalog.hpp"
#include "tests/relay/ws_test_client.hpp"

namespace fs = std::filesystem;
using mc::relay::testing::WsTestClient;

namespace mc::replay {
namespace {

const std::string kLog = std::string(MATCHCAST_SOURCE_DIR) +
                         "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";


// Reads until a frame, skipping text; returns its header. `texts` collects
// the JSON messages met on the way.
proto::FrameHeader next_frame(WsTestClient& c, std::vector<nlohmann::json>* texts = nullptr) {
  for (int i = 0; i < 400; ++i) {
    auto m = c.read();
    if (!m.binary) {
      if (texts) texts->push_back(nlohmann::json::parse(m.data, nullptr, false));
      continue;
    }
    proto::FrameHeader h;
    std::string error;
    EXPECT_TRUE(proto::peek_header(m.data, h, error)) << error;
    return h;
  }
  ADD_FAILURE() << "no frame";
  return {};
}

// Reads until a {"type":"timeshift"} message; frames on the way are skipped.
nlohmann::json next_timeshift(WsTestClient& c) {
  for (int i = 0; i < 400; ++i) {
    auto m = c.read();
    if (m.binary) continue;
    auto j = nlohmann::json::parse(m.data, nullptr, false);
    if (j.is_object() && j.value("type", "") == "timeshift") return j;
  }
  ADD_FAILURE() << "no timeshift message";
  return {};
}

class TimeshiftTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mc-timeshift-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    channels_ = std::make_shared<relay::ChannelRegistry>();
    app::FeedConfig feed_config;
    feed_config.log_path = kLog;
    feed_config.speed = 10;  // 100 cycles a second: the recording grows fast
    feed_ = std::make_unique<app::LogFeed>(feed_config, channels_->open("live"));
    std::string error;
    ASSERT_TRUE(feed_->start(error)) << error;
    recorder_ = app::Recorder::start(channels_->find("live"), (dir_ / "live.mcrec").string(), error);
    ASSERT_TRUE(recorder_) << error;
    catalog_ = std::make_unique<ReplayCatalog>(dir_.string());
    catalog_->set_live_recording("live", "live.mcrec");
    channels_->open("unrecorded")->set_hello(R"({"type":"hello"})");
    relay::RelayConfig config;
    config.port = 0;
    config.web_root = dir_.string();
    config.threads = 2;
    server_ = std::make_unique<relay::RelayServer>(config, channels_, nullptr, catalog_.get());
    ASSERT_TRUE(server_->start(error)) << error;
    // A few seconds of game recorded (chunks are written at each keyframe).
    for (int i = 0; i < 500 && feed_->frames() < 300; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  void TearDown() override {
    if (server_) server_->stop();
    if (feed_) feed_->stop();
    if (recorder_) recorder_->stop();
    fs::remove_all(dir_);
  }

  fs::path dir_;
  std::shared_ptr<relay::ChannelRegistry> channels_;
  std::unique_ptr<app::LogFeed> feed_;
  std::shared_ptr<app::Recorder> recorder_;
  std::unique_ptr<ReplayCatalog> catalog_;
  std::unique_ptr<relay::RelayServer> server_;
};

TEST_F(TimeshiftTest, RewindIntoTheGrowingRecordingAndBackToLive) {
  WsTestClient shifter(server_->port(), "/ws?channel=live");
  WsTestClient watcher(server_->port(), "/ws?channel=live");
  const auto live_start = next_frame(shifter);
  next_frame(watcher);
  ASSERT_GT(live_start.time, 60);

  // Rewind to cycle 30: the first frame after the switch is a keyframe there.
  shifter.write_text(R"({"type":"timeshift","action":"seek","time":30})");
  EXPECT_EQ(next_timeshift(shifter).value("mode", ""), "replay");
  std::vector<nlohmann::json> texts;
  auto f = next_frame(shifter, &texts);
  ASSERT_FALSE(texts.empty());
  EXPECT_EQ(texts.front().value("type", ""), "hello");  // the replay's stream starts over
  EXPECT_TRUE(f.keyframe);
  EXPECT_GE(f.time, 30);
  EXPECT_LT(f.time, 40);
  // It plays on from there with a continuous sequence.
  for (int i = 0; i < 10; ++i) {
    const auto g = next_frame(shifter);
    EXPECT_EQ(g.seq, f.seq + 1);
    EXPECT_GE(g.time, f.time);
    f = g;
  }
  EXPECT_LT(f.time, live_start.time);

  // Meanwhile the game goes on and its recording grows: a point recorded
  // after the shift began is reachable.
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  shifter.write_text(R"({"type":"timeshift","action":"seek","time":1000000})");
  // Frames played during the wait come first; then the jump, as a keyframe.
  const int before_jump = f.time;
  for (int i = 0; i < 200 && f.time < before_jump + 50; ++i) f = next_frame(shifter);
  EXPECT_TRUE(f.keyframe);
  EXPECT_GT(f.time, live_start.time + 50) << "the shift did not follow the growing recording";

  // Back to live: the latest keyframe of the live channel, ahead of the
  // recording (which trails live by up to one chunk).
  shifter.write_text(R"({"type":"timeshift","action":"live"})");
  EXPECT_EQ(next_timeshift(shifter).value("mode", ""), "live");
  const auto back = next_frame(shifter);
  EXPECT_TRUE(back.keyframe);
  EXPECT_GE(back.time, f.time);

  // The other spectator never saw any of it: live frames, no gap.
  auto w = next_frame(watcher);
  for (int i = 0; i < 100; ++i) {
    const auto g = next_frame(watcher);
    ASSERT_EQ(g.seq, w.seq + 1);
    w = g;
  }
}

TEST_F(TimeshiftTest, ReplayControlsSteerTheShiftOnly) {
  WsTestClient c(server_->port(), "/ws?channel=live");
  next_frame(c);
  // Not shifted: replay controls from a live spectator are ignored.
  c.write_text(R"({"type":"replay","action":"pause"})");
  c.write_text(R"({"type":"timeshift","action":"live"})");
  const auto a = next_frame(c);
  const auto b = next_frame(c);
  EXPECT_EQ(b.seq, a.seq + 1);
  // Shifted: pausing holds the picture, and status messages say so.
  c.write_text(R"({"type":"timeshift","action":"seek","time":50})");
  EXPECT_EQ(next_timeshift(c).value("mode", ""), "replay");
  next_frame(c);
  c.write_text(R"({"type":"replay","action":"pause"})");
  for (int i = 0; i < 100; ++i) {
    auto m = c.read();
    if (m.binary) continue;
    auto j = nlohmann::json::parse(m.data, nullptr, false);
    if (j.value("type", "") == "replay" && j.value("paused", false)) {
      EXPECT_FALSE(j.value("live_edge", true));
      return;
    }
  }
  FAIL() << "no paused status";
}

TEST_F(TimeshiftTest, AShiftedSpectatorGetsACloseFrameOnShutdown) {
  WsTestClient c(server_->port(), "/ws?channel=live");
  next_frame(c);
  c.write_text(R"({"type":"timeshift","action":"seek","time":20})");
  EXPECT_EQ(next_timeshift(c).value("mode", ""), "replay");
  // It no longer follows a registered channel, yet the stop reaches it.
  std::thread stopper([&] { server_->stop(); });
  std::uint16_t code = 0;
  try {
    for (int i = 0; i < 1000; ++i) c.read();
  } catch (const boost::system::system_error& e) {
    if (e.code() == boost::beast::websocket::error::closed) code = c.stream().reason().code;
  }
  stopper.join();
  EXPECT_EQ(code, static_cast<std::uint16_t>(boost::beast::websocket::close_code::going_away));
}

TEST_F(TimeshiftTest, AnUnrecordedChannelSaysSoAndStaysLive) {
  WsTestClient c(server_->port(), "/ws?channel=unrecorded");
  EXPECT_FALSE(c.read().binary);  // hello
  c.write_text(R"({"type":"timeshift","action":"seek","time":10})");
  auto j = next_timeshift(c);
  EXPECT_EQ(j.value("mode", ""), "live");
  EXPECT_NE(j.value("error", "").find("not recorded"), std::string::npos) << j.dump();
  // Garbage is ignored, the connection stays.
  c.write_text("{not json");
  c.write_text(R"({"type":"timeshift","action":"seek","time":"soon"})");
  c.write_text(R"({"type":"timeshift"})");
  channels_->find("unrecorded")->publish_control(R"({"type":"still-here"})");
  EXPECT_EQ(c.read().data, R"({"type":"still-here"})");
}

}  // namespace
}  // namespace mc::replay
