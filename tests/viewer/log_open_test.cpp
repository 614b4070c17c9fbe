// The viewer opens a game log by itself, headless under Xvfb: from its
// command line (the bundled game, --screenshot at a cycle), and dropped onto
// its window (a real XDND drag, tests/viewer/xdnd_drop.cpp, of a v3 binary
// log onto a viewer showing the bundled game). Each picture is kept in
// test-output/viewer/ (log-commandline.png, log-drop.png) and checked: the
// grass, the red and the blue kits are in it.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/viewer/test_processes.hpp"
#include "viewer/png.hpp"

namespace mc::viewer {
namespace {

namespace fs = std::filesystem;
using namespace e2e;

const std::string kV3 =
    std::string(MATCHCAST_TEST_RCG_DIR) + "/generated/gen19-v3-20261122025631-Alpha_0-vs-Beta_1.rcg.gz";

// Pixels like the broadcast kits (#d62828 red, #1d4ed8 blue, lit or shaded) and grass.
struct Colours {
  int red = 0, blue = 0, green = 0;
};
Colours count(const Image& img) {
  Colours c;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = &img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3];
      const int r = p[0], g = p[1], b = p[2];
      if (r > 110 && r > 2 * g && r > 2 * b) ++c.red;
      else if (b > 110 && b > g + 40 && b > 2 * r) ++c.blue;
      else if (g > 80 && g > r + 20 && g > b + 20) ++c.green;
    }
  return c;
}

TEST(LogOpen, FromTheCommandLine) {
  fs::create_directories(kOut);
  const std::string png = kOut + "/log-commandline.png", json = kOut + "/log-commandline.json";
  fs::remove(png);
  std::vector<std::string> args = xvfb("log-commandline");
  for (const std::string& a : {std::string(MATCHCAST_VIEWER), kLog, std::string("--screenshot"), png,
                               std::string("--at"), std::string("1200"), std::string("--camera"),
                               std::string("broadcast"), std::string("--width"), std::string("960"),
                               std::string("--height"), std::string("540"), std::string("--report"), json,
                               std::string("--timeout"), std::string("120")})
    args.push_back(a);
  const Child c = spawn(args, kOut + "/log-commandline.log", false, kOut);
  ASSERT_GT(c.pid, 0);
  ASSERT_EQ(wait_for(c.pid, 240), 0) << slurp(kOut + "/log-commandline.log");
  Image img;
  std::string error;
  ASSERT_TRUE(read_png(png, img, error)) << error;
  const auto report = nlohmann::json::parse(slurp(json));
  EXPECT_GE(report.at("time").get<int>(), 1200);
  const Colours k = count(img);
  std::printf("log-commandline: cycle %d, %d red, %d blue, %d grass pixels\n", report.at("time").get<int>(), k.red,
              k.blue, k.green);
  EXPECT_GT(k.green, img.width * img.height / 5);
  EXPECT_GT(k.red, 200);
  EXPECT_GT(k.blue, 200);
}

TEST(LogOpen, DroppedOntoTheWindow) {
  fs::create_directories(kOut);
  const std::string png = kOut + "/log-drop.png";
  fs::remove(png);
  // The viewer shows the bundled game; the drag of the v3 log comes 3 s later.
  const std::string script =
      "\"$1\" \"$2\" --width 960 --height 540 --quit-after 40 & v=$!; sleep 3; "
      "\"$3\" Matchcast \"$4\" --wait 8 --expect-title \"Matchcast: " + fs::path(kV3).filename().string() +
      "\" --shot \"$5\"; r=$?; kill $v 2>/dev/null; wait $v; exit $r";
  std::vector<std::string> args = xvfb("log-drop");
  for (const std::string& a : {std::string("/bin/sh"), std::string("-c"), script, std::string("sh"),
                               std::string(MATCHCAST_VIEWER), kLog, std::string(MATCHCAST_XDND_DROP), kV3, png})
    args.push_back(a);
  const Child c = spawn(args, kOut + "/log-drop.log", false, kOut);
  ASSERT_GT(c.pid, 0);
  const int code = wait_for(c.pid, 120);
  const std::string log = slurp(kOut + "/log-drop.log") + slurp(kOut + "/log-drop.log.out");
  ASSERT_EQ(code, 0) << log;
  EXPECT_NE(log.find("(dropped onto the window)"), std::string::npos) << log;
  Image img;
  std::string error;
  ASSERT_TRUE(read_png(png, img, error)) << error;
  const Colours k = count(img);
  std::printf("log-drop: %d red, %d blue, %d grass pixels\n", k.red, k.blue, k.green);
  EXPECT_GT(k.green, img.width * img.height / 5);
  EXPECT_GT(k.red + k.blue, 200);
}

}  // namespace
}  // namespace mc::viewer
