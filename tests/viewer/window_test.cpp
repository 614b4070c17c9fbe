// The viewer's window loop (not --screenshot) under Xvfb against a live
// server: it runs, draws, and closes cleanly; with a simulated very slow
// GPU it skips to the newest keyframe instead of falling behind live.
#include <gtest/gtest.h>

#include <cstdio>
#include <regex>

#include "tests/viewer/test_processes.hpp"

namespace mc::viewer {
namespace {

using namespace e2e;

struct Figures {
  long drawn = 0;
  long skips = 0;
  double lag_end = 1e9;
};

// Runs the window for `seconds` and reads the figures line it prints.
Figures run_window(std::uint16_t port, double seconds, int slow_ms, const std::string& name) {
  const std::string log = kOut + "/" + name + ".log";
  std::vector<std::string> args = xvfb(name);
  for (const std::string& a : {std::string(MATCHCAST_VIEWER), "ws://127.0.0.1:" + std::to_string(port) + "/ws",
                               std::string("--width"), std::string("640"), std::string("--height"),
                               std::string("360"), std::string("--quit-after"), std::to_string(seconds),
                               std::string("--simulate-slow-ms"), std::to_string(slow_ms)})
    args.push_back(a);
  const Child c = spawn(args, log, false, kOut);
  EXPECT_GT(c.pid, 0);
  EXPECT_EQ(wait_for(c.pid, seconds + 60), 0) << slurp(log);
  const std::string out = slurp(log + ".out");
  std::printf("%s: %s", name.c_str(), out.c_str());
  std::smatch m;
  Figures f;
  const std::regex re(R"(drew (\d+) frames.*keyframe: (\d+);.*at the end ([0-9.]+))");
  EXPECT_TRUE(std::regex_search(out, m, re)) << out << slurp(log);
  if (m.size() == 4) {
    f.drawn = std::stol(m[1]);
    f.skips = std::stol(m[2]);
    f.lag_end = std::stod(m[3]);
  }
  return f;
}

TEST(Window, DrawsTheLiveStreamAndClosesCleanly) {
  Server server("", "1");
  ASSERT_GT(server.port(), 0) << slurp(kOut + "/server.log");
  const Figures f = run_window(server.port(), 4, 0, "window-live");
  EXPECT_GE(f.drawn, 10);
  EXPECT_LE(f.lag_end, 12.0);  // close behind the newest frame
}

TEST(Window, AVerySlowGpuSkipsToTheNewestKeyframeInsteadOfFallingBehind) {
  Server server("", "1");
  ASSERT_GT(server.port(), 0) << slurp(kOut + "/server.log");
  // 1.5 s per frame: the stream brings 30 frames while the viewer can
  // advance at most 20 (a 0.5 s step at double speed).
  const Figures f = run_window(server.port(), 9, 1500, "window-slow-gpu");
  EXPECT_GE(f.drawn, 3);
  EXPECT_GE(f.skips, 1);
  EXPECT_LE(f.lag_end, 40.0 + 30.0);  // never more than the allowed lag plus one slow frame
}

}  // namespace
}  // namespace mc::viewer
