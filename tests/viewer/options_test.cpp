// Command line, relay addresses, and the PNG files screenshots are written in.
#include "viewer/options.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "viewer/ws_source.hpp"

namespace mc::viewer {
namespace {

std::optional<ViewerOptions> parse(std::vector<std::string> args, std::string& message, int& code) {
  args.insert(args.begin(), "matchcast-viewer");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return parse_options(static_cast<int>(argv.size()), argv.data(), message, code);
}

TEST(Options, ARelayAddressAndAScreenshot) {
  std::string message;
  int code = -1;
  auto o = parse({"ws://127.0.0.1:8080/ws", "--screenshot", "x.png", "--at", "120", "--camera", "top",
                  "--follow", "r9"},
                 message, code);
  ASSERT_TRUE(o) << message;
  EXPECT_FALSE(o->is_file);
  EXPECT_EQ(o->at, 120);
  EXPECT_EQ(o->camera, CameraMode::Top);
  EXPECT_EQ(o->screenshot, "x.png");
}

TEST(Options, ARecordingFileIsRecognised) {
  std::string message;
  int code = -1;
  auto o = parse({std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/recording_v1.mcrec"}, message, code);
  ASSERT_TRUE(o) << message;
  EXPECT_TRUE(o->is_file);
  o = parse({"missing.mcrec"}, message, code);
  ASSERT_TRUE(o) << message;
  EXPECT_TRUE(o->is_file);  // named like one: opening it will say what is wrong
}

TEST(Options, MistakesAreExplained) {
  std::string message;
  int code = -1;
  EXPECT_FALSE(parse({}, message, code));
  EXPECT_EQ(code, 1);
  EXPECT_NE(message.find("no SOURCE"), std::string::npos) << message;
  EXPECT_FALSE(parse({"ws://h:1/ws", "--screenshot", "x.png"}, message, code));
  EXPECT_NE(message.find("--at"), std::string::npos) << message;
  EXPECT_FALSE(parse({"ws://h:1/ws", "--camera", "drone"}, message, code));
  EXPECT_NE(message.find("drone"), std::string::npos) << message;
  EXPECT_FALSE(parse({"ws://h:1/ws", "--follow", "l12"}, message, code));
  EXPECT_FALSE(parse({"ws://h:1/ws", "--width", "abc"}, message, code));
  EXPECT_EQ(code, 1);
  EXPECT_FALSE(parse({"--help"}, message, code));
  EXPECT_EQ(code, 0);
  EXPECT_NE(message.find("--screenshot"), std::string::npos);
}

TEST(Options, RelayAddresses) {
  WsUrl u;
  std::string error;
  ASSERT_TRUE(parse_ws_url("ws://127.0.0.1:8080/ws?channel=b", u, error)) << error;
  EXPECT_EQ(u.host, "127.0.0.1");
  EXPECT_EQ(u.port, "8080");
  EXPECT_EQ(u.target, "/ws?channel=b");
  ASSERT_TRUE(parse_ws_url("http://example.org:9000/?recording=r1", u, error)) << error;
  EXPECT_EQ(u.target, "/ws?recording=r1");  // the page's address: its stream
  ASSERT_TRUE(parse_ws_url("localhost:8080", u, error)) << error;
  EXPECT_EQ(u.target, "/ws");
  ASSERT_TRUE(parse_ws_url("ws://relay", u, error)) << error;
  EXPECT_EQ(u.port, "80");
  EXPECT_FALSE(parse_ws_url("wss://relay/ws", u, error));
  EXPECT_NE(error.find("TLS"), std::string::npos);
  EXPECT_FALSE(parse_ws_url("ws://:80/ws", u, error));
  EXPECT_FALSE(parse_ws_url("ws://host:port/ws", u, error));
}

TEST(Options, PlayerNames) {
  Side side;
  int unum;
  ASSERT_TRUE(parse_player("l10", side, unum));
  EXPECT_EQ(side, Side::Left);
  EXPECT_EQ(unum, 10);
  ASSERT_TRUE(parse_player("R1", side, unum));
  EXPECT_EQ(side, Side::Right);
  EXPECT_FALSE(parse_player("x1", side, unum));
  EXPECT_FALSE(parse_player("l0", side, unum));
  EXPECT_FALSE(parse_player("l", side, unum));
}

}  // namespace
}  // namespace mc::viewer
