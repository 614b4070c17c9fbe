// Issue 18, "a node lost mid-game", on a real 3-node NATS cluster on
// loopback: three nats-server processes run deploy/nats/nats-cluster.conf
// (its users and permissions included), the keyframe stream has 3
// replicas. The origin lists node 1 first, edge A node 2, edge B node 3
// (--nats-in-order), so each phase knows whom it hits. Spectators watch the
// origin (the reference: its frames never pass through NATS) and both edges.
//
// A. Node 2, edge A's, is killed (SIGKILL: the process dies, its sockets
//    close). Edge A moves to another node; its spectators see "feed lost",
//    then "back". Node 2 restarts.
// B. Node 1, the origin's, is killed. The origin moves to another node; its
//    recording has no gap longer than that outage. Node 1 restarts.
// C. Node 3, which both edges are on by now, hangs (SIGSTOP: a machine that
//    stops answering). The edges notice by their pings, move on, and a
//    spectator who joined during the outage gets the hello at once and a
//    fresh keyframe as soon as its edge is back. (The outage is shorter
//    than --origin-silence-ms, so "feed lost" comes with the link's loss,
//    right before "back": the frames' gap is the outage spectators saw.)
//
// Every edge spectator, all along: frames in order, each once; after a jump
// the next frame is a keyframe; each frame byte-equal to the origin's frame
// of the same number; never disconnected. The outage each one saw is
// printed. Skipped only when nats-server is not installed.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "server/record/recording_reader.hpp"
#include "tests/nats/child_process.hpp"
#include "tests/nats/nats_processes.hpp"
#include "tests/nats/spectator.hpp"

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace mc::nats::testing;

namespace {

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// What one spectator saw around one failure.
struct Seen {
  double frame_gap_s = 0;     // longest time without a frame
  bool lost = false, back = false;
  double lost_to_back_s = -1;  // "feed lost" to "feed back"
  Clock::time_point back_at{};
};

Seen seen(Spectator& s, Clock::time_point from, Clock::time_point to) {
  Seen out;
  const auto f = s.frames();
  for (std::size_t i = 1; i < f.size(); ++i)
    if (f[i].at >= from && f[i - 1].at <= to) out.frame_gap_s = std::max(out.frame_gap_s, seconds(f[i].at - f[i - 1].at));
  Clock::time_point lost_at{};
  for (const auto& t : s.texts()) {
    if (t.at < from || t.at > to) continue;
    if (!out.lost && t.data.find("\"status\":\"lost\"") != std::string::npos) {
      out.lost = true;
      lost_at = t.at;
    } else if (out.lost && !out.back && t.data.find("\"status\":\"back\"") != std::string::npos) {
      out.back = true;
      out.back_at = t.at;
      out.lost_to_back_s = seconds(t.at - lost_at);
    }
  }
  return out;
}

// When `s` first received a text holding `needle`, or nullopt.
std::optional<Clock::time_point> first_text(Spectator& s, const std::string& needle) {
  for (const auto& t : s.texts())
    if (t.data.find(needle) != std::string::npos) return t.at;
  return std::nullopt;
}

// No frame out of order or twice, no delta after a jump, and every frame
// the same bytes as the origin's frame of that number.
::testing::AssertionResult clean(const std::vector<Frame>& f, const std::map<std::uint32_t, std::string>& origin,
                                 std::size_t& compared) {
  if (f.empty()) return ::testing::AssertionFailure() << "no frames";
  if (!f.front().key) return ::testing::AssertionFailure() << "the first frame is a delta";
  compared = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (i > 0 && f[i].seq <= f[i - 1].seq)
      return ::testing::AssertionFailure() << "frame " << i << ": seq " << f[i].seq << " after " << f[i - 1].seq;
    if (i > 0 && f[i].seq != f[i - 1].seq + 1 && !f[i].key)
      return ::testing::AssertionFailure() << "frame " << i << ": a delta (seq " << f[i].seq << ") after a jump from "
                                           << f[i - 1].seq;
    const auto it = origin.find(f[i].seq);
    if (it == origin.end()) continue;
    if (it->second != f[i].bytes) return ::testing::AssertionFailure() << "frame seq " << f[i].seq << " differs";
    ++compared;
  }
  return ::testing::AssertionSuccess();
}

// Milliseconds of the day of a log line's "ts":"...THH:MM:SS.mmmZ".
long long log_ms(const std::string& line) {
  const auto t = line.find("\"ts\":\"");
  if (t == std::string::npos) return -1;
  const auto at = line.find('T', t + 6);
  if (at == std::string::npos || line.size() < at + 13) return -1;
  const int h = std::stoi(line.substr(at + 1, 2)), m = std::stoi(line.substr(at + 4, 2));
  const double s = std::stod(line.substr(at + 7, 6));
  return (h * 3600 + m * 60) * 1000LL + static_cast<long long>(s * 1000 + 0.5);
}

// The link outages in a matchcast-server log: nats_disconnected to the
// nats_connected after it, in seconds.
std::vector<double> link_outages(const fs::path& log) {
  std::vector<double> out;
  std::istringstream in(read_file(log));
  long long down = -1;
  for (std::string line; std::getline(in, line);) {
    if (line.find("\"event\":\"nats_disconnected\"") != std::string::npos) down = log_ms(line);
    if (line.find("\"event\":\"nats_connected\"") != std::string::npos && down >= 0) {
      out.push_back(static_cast<double>((log_ms(line) - down + 86400000LL) % 86400000LL) / 1000.0);
      down = -1;
    }
  }
  return out;
}

class NatsClusterFailover : public ::testing::Test {
 protected:
  struct Node {
    std::uint16_t client = 0, cluster = 0, monitor = 0;
    ChildProcess proc;
    bool up = false;
  };

  void SetUp() override {
    nats_bin_ = find_nats_server();
    if (nats_bin_.empty()) GTEST_SKIP() << "nats-server is not installed (Debian package nats-server)";
    dir_ = fs::temp_directory_path() / ("mc-nats-cluster-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (auto& n : nodes_) {
      n.client = free_port();
      n.cluster = free_port();
      n.monitor = free_port();
    }
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(start_node(i));
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(healthy(i, 60s)) << "node " << i + 1 << " did not join the cluster" << why(i);
  }
  void TearDown() override {
    for (auto* p : {&edge_a_, &edge_b_, &origin_}) p->stop();
    for (auto& n : nodes_) n.proc.stop(SIGKILL);
    if (HasFailure()) std::printf("logs kept in %s\n", dir_.c_str());
    else if (!dir_.empty()) fs::remove_all(dir_);
  }

  // Node i (0-based) with the deployment's configuration; its values from
  // the environment, as deploy/nats/nats-node.env gives them.
  bool start_node(int i) {
    Node& n = nodes_[i];
    std::vector<std::string> env = {"NATS_NAME=nats-" + std::to_string(i + 1), "NATS_HOST=127.0.0.1",
                                    "NATS_PORT=" + std::to_string(n.client),
                                    "NATS_MONITOR_PORT=" + std::to_string(n.monitor),
                                    "NATS_CLUSTER_PORT=" + std::to_string(n.cluster),
                                    "NATS_STORE=" + (dir_ / ("store-" + std::to_string(i + 1))).string(),
                                    "MATCHCAST_ORIGIN_PASSWORD=origin-secret", "MATCHCAST_EDGE_PASSWORD=edge-secret"};
    for (int r = 0; r < 3; ++r)
      env.push_back("NATS_ROUTE_" + std::to_string(r + 1) + "=nats-route://127.0.0.1:" +
                    std::to_string(nodes_[r].cluster));
    n.up = n.proc.start({nats_bin_, "-c", std::string(MATCHCAST_SOURCE_DIR) + "/deploy/nats/nats-cluster.conf"},
                        (dir_ / ("nats-" + std::to_string(i + 1) + ".log")).string(), env);
    return n.up;
  }
  // Routes to every other live node, and JetStream current (/healthz).
  bool healthy(int i, std::chrono::milliseconds timeout) {
    int live = 0;
    for (const auto& n : nodes_) live += n.up;
    return eventually(
        [&] {
          const auto routez = nlohmann::json::parse(http_get(nodes_[i].monitor, "/routez"), nullptr, false);
          return routez.is_object() && routez.value("num_routes", 0) >= live - 1 &&
                 http_get(nodes_[i].monitor, "/healthz").find("ok") != std::string::npos;
        },
        timeout);
  }
  // What a node that stays unhealthy says: alive or not, its monitor's
  // answers, the end of its log.
  std::string why(int i) {
    const std::string log = read_file(dir_ / ("nats-" + std::to_string(i + 1) + ".log"));
    return std::string("\n  process ") + (nodes_[i].proc.running() ? "running" : "gone") + ", ports client " +
           std::to_string(nodes_[i].client) + " cluster " + std::to_string(nodes_[i].cluster) + " monitor " +
           std::to_string(nodes_[i].monitor) + "\n  /healthz: " + http_get(nodes_[i].monitor, "/healthz") +
           "\n  log tail:\n" + log.substr(log.size() > 3000 ? log.size() - 3000 : 0);
  }
  // The node (0-based) a process's NATS connection is on, or -1.
  int node_of(const ChildProcess& p) {
    const std::string suffix = ", pid " + std::to_string(p.pid());
    for (int i = 0; i < 3; ++i) {
      if (!nodes_[i].up) continue;
      const auto connz = nlohmann::json::parse(http_get(nodes_[i].monitor, "/connz?limit=1024"), nullptr, false);
      if (!connz.is_object() || !connz.contains("connections")) continue;
      for (const auto& c : connz["connections"]) {
        const std::string name = c.value("name", "");
        if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
          return i;
      }
    }
    return -1;
  }
  // nats://USER:PASSWORD@... for the nodes in this order.
  std::string urls(const std::string& user, std::initializer_list<int> order) {
    std::string out;
    for (int i : order)
      out += (out.empty() ? "" : ",") + std::string("nats://") + user + ":" + user + "-secret@127.0.0.1:" +
             std::to_string(nodes_[i].client);
    return out;
  }
  std::uint16_t start_server(ChildProcess& p, const std::string& name, const std::string& url,
                             const std::string& record_dir, std::vector<std::string> extra) {
    extra.push_back("--nats-in-order");
    // The production reconnect pause (1 s), so the outages are the real ones.
    if (!p.start(matchcast_argv(url, record_dir, extra, 1000), (dir_ / (name + ".log")).string())) return 0;
    return wait_for_port(p, 30s);
  }
  std::unique_ptr<Spectator> watch(std::uint16_t port, std::size_t frames) {
    auto s = std::make_unique<Spectator>(port, "/ws?channel=g");
    EXPECT_TRUE(eventually([&] { return s->frame_count() >= frames; }, 20s)) << "no frames on port " << port;
    return s;
  }
  // Waits until every spectator in `list` has `frames` frames after `after`.
  bool all_flowing(const std::vector<Spectator*>& list, Clock::time_point after, std::size_t frames,
                   std::chrono::milliseconds timeout) {
    return eventually(
        [&] {
          for (auto* s : list) {
            const auto f = s->frames();
            std::size_t n = 0;
            for (const auto& x : f) n += x.at > after;
            if (n < frames) return false;
          }
          return true;
        },
        timeout);
  }
  std::map<std::uint32_t, std::string> origin_frames() {
    std::map<std::uint32_t, std::string> out;
    for (auto& f : at_origin_->frames()) out[f.seq] = f.bytes;
    return out;
  }
  void report(const char* phase, const char* who, const Seen& s) {
    std::printf("[outage] %s, %s: longest wait for a frame %.2f s", phase, who, s.frame_gap_s);
    if (s.lost) std::printf(", feed lost -> back %.2f s", s.lost_to_back_s);
    std::printf("\n");
  }

  std::string nats_bin_;
  fs::path dir_;
  Node nodes_[3];
  ChildProcess origin_, edge_a_, edge_b_;
  std::unique_ptr<Spectator> at_origin_;
};

TEST_F(NatsClusterFailover, EdgesAndTheOriginRideOutTheLossOfANode) {
  const auto began = Clock::now();
  const auto origin_port = start_server(origin_, "origin", urls("origin", {0, 1, 2}), (dir_ / "rec").string(),
                                        {"--role", "origin", "--rcg", "g=" + test_game_log(), "--nats-replicas", "3"});
  ASSERT_NE(origin_port, 0);
  const auto a_port = start_server(edge_a_, "edge-a", urls("edge", {1, 2, 0}), "", {"--role", "edge", "--edge-games", "g"});
  const auto b_port = start_server(edge_b_, "edge-b", urls("edge", {2, 0, 1}), "", {"--role", "edge", "--edge-games", "g"});
  ASSERT_NE(a_port, 0);
  ASSERT_NE(b_port, 0);
  at_origin_ = watch(origin_port, 10);
  auto a1 = watch(a_port, 20), b1 = watch(b_port, 20);
  ASSERT_EQ(node_of(origin_), 0);
  ASSERT_EQ(node_of(edge_a_), 1);
  ASSERT_EQ(node_of(edge_b_), 2);
  // The keyframe stream, at 3 replicas.
  const auto jsz = http_get(nodes_[0].monitor, "/jsz?accounts=true&streams=true&config=true");
  EXPECT_NE(jsz.find("\"num_replicas\": 3"), std::string::npos) << jsz.substr(0, 2000);
  std::this_thread::sleep_for(2s);

  // A. Edge A's node dies.
  const auto a_kill = Clock::now();
  nodes_[1].proc.stop(SIGKILL);
  nodes_[1].up = false;
  auto a_joiner = std::make_unique<Spectator>(a_port, "/ws?channel=g");  // probably during the outage
  EXPECT_TRUE(all_flowing({a1.get(), a_joiner.get()}, a_kill, 40, 30s)) << describe(*a1);
  const auto a_end = Clock::now();
  EXPECT_TRUE(eventually([&] { return node_of(edge_a_) == 2 || node_of(edge_a_) == 0; }, 10s));
  const Seen a_a1 = seen(*a1, a_kill, a_end), a_b1 = seen(*b1, a_kill, a_end);
  report("A: edge A's node killed", "edge A spectator", a_a1);
  report("A: edge A's node killed", "edge B spectator", a_b1);
  EXPECT_TRUE(a_a1.lost && a_a1.back) << "edge A's spectator sees feed lost, then back: " << describe(*a1);
  EXPECT_FALSE(a_b1.lost) << "nothing happened to edge B's feed";
  ASSERT_FALSE(a_joiner->texts().empty());
  EXPECT_NE(a_joiner->texts().front().data.find("\"type\":\"hello\""), std::string::npos);
  // A process crash closes the sockets: edge A is usually back before this
  // spectator is in (phase C has the long outage that a joiner can hit).
  std::printf("[outage] A: a spectator joining edge A %s its 'back'\n",
              first_text(*a_joiner, "\"status\":\"back\"") ? "before" : "after");
  ASSERT_TRUE(start_node(1));
  ASSERT_TRUE(healthy(1, 40s)) << "node 2 did not come back" << why(1);

  // B. The origin's node dies.
  std::this_thread::sleep_for(2s);
  const auto b_kill = Clock::now();
  nodes_[0].proc.stop(SIGKILL);
  nodes_[0].up = false;
  EXPECT_TRUE(all_flowing({a1.get(), b1.get()}, b_kill, 40, 30s));
  const auto b_end = Clock::now();
  EXPECT_TRUE(eventually([&] { return node_of(origin_) == 1; }, 10s)) << "the origin moved to node 2";
  const Seen b_a1 = seen(*a1, b_kill, b_end), b_b1 = seen(*b1, b_kill, b_end);
  report("B: the origin's node killed", "edge A spectator", b_a1);
  report("B: the origin's node killed", "edge B spectator", b_b1);
  ASSERT_TRUE(start_node(0));
  ASSERT_TRUE(healthy(0, 40s)) << "node 1 did not come back" << why(0);

  // C. Node 3 hangs; both edges are on it.
  std::this_thread::sleep_for(2s);
  ASSERT_EQ(node_of(edge_b_), 2);
  const int a_node_before_c = node_of(edge_a_);
  const auto c_stop = Clock::now();
  ::kill(nodes_[2].proc.pid(), SIGSTOP);
  nodes_[2].up = false;
  // A spectator arrives while edge B has no feed: its node hangs, and the
  // pings take 2 to 3 s to tell.
  std::this_thread::sleep_for(500ms);
  const auto joined = Clock::now();
  auto c_joiner = std::make_unique<Spectator>(b_port, "/ws?channel=g");
  EXPECT_TRUE(all_flowing({a1.get(), b1.get(), c_joiner.get()}, c_stop, 40, 40s)) << describe(*b1);
  const auto c_end = Clock::now();
  const Seen c_a1 = seen(*a1, c_stop, c_end), c_b1 = seen(*b1, c_stop, c_end);
  report("C: node 3 hangs", "edge A spectator", c_a1);
  report("C: node 3 hangs", "edge B spectator", c_b1);
  EXPECT_TRUE(c_b1.lost && c_b1.back) << describe(*b1);
  EXPECT_NE(node_of(edge_b_), 2);
  if (a_node_before_c == 2) {
    EXPECT_NE(node_of(edge_a_), 2);
  }
  // The joiner: the hello first, and a fresh keyframe once its edge is back.
  ASSERT_FALSE(c_joiner->texts().empty());
  EXPECT_NE(c_joiner->texts().front().data.find("\"type\":\"hello\""), std::string::npos);
  const auto joiner_back = first_text(*c_joiner, "\"status\":\"back\"");
  ASSERT_TRUE(joiner_back) << "the joiner was there for the 'back': " << describe(*c_joiner);
  double key_after_back = -1;
  for (const auto& f : c_joiner->frames())
    if (f.key && f.at >= *joiner_back) {
      key_after_back = seconds(f.at - *joiner_back);
      break;
    }
  std::printf("[outage] C: node 3 hangs, joiner on edge B: joined %.2f s after the hang, keyframe %.2f s after 'back'\n",
              seconds(joined - c_stop), key_after_back);
  EXPECT_GE(key_after_back, 0);
  EXPECT_LE(key_after_back, 1.5) << "a keyframe as soon as the edge is back";

  // All along: nothing out of order, doubled, baseless or altered.
  const auto reference = origin_frames();
  for (auto* s : {a1.get(), b1.get(), a_joiner.get(), c_joiner.get()}) {
    std::size_t compared = 0;
    EXPECT_TRUE(clean(s->frames(), reference, compared)) << describe(*s);
    EXPECT_GT(compared, 20u);
    EXPECT_FALSE(s->closed()) << "a spectator stayed connected";
    EXPECT_EQ(s->bad(), 0);
  }

  // Both edges resynced from the keyframe stream after their moves (a
  // snapshot found), and no node refused anything to the deployment's users.
  for (auto port : {a_port, b_port}) {
    const std::string m = http_get(port, "/metrics");
    EXPECT_GE(metric(m, "matchcast_edge_snapshot_fetches_total{result=\"found\"}"), 1) << m;
    EXPECT_GE(metric(m, "matchcast_edge_nats_reconnects_total"), 1) << m;
  }
  for (int i = 1; i <= 3; ++i) {
    const std::string log = read_file(dir_ / ("nats-" + std::to_string(i) + ".log"));
    const auto at = log.find("Violation");
    EXPECT_EQ(at, std::string::npos) << "nats-" << i << ": " << log.substr(at == std::string::npos ? 0 : at, 200);
  }

  // The links as the processes logged them.
  nodes_[2].proc.stop(SIGKILL);
  a1.reset();
  b1.reset();
  a_joiner.reset();
  c_joiner.reset();
  at_origin_.reset();
  for (auto* p : {&edge_a_, &edge_b_, &origin_}) p->stop();
  auto print = [](const char* who, const std::vector<double>& v) {
    std::printf("[outage] %s's NATS link down:", who);
    for (double d : v) std::printf(" %.2f s", d);
    std::printf("\n");
  };
  const auto origin_down = link_outages(dir_ / "origin.log");
  print("origin", origin_down);
  print("edge A", link_outages(dir_ / "edge-a.log"));
  print("edge B", link_outages(dir_ / "edge-b.log"));
  ASSERT_FALSE(origin_down.empty()) << "the origin reconnected after its node died";

  // The origin's recording: every frame, none late by more than the outage.
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir_ / "rec")) files.push_back(e.path());
  ASSERT_EQ(files.size(), 1u);
  mc::record::RecordingReader rec;
  std::string error;
  ASSERT_TRUE(rec.open(files.front().string(), error)) << error;
  mc::PoseFrame f;
  std::uint64_t frames = 0, seq_gaps = 0, longest_ms = 0, prev_ms = 0;
  std::uint32_t prev_seq = 0;
  while (rec.next(f, error)) {
    if (frames > 0) {
      seq_gaps += f.seq != prev_seq + 1;
      longest_ms = std::max(longest_ms, f.server_time_ms - prev_ms);
    }
    prev_seq = f.seq;
    prev_ms = f.server_time_ms;
    ++frames;
  }
  EXPECT_TRUE(error.empty()) << error;
  std::printf("[outage] origin's recording: %llu frames, %llu seq gaps, longest %.2f s between frames "
              "(origin link outage %.2f s)\n",
              static_cast<unsigned long long>(frames), static_cast<unsigned long long>(seq_gaps),
              static_cast<double>(longest_ms) / 1000.0, origin_down.front());
  // The recording is made before NATS: every frame is there. Its spacing
  // is the feed's (50 ms), plus what a loaded test machine adds.
  EXPECT_GT(frames, 200u);
  EXPECT_EQ(seq_gaps, 0u);
  EXPECT_LE(static_cast<double>(longest_ms) / 1000.0, std::max(origin_down.front(), 1.0));
  std::printf("cluster failover test: %.0f s\n", seconds(Clock::now() - began));
}

}  // namespace
