// matchcast-server's command line: the animation options per channel.
#include "server/app/server_options.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace mc::app {
namespace {

std::optional<ServerOptions> parse(std::vector<const char*> args, std::string& message) {
  args.insert(args.begin(), "matchcast-server");
  int exit_code = -1;
  return parse_server_options(static_cast<int>(args.size()), args.data(), message, exit_code);
}

TEST(ServerOptions, DetailIsFullByDefaultAndSetPerChannelOrForAll) {
  std::string message;
  auto o = parse({"--rcg", "a=x.rcg", "--rcg", "b=y.rcg"}, message);
  ASSERT_TRUE(o) << message;
  ASSERT_EQ(o->feeds.size(), 2u);
  EXPECT_EQ(o->feeds[0].feed.anim.detail, anim::DetailLevel::Full);
  EXPECT_EQ(o->feeds[0].feed.anim.lookahead_cycles, 2);

  o = parse({"--rcg", "a=x.rcg", "--rcg", "b=y.rcg", "--detail", "run", "--detail", "b=kick", "--lookahead", "3"},
            message);
  ASSERT_TRUE(o) << message;
  EXPECT_EQ(o->feeds[0].feed.anim.detail, anim::DetailLevel::Run);
  EXPECT_EQ(o->feeds[1].feed.anim.detail, anim::DetailLevel::Kick);
  EXPECT_EQ(o->feeds[1].feed.anim.lookahead_cycles, 3);
}

TEST(ServerOptions, BadDetailOrLookaheadIsAClearError) {
  std::string message;
  EXPECT_FALSE(parse({"--rcg", "a=x.rcg", "--detail", "most"}, message));
  EXPECT_NE(message.find("--detail must be none, run, kick or full"), std::string::npos) << message;
  EXPECT_FALSE(parse({"--rcg", "a=x.rcg", "--detail", "zz=run"}, message));
  EXPECT_NE(message.find("no channel"), std::string::npos) << message;
  EXPECT_FALSE(parse({"--rcg", "a=x.rcg", "--lookahead", "0"}, message));
  EXPECT_NE(message.find("--lookahead"), std::string::npos) << message;
  EXPECT_FALSE(parse({"--rcg", "a=x.rcg", "--lookahead", "9"}, message));
}

TEST(ServerOptions, RecordingsAreBoundedByDefaultAndByChoice) {
  std::string message;
  auto o = parse({"--rcg", "a=x.rcg"}, message);
  ASSERT_TRUE(o) << message;
  EXPECT_EQ(o->retention.max_bytes, 2ull << 30);
  EXPECT_EQ(o->retention.max_age, std::chrono::hours(24 * 30));
  o = parse({"--rcg", "a=x.rcg", "--record-max-bytes", "300M", "--record-max-age", "2d"}, message);
  ASSERT_TRUE(o) << message;
  EXPECT_EQ(o->retention.max_bytes, 300ull << 20);
  EXPECT_EQ(o->retention.max_age, std::chrono::hours(48));
  EXPECT_FALSE(parse({"--rcg", "a=x.rcg", "--record-max-bytes", "lots"}, message));
  EXPECT_NE(message.find("--record-max-bytes takes a size"), std::string::npos) << message;
  EXPECT_FALSE(parse({"--rcg", "a=x.rcg", "--record-max-age", "1y"}, message));
  EXPECT_NE(message.find("--record-max-age takes a duration"), std::string::npos) << message;
}

TEST(ServerOptions, AnimModeMocapLoadsTheCapturesOnceForTheChannelsThatAskForIt) {
  std::string message;
  const std::string dir = std::string(MATCHCAST_MOCAP_DIR) + "";
  const std::string cache = ::testing::TempDir() + "/matchcast-options-mocap-cache";
  auto o = parse({"--rcg", "a=x.rcg", "--rcg", "b=y.rcg", "--rcg", "c=z.rcg", "--anim-mode", "mocap", "--anim-mode",
                  "a=keyframe", "--mocap-dir", dir.c_str(), "--mocap-cache", cache.c_str()},
                 message);
  ASSERT_TRUE(o) << message;
  EXPECT_EQ(o->feeds[0].feed.anim.motion_source, nullptr);
  ASSERT_NE(o->feeds[1].feed.anim.motion_source, nullptr);
  EXPECT_EQ(o->feeds[1].feed.anim.motion_source, o->feeds[2].feed.anim.motion_source);  // one copy
}

TEST(ServerOptions, BadAnimModeOrMissingCapturesIsAClearError) {
  std::string message;
  EXPECT_FALSE(parse({"--rcg", "a=x.rcg", "--anim-mode", "ballet"}, message));
  EXPECT_NE(message.find("--anim-mode must be keyframe or mocap"), std::string::npos) << message;
  EXPECT_FALSE(parse({"--rcg", "a=x.rcg", "--anim-mode", "mocap", "--mocap-dir", "/nonexistent/mocap"}, message));
  EXPECT_NE(message.find("--anim-mode mocap"), std::string::npos) << message;
  EXPECT_NE(message.find("/nonexistent/mocap"), std::string::npos) << message;
}

}  // namespace
}  // namespace mc::app
