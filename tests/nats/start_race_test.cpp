// Issue 18, "the broker crash": an origin and two edges started at the same
// moment, 30 times, each time on a fresh nats-server (its own port, its own
// JetStream folder, started as an operator would: -js -sd DIR). Before the
// fix, an edge's message-get could reach the keyframe stream while the
// origin was still creating it, and nats-server 2.9 died of a nil pointer
// in jsMsgGetRequest in about 1 start out of 6. Every start must leave the
// broker alive, and each edge must deliver frames to a spectator.
// One edge is given its game (it reads the snapshot as soon as it
// connects), the other carries every game (it reads it as soon as the
// first live message names the game): both ways of racing the origin.
// Skipped only when nats-server is not installed.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <thread>

#include "tests/nats/child_process.hpp"
#include "tests/nats/nats_processes.hpp"
#include "tests/nats/spectator.hpp"

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace mc::nats::testing;

namespace {

constexpr int kStarts = 30;
constexpr std::size_t kFrames = 5;  // per edge per start: enough to show frames flow

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct StartResult {
  bool broker_alive = true;
  bool frames[2] = {false, false};
  std::string panic;  // nats-server's panic line, if it died
};

// Waits (bounded) until `port` serves a spectator with `frames` frames;
// gives up at once when the broker died.
bool edge_delivers(std::uint16_t port, ChildProcess& broker, Clock::time_point deadline) {
  std::unique_ptr<Spectator> s;
  while (!s && Clock::now() < deadline && broker.running()) {
    try {
      s = std::make_unique<Spectator>(port);  // 404 until an edge carrying every game has seen it
    } catch (const std::exception&) {
      std::this_thread::sleep_for(50ms);
    }
  }
  while (s && s->frame_count() < kFrames && Clock::now() < deadline && broker.running())
    std::this_thread::sleep_for(20ms);
  return s && s->frame_count() >= kFrames && s->bad() == 0;
}

StartResult one_start(const std::string& nats_bin, const fs::path& dir) {
  StartResult r;
  const auto port = free_port();
  ChildProcess broker, origin, edge_a, edge_b;
  EXPECT_TRUE(broker.start({nats_bin, "-a", "127.0.0.1", "-p", std::to_string(port), "-js", "-sd",
                            (dir / "js").string()},
                           (dir / "nats-server.log").string()));
  EXPECT_TRUE(eventually([&] { return port_open(port); }, 10s)) << "nats-server did not listen";
  const std::string url = "nats://127.0.0.1:" + std::to_string(port);
  // The three at the same moment, none waiting for another.
  EXPECT_TRUE(origin.start(matchcast_argv(url, "", {"--role", "origin", "--rcg", "g=" + test_game_log()}),
                           (dir / "origin.log").string()));
  EXPECT_TRUE(edge_a.start(matchcast_argv(url, "", {"--role", "edge", "--edge-games", "g"}),
                           (dir / "edge-a.log").string()));
  EXPECT_TRUE(edge_b.start(matchcast_argv(url, "", {"--role", "edge"}), (dir / "edge-b.log").string()));
  const std::uint16_t ports[2] = {wait_for_port(edge_a, 30s), wait_for_port(edge_b, 30s)};
  const auto deadline = Clock::now() + 20s;
  for (int e = 0; e < 2; ++e) r.frames[e] = ports[e] != 0 && edge_delivers(ports[e], broker, deadline);
  r.broker_alive = broker.running();
  edge_a.stop();
  edge_b.stop();
  origin.stop();
  broker.stop();
  const std::string log = read_file(dir / "nats-server.log");
  if (const auto at = log.find("panic:"); at != std::string::npos) {
    r.broker_alive = false;
    r.panic = log.substr(at, log.find('\n', at) - at);
    if (const auto where = log.find("jetstream_api.go"); where != std::string::npos)
      r.panic += " at " + log.substr(where, log.find(' ', where) - where);
  }
  return r;
}

TEST(NatsStartRace, TheBrokerSurvivesAnOriginAndTwoEdgesStartedTogether) {
  const std::string nats_bin = find_nats_server();
  if (nats_bin.empty()) GTEST_SKIP() << "nats-server is not installed (Debian package nats-server)";
  const fs::path root = fs::temp_directory_path() / ("mc-nats-start-race-" + std::to_string(::getpid()));
  fs::remove_all(root);
  int deaths = 0, silent_edges = 0;
  const auto began = Clock::now();
  for (int i = 0; i < kStarts; ++i) {
    const fs::path dir = root / std::to_string(i);
    fs::create_directories(dir);
    const StartResult r = one_start(nats_bin, dir);
    const bool ok = r.broker_alive && r.frames[0] && r.frames[1];
    deaths += !r.broker_alive;
    silent_edges += !r.frames[0] + !r.frames[1];
    EXPECT_TRUE(r.broker_alive) << "start " << i << ": nats-server died: " << r.panic << " (logs in " << dir << ")";
    EXPECT_TRUE(r.frames[0]) << "start " << i << ": the edge given its game delivered no frames (logs in " << dir << ")";
    EXPECT_TRUE(r.frames[1]) << "start " << i << ": the edge carrying every game delivered no frames (logs in " << dir
                             << ")";
    if (ok) fs::remove_all(dir);
  }
  const auto seconds = std::chrono::duration<double>(Clock::now() - began).count();
  std::printf("%d starts in %.1f s: nats-server died %d times, %d edges delivered no frames\n", kStarts, seconds,
              deaths, silent_edges);
  if (!HasFailure()) fs::remove_all(root);
}

}  // namespace
