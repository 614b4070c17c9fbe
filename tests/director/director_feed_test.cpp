// The director in the server: the bundled game through LogFeed, a spectator
// and the recorder on its channel. The director's cues go out just before
// the frame they name, the first goal's scorer and replay among them, and
// the recording holds the same cues in the same places.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "proto/control_messages.hpp"
#include "proto/frame_codec.hpp"
#include "anim/human_skeleton.hpp"
#include "proto/hello.hpp"
#include "server/app/log_feed.hpp"
#include "server/app/recorder.hpp"
#include "server/record/recording_reader.hpp"
#include "tests/relay/channel_collector.hpp"

namespace mc::director {
namespace {

const std::string kLog = std::string(MATCHCAST_SOURCE_DIR) + "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";

bool is_director(const std::string& text) {
  std::string error;
  return proto::control_type(text, error) == "director";
}

TEST(DirectorFeed, CuesLeaveBeforeTheirFramesAndAreRecorded) {
  const auto dir = std::filesystem::temp_directory_path() / ("matchcast-director-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "game.mcrec").string();

  auto channel = std::make_shared<relay::Channel>("test");
  app::FeedConfig config;
  config.log_path = kLog;
  config.speed = 40;  // 800 frames per second
  config.loop = false;
  app::LogFeed feed(config, channel);
  std::string error;
  ASSERT_TRUE(feed.start(error)) << error;
  auto collector = std::make_shared<relay::testing::ChannelCollector>();
  const auto first = channel->join(collector);
  ASSERT_FALSE(first.empty());
  auto recorder = app::Recorder::start(channel, path, error);
  ASSERT_TRUE(recorder) << error;

  // Until the first goal's replay has gone out and the live shot after it.
  auto replay_seen = [&] {
    int replay = 0, after = 0;
    for (const auto& m : collector->snapshot()) {
      if (m.binary() || !is_director(*m.bytes)) continue;
      if (m.bytes->find("\"shot\":\"replay\"") != std::string::npos) ++replay;
      else if (replay > 0) ++after;
    }
    return replay > 0 && after > 0;
  };
  for (int i = 0; i < 600 && !replay_seen(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  feed.stop();
  recorder->stop();
  ASSERT_TRUE(replay_seen()) << "no replay within 30 s";

  // What the spectator got: each cue names the frame that follows it.
  std::vector<std::string> sent;
  std::vector<proto::DirectorCue> pending;
  int cuts = 0, frames = 0;
  bool scorer = false, replay = false;
  proto::FrameDecoder decoder(anim::human_skeleton());
  PoseFrame f;
  std::vector<relay::Message> messages(first.begin() + 1, first.end());
  for (const auto& m : collector->snapshot()) messages.push_back(m);
  for (const auto& m : messages) {
    if (!m.binary()) {
      if (!is_director(*m.bytes)) continue;
      proto::ControlMessage c;
      ASSERT_TRUE(proto::control_from_json(*m.bytes, c, error)) << error;
      pending.push_back(std::get<proto::DirectorCue>(c));
      sent.push_back(*m.bytes);
      continue;
    }
    ASSERT_TRUE(decoder.decode(*m.bytes, f, error)) << error;
    if (frames == 0) {
      ASSERT_FALSE(pending.empty()) << "the first frame has its shot";
      EXPECT_EQ(pending.front().shot, proto::Shot::Wide) << "the kick-off is wide";
    }
    for (const auto& cue : pending) {
      EXPECT_EQ(cue.seq, f.seq) << "a cue goes out just before its frame";
      EXPECT_EQ(cue.time, f.time);
      cuts += cue.cut;
      if (cue.shot == proto::Shot::Scorer) {
        scorer = true;
        EXPECT_EQ(f.score_right, 1) << "the first goal is HELIOS_B's";
        EXPECT_EQ(cue.subject_side, Side::Right);
      }
      if (cue.shot == proto::Shot::Replay) {
        replay = true;
        EXPECT_TRUE(scorer) << "the scorer first";
        ASSERT_EQ(cue.replay.size(), 2u);
        // The goal's frame is within the second segment, which ends 10 frames after it.
        const std::int64_t goal_seq = static_cast<std::int64_t>(cue.seq) + cue.replay[1].to - 10;
        EXPECT_GE(goal_seq, 0);
      }
    }
    pending.clear();
    ++frames;
  }
  EXPECT_TRUE(scorer);
  EXPECT_TRUE(replay);
  EXPECT_GE(cuts, 10);

  // The recording holds the same cues, before the same frames.
  record::RecordingReader reader;
  ASSERT_TRUE(reader.open(path, error)) << error;
  std::vector<std::string> recorded, controls;
  for (;;) {
    controls.clear();
    if (!reader.next(f, error, &controls)) break;
    for (const auto& text : controls)
      if (is_director(text)) recorded.push_back(text);
  }
  ASSERT_GE(recorded.size(), 10u);
  ASSERT_LE(recorded.size(), sent.size());
  for (std::size_t i = 0; i < recorded.size(); ++i) EXPECT_EQ(recorded[i], sent[i]) << "cue " << i;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mc::director
