// matchcast-server's --reach-overlay: which channels get the reach model.
#include "server/app/server_options.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mc::app {
namespace {

std::optional<ServerOptions> parse(std::vector<std::string> args, std::string& message) {
  args.insert(args.begin(), "matchcast-server");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  int code = 0;
  return parse_server_options(static_cast<int>(argv.size()), argv.data(), message, code);
}

const std::string kMocap = std::string(MATCHCAST_MOCAP_DIR) + "";
const std::string kLog = std::string(MATCHCAST_SOURCE_DIR) + "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";

}  // namespace

TEST(ReachOptions, OnlyTheNamedChannelsGetTheModel) {
  std::string message;
  auto o = parse({"--rcg", "a=" + kLog, "--rcg", "b=" + kLog, "--reach-overlay", "b", "--mocap-dir", kMocap,
                  "--mocap-cache", MATCHCAST_MOCAP_CACHE},
                 message);
  ASSERT_TRUE(o) << message;
  ASSERT_EQ(o->feeds.size(), 2u);
  EXPECT_FALSE(o->feeds[0].feed.reach_model);
  EXPECT_TRUE(o->feeds[1].feed.reach_model);
  o = parse({"--rcg", kLog, "--reach-overlay", "all", "--mocap-dir", kMocap, "--mocap-cache", MATCHCAST_MOCAP_CACHE}, message);
  ASSERT_TRUE(o) << message;
  EXPECT_TRUE(o->feeds[0].feed.reach_model);
  o = parse({"--rcg", kLog}, message);
  ASSERT_TRUE(o) << message;
  EXPECT_FALSE(o->feeds[0].feed.reach_model);
}

TEST(ReachOptions, ErrorsAreClear) {
  std::string message;
  EXPECT_FALSE(parse({"--rcg", kLog, "--reach-overlay", "nosuch", "--mocap-dir", kMocap, "--mocap-cache", MATCHCAST_MOCAP_CACHE}, message));
  EXPECT_NE(message.find("names no channel"), std::string::npos) << message;
  EXPECT_FALSE(parse({"--rcg", kLog, "--reach-overlay", "all", "--mocap-dir", "/nonexistent"}, message));
  EXPECT_NE(message.find("--reach-overlay"), std::string::npos) << message;
}

}  // namespace mc::app
