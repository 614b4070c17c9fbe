// Connection abuse on loopback: 1,000 sockets that send one header byte a
// second (slowloris) and a flood of upgrades from one address must not stop
// live spectators from getting every frame. Slow sockets are closed by the
// header timeout; the per-address cap holds from the moment a connection is
// accepted, and spectators from another address (127.0.0.2) are unaffected.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <chrono>
#include <filesystem>
#include <thread>

#include "server/relay/relay_server.hpp"
#include "tests/relay/ws_test_client.hpp"

namespace fs = std::filesystem;
using mc::relay::testing::WsTestClient;
using Clock = std::chrono::steady_clock;

namespace mc::relay {
namespace {

// A raw TCP connection from `source` to 127.0.0.1:`port`, non-blocking
// once connected; -1 when it cannot be made.
int raw_connect(const char* source, std::uint16_t port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_in local{};
  local.sin_family = AF_INET;
  ::inet_pton(AF_INET, source, &local.sin_addr);
  sockaddr_in remote{};
  remote.sin_family = AF_INET;
  remote.sin_port = htons(port);
  ::inet_pton(AF_INET, "127.0.0.1", &remote.sin_addr);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local) != 0 ||
      ::connect(fd, reinterpret_cast<sockaddr*>(&remote), sizeof remote) != 0) {
    ::close(fd);
    return -1;
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  return fd;
}

// True when the server has closed `fd` (EOF or reset); reads and drops
// whatever it sent before (a 429 answer).
bool closed_by_server(int fd, std::string* seen = nullptr) {
  char buf[512];
  for (;;) {
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n > 0) {
      if (seen) seen->append(buf, static_cast<std::size_t>(n));
      continue;
    }
    if (n == 0) return true;
    return errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR;
  }
}

// A spectator on its own thread, counting frames and noting gaps and the
// longest pause between two frames.
class Watcher {
 public:
  Watcher(std::uint16_t port, const std::string& source) : client_(port, "/ws", source) {
    thread_ = std::thread([this] { run(); });
  }
  ~Watcher() {
    stop_ = true;
    thread_.join();
  }
  int frames() const { return frames_; }
  int gaps() const { return gaps_; }
  double longest_pause_ms() const { return longest_pause_ms_; }
  bool failed() const { return failed_; }

 private:
  void run() {
    int last = -1;
    auto last_at = Clock::now();
    while (!stop_) {
      testing::Received m;
      try {
        m = client_.read(std::chrono::seconds(2));
      } catch (const std::exception&) {
        failed_ = true;
        return;
      }
      if (!m.binary) continue;
      const int seq = std::stoi(m.data.substr(1));
      const auto now = Clock::now();
      if (last >= 0) {
        if (seq != last + 1) ++gaps_;
        longest_pause_ms_ = std::max(longest_pause_ms_.load(), std::chrono::duration<double, std::milli>(now - last_at).count());
      }
      last = seq;
      last_at = now;
      ++frames_;
    }
  }
  WsTestClient client_;
  std::thread thread_;
  std::atomic<bool> stop_{false}, failed_{false};
  std::atomic<int> frames_{0}, gaps_{0};
  std::atomic<double> longest_pause_ms_{0};
};

class ConnectionAbuseTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // 1,000 sockets here and 1,000 in the relay: more than a default 1,024.
    rlimit r{};
    ::getrlimit(RLIMIT_NOFILE, &r);
    r.rlim_cur = std::max<rlim_t>(r.rlim_cur, std::min<rlim_t>(r.rlim_max, 8192));
    ::setrlimit(RLIMIT_NOFILE, &r);
    web_ = fs::temp_directory_path() / ("mc-abuse-web-" + std::to_string(::getpid()));
    fs::create_directories(web_);
    config_.port = 0;
    config_.web_root = web_.string();
    config_.threads = 2;
    config_.header_timeout = std::chrono::milliseconds(2000);
    channels_ = std::make_shared<ChannelRegistry>();
    channel_ = channels_->open("live");
    channel_->set_hello(R"({"type":"hello"})");
  }
  void TearDown() override {
    stop_feed();
    for (int fd : sockets_) ::close(fd);
    if (server_) server_->stop();
    fs::remove_all(web_);
  }
  void start() {
    server_ = std::make_unique<RelayServer>(config_, channels_);
    std::string error;
    ASSERT_TRUE(server_->start(error)) << error;
    // Frames at 20 Hz, as a feed would publish them.
    feed_ = std::thread([this] {
      for (int seq = 0; !feed_stop_; ++seq) {
        const bool key = seq % 20 == 0;
        std::string bytes = (key ? "K" : "D") + std::to_string(seq);
        bytes.resize(400, '.');
        channel_->publish_frame(std::move(bytes), key);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    });
  }
  void stop_feed() {
    feed_stop_ = true;
    if (feed_.joinable()) feed_.join();
  }
  // `n` sockets from `source` that send one byte of a request line a second
  // for `seconds`; returns how many the server closed and when the last went.
  struct SlowResult {
    int refused_at_once = 0;  // closed before they sent their second byte
    int closed = 0;           // closed by the end
    double last_closed_s = 0;
  };
  SlowResult slowloris(const char* source, int n, double seconds) {
    SlowResult r;
    const std::string line = "GET /index.html HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: ";
    const auto start = Clock::now();
    for (int i = 0; i < n; ++i) {
      const int fd = raw_connect(source, server_->port());
      EXPECT_GE(fd, 0) << "connect " << i << ": " << std::strerror(errno);
      if (fd >= 0) sockets_.push_back(fd);
    }
    std::vector<bool> closed(sockets_.size(), false);
    for (int second = 0; Clock::now() - start < std::chrono::duration<double>(seconds); ++second) {
      for (std::size_t i = 0; i < sockets_.size(); ++i) {
        if (closed[i]) continue;
        if (closed_by_server(sockets_[i]) ||
            ::send(sockets_[i], &line[static_cast<std::size_t>(second) % line.size()], 1, MSG_NOSIGNAL) < 0) {
          closed[i] = true;
          ++r.closed;
          if (second <= 1) ++r.refused_at_once;
          r.last_closed_s = std::chrono::duration<double>(Clock::now() - start).count();
        }
      }
      std::this_thread::sleep_until(start + std::chrono::seconds(second + 1));
    }
    return r;
  }

  fs::path web_;
  RelayConfig config_;
  std::shared_ptr<ChannelRegistry> channels_;
  std::shared_ptr<Channel> channel_;
  std::unique_ptr<RelayServer> server_;
  std::thread feed_;
  std::atomic<bool> feed_stop_{false};
  std::vector<int> sockets_;
};

TEST_F(ConnectionAbuseTest, AThousandSlowHeaderSocketsAreClosedByTheTimeoutAndSpectatorsGetEveryFrame) {
  config_.max_connections_per_ip = 0;  // no cap: every slow socket gets in
  start();
  Watcher a(server_->port(), "127.0.0.1"), b(server_->port(), "127.0.0.2");
  const auto r = slowloris("127.0.0.1", 1000, 4.5);
  EXPECT_EQ(r.closed, 1000) << "slow sockets still open after 4.5 s with a 2 s header timeout";
  EXPECT_EQ(r.refused_at_once, 0);
  EXPECT_LE(r.last_closed_s, 4.0);
  for (const Watcher* w : {&a, &b}) {
    EXPECT_FALSE(w->failed());
    EXPECT_EQ(w->gaps(), 0);
    EXPECT_GE(w->frames(), 60) << "4.5 s at 20 Hz";
    EXPECT_LT(w->longest_pause_ms(), 1000);
  }
}

TEST_F(ConnectionAbuseTest, TheCapHoldsAgainstSlowHeadersFromOneAddress) {
  config_.max_connections_per_ip = 64;
  start();
  Watcher other(server_->port(), "127.0.0.2");
  const auto r = slowloris("127.0.0.1", 1000, 3.5);
  // 64 held until the timeout, the rest refused at once.
  EXPECT_EQ(r.refused_at_once, 1000 - 64);
  EXPECT_EQ(r.closed, 1000);
  EXPECT_GE(server_->stats().refused_per_ip.load(), 936u);
  EXPECT_FALSE(other.failed());
  EXPECT_EQ(other.gaps(), 0);
  EXPECT_GE(other.frames(), 50);
  EXPECT_LT(other.longest_pause_ms(), 1000);
  // Once they are gone, the address may connect again.
  for (int fd : sockets_) ::close(fd);
  sockets_.clear();
  EXPECT_NO_THROW(WsTestClient again(server_->port(), "/ws", "127.0.0.1"));
}

TEST_F(ConnectionAbuseTest, AnUpgradeFloodFromOneAddressIsRefusedAndOthersAreUnaffected) {
  config_.max_connections_per_ip = 64;
  start();
  Watcher w1(server_->port(), "127.0.0.2"), w2(server_->port(), "127.0.0.2");
  // 500 complete upgrade requests at once from 127.0.0.1, held open.
  const std::string upgrade =
      "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
      "Sec-WebSocket-Version: 13\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n";
  for (int i = 0; i < 500; ++i) {
    const int fd = raw_connect("127.0.0.1", server_->port());
    ASSERT_GE(fd, 0);
    sockets_.push_back(fd);
    EXPECT_EQ(::send(fd, upgrade.data(), upgrade.size(), MSG_NOSIGNAL), static_cast<ssize_t>(upgrade.size()));
  }
  // Each gets its answer: 101 for the first 64, 429 or a closed socket for the rest.
  std::vector<std::string> answers(sockets_.size());
  std::vector<bool> closed(sockets_.size(), false);
  const auto deadline = Clock::now() + std::chrono::seconds(5);
  int upgraded = 0, refused = 0;
  while (Clock::now() < deadline && upgraded + refused < 500) {
    upgraded = refused = 0;
    for (std::size_t i = 0; i < sockets_.size(); ++i) {
      if (!closed[i]) closed[i] = closed_by_server(sockets_[i], &answers[i]);
      if (answers[i].rfind("HTTP/1.1 101", 0) == 0) ++upgraded;
      else if (closed[i]) ++refused;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(upgraded, 64);
  EXPECT_EQ(refused, 500 - 64);
  int told = 0;
  for (const auto& a : answers) told += a.rfind("HTTP/1.1 429", 0) == 0 ? 1 : 0;
  EXPECT_GT(told, 0) << "no refused client got the 429 answer";
  // Another address still joins during the flood, and nobody there missed a frame.
  EXPECT_NO_THROW(WsTestClient late(server_->port(), "/ws", "127.0.0.2"));
  std::this_thread::sleep_for(std::chrono::seconds(1));
  for (const Watcher* w : {&w1, &w2}) {
    EXPECT_FALSE(w->failed());
    EXPECT_EQ(w->gaps(), 0);
    EXPECT_LT(w->longest_pause_ms(), 1000);
  }
}

// Out of file descriptors: accepting fails while the queue is full. The
// relay logs it and tries again 50 ms later; retrying at once would spin a
// core on the same error for as long as it lasts. When descriptors are
// free again it accepts, and a spectator gets frames.
TEST_F(ConnectionAbuseTest, OutOfDescriptorsTheRelayBacksOffAndThenAcceptsAgain) {
  config_.max_connections_per_ip = 0;  // no cap: the descriptors run out first
  start();
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_NOFILE, &old), 0);
  std::size_t open_now = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator("/proc/self/fd")) ++open_now;
  rlimit low = old;
  low.rlim_cur = open_now + 60;
  ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &low), 0);
  // Connections until this process (test and relay share it) has no
  // descriptor left: the last ones wait in the relay's listen queue.
  for (int i = 0; i < 200; ++i) {
    const int fd = raw_connect("127.0.0.3", server_->port());
    if (fd < 0) break;
    sockets_.push_back(fd);
  }
  ASSERT_LT(sockets_.size(), 200u) << "the descriptors never ran out";
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto cpu_seconds = [] {
    rusage u{};
    ::getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
  };
  const double before = cpu_seconds();
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const double used = cpu_seconds() - before;
  std::printf("out of descriptors for 1 s with %zu connections: %.3f s of CPU\n", sockets_.size(), used);
  EXPECT_LT(used, 0.3) << "the relay spins on the failing accept";
  for (int fd : sockets_) ::close(fd);
  sockets_.clear();
  ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &old), 0);
  Watcher w(server_->port(), "127.0.0.4");
  const auto deadline = Clock::now() + std::chrono::seconds(5);
  while (w.frames() < 20 && !w.failed() && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(w.failed());
  EXPECT_GE(w.frames(), 20) << "no frames after the descriptors came back";
}

}  // namespace
}  // namespace mc::relay
