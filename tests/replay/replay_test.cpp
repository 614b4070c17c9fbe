// Replays over a real relay on loopback: a recording made from the real game
// is opened by a spectator, who seeks, changes speed, jumps to goals and
// pauses, with every frame decodable and the sequence continuous.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"
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

class ReplayTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("mc-replay-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    // Record about 90 s of the real game (the first goal falls at cycle 720)
    // by broadcasting it at 60x for 1.5 s.
    auto channels = std::make_shared<relay::ChannelRegistry>();
    app::FeedConfig config;
    config.log_path = kLog;
    config.speed = 100;
    app::LogFeed feed(config, channels->open("live"));
    std::string error;
    ASSERT_TRUE(feed.start(error)) << error;
    auto rec = app::Recorder::start(channels->find("live"), (dir_ / "game.mcrec").string(), error);
    ASSERT_TRUE(rec) << error;
    for (int i = 0; i < 200 && feed.frames() < 2200; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    feed.stop();
    rec->stop();
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  void SetUp() override {
    config_.port = 0;
    config_.web_root = dir_.string();
    config_.threads = 2;
    catalog_ = std::make_unique<ReplayCatalog>(dir_.string());
    server_ = std::make_unique<relay::RelayServer>(config_, std::make_shared<relay::ChannelRegistry>(),
                                                   nullptr, catalog_.get());
    std::string error;
    ASSERT_TRUE(server_->start(error)) << error;
  }

  // Reads until a replay status or frame; fills `status` for statuses.
  struct Reader {
    Reader(WsTestClient& client, const SkeletonDef& skeleton) : c(client), decoder(skeleton) {}
    WsTestClient& c;
    proto::FrameDecoder decoder;
    PoseFrame frame;
    nlohmann::json status;
    std::uint32_t last_seq = 0;
    bool have_seq = false;
    int frames = 0;
    // Next frame (statuses on the way are kept); fails the test on a gap.
    void next_frame() {
      for (int i = 0; i < 200; ++i) {
        auto m = c.read();
        if (!m.binary) {
          auto j = nlohmann::json::parse(m.data, nullptr, false);
          if (j.is_object() && j.value("type", "") == "replay") status = j;
          continue;
        }
        std::string error;
        ASSERT_TRUE(decoder.decode(m.data, frame, error)) << error;
        if (have_seq) {
          ASSERT_EQ(frame.seq, last_seq + 1);
        }
        last_seq = frame.seq;
        have_seq = true;
        ++frames;
        return;
      }
      FAIL() << "no frame";
    }
    // Reads until the next replay status (frames on the way are checked).
    void next_status() {
      for (int i = 0; i < 200; ++i) {
        auto m = c.read();
        if (m.binary) {
          std::string error;
          ASSERT_TRUE(decoder.decode(m.data, frame, error)) << error;
          if (have_seq) {
            ASSERT_EQ(frame.seq, last_seq + 1);
          }
          last_seq = frame.seq;
          have_seq = true;
          continue;
        }
        auto j = nlohmann::json::parse(m.data, nullptr, false);
        if (j.is_object() && j.value("type", "") == "replay") {
          status = j;
          return;
        }
      }
      FAIL() << "no status";
    }
  };

  static fs::path dir_;
  relay::RelayConfig config_;
  std::unique_ptr<ReplayCatalog> catalog_;
  std::unique_ptr<relay::RelayServer> server_;
};
fs::path ReplayTest::dir_;

proto::Hello read_hello(WsTestClient& c) {
  auto m = c.read();
  proto::Hello hello;
  std::string error;
  EXPECT_FALSE(m.binary);
  EXPECT_TRUE(proto::hello_from_json(m.data, hello, error)) << error;
  return hello;
}

TEST_F(ReplayTest, SeekSpeedGoalsAndPauseEachSpectatorOnItsOwn) {
  WsTestClient a(server_->port(), "/ws?recording=game.mcrec");
  WsTestClient b(server_->port(), "/ws?recording=game.mcrec");
  auto hello = read_hello(a);
  read_hello(b);
  auto ra_ptr = std::make_unique<Reader>(a, hello.skeleton);  // a decoder is large: not on the stack
  Reader& ra = *ra_ptr;
  auto rb_ptr = std::make_unique<Reader>(b, hello.skeleton);
  Reader& rb = *rb_ptr;
  ra.next_frame();
  EXPECT_LE(ra.frame.time, 2);  // starts at the beginning

  a.write_text(R"({"type":"replay","action":"seek","time":600})");
  for (int i = 0; i < 40 && !(ra.frame.time >= 600 && ra.frame.time < 620); ++i) ra.next_frame();
  EXPECT_GE(ra.frame.time, 600);
  EXPECT_LT(ra.frame.time, 620);

  a.write_text(R"({"type":"replay","action":"next_goal"})");
  for (int i = 0; i < 40 && ra.frame.time < 660; ++i) ra.next_frame();
  // The first goal (cycle 720, HELIOS_B) is announced in the status and the
  // jump lands shortly before it.
  ASSERT_TRUE(ra.status.contains("goals"));
  ASSERT_FALSE(ra.status["goals"].empty());
  const int goal = ra.status["goals"][0]["time"];
  EXPECT_EQ(ra.status["goals"][0]["side"], "r");
  EXPECT_GE(ra.frame.time, goal - 55);
  EXPECT_LE(ra.frame.time, goal);

  a.write_text(R"({"type":"replay","action":"speed","speed":4})");
  a.write_text(R"({"type":"replay","action":"pause"})");
  a.write_text("not json at all {");  // ignored, never fatal
  for (int i = 0; i < 40 && !ra.status.value("paused", false); ++i) ra.next_status();
  EXPECT_TRUE(ra.status.value("paused", false));
  EXPECT_DOUBLE_EQ(ra.status.value("speed", 0.0), 4.0);

  // Paused means paused: nothing but silence for half a second.
  EXPECT_THROW(a.read(std::chrono::milliseconds(500)), boost::system::system_error);

  // B was never steered: it is still near the start, unaffected by A.
  rb.next_frame();
  EXPECT_LT(rb.frame.time, 100);
}

TEST_F(ReplayTest, UnknownOrHostileRecordingNamesAreRefused) {
  for (const char* target : {"/ws?recording=nope.mcrec", "/ws?recording=../game.mcrec",
                             "/ws?recording=%2e%2e%2fgame.mcrec", "/ws?recording=game.txt"})
    EXPECT_THROW(WsTestClient c(server_->port(), target), boost::system::system_error) << target;
  EXPECT_FALSE(valid_recording_name("../x.mcrec"));
  EXPECT_FALSE(valid_recording_name(".hidden.mcrec"));
  EXPECT_TRUE(valid_recording_name("live-20261122-050041.mcrec"));
}

TEST_F(ReplayTest, TruncatedRecordingStillReplaysWhatItHolds) {
  // A recording cut mid-way (the server was killed) loses only its tail.
  const auto src = dir_ / "game.mcrec";
  const auto cut = dir_ / "cut.mcrec";
  {
    std::ifstream in(src, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::ofstream(cut, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  }
  WsTestClient c(server_->port(), "/ws?recording=cut.mcrec");
  auto hello = read_hello(c);
  auto r_ptr = std::make_unique<Reader>(c, hello.skeleton);
  Reader& r = *r_ptr;
  for (int i = 0; i < 10; ++i) r.next_frame();
  EXPECT_EQ(r.frames, 10);
}

}  // namespace
}  // namespace mc::replay
