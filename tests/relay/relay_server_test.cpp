// The relay end to end on loopback: fan-out order, late join, a stalled
// client that never slows the others, inbound limits, static files over HTTP.
#include "server/relay/relay_server.hpp"

#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/http.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "tests/relay/ws_test_client.hpp"

namespace fs = std::filesystem;
namespace http = boost::beast::http;
using mc::relay::testing::WsTestClient;

namespace mc::relay {
namespace {

std::string frame_bytes(int seq, bool key, std::size_t size = 16) {
  std::string s = (key ? "K" : "D") + std::to_string(seq);
  s.resize(std::max(size, s.size()), '.');
  return s;
}

class RelayServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    web_ = fs::temp_directory_path() / ("mc-relay-web-" + std::to_string(::getpid()));
    fs::create_directories(web_);
    std::ofstream(web_ / "index.html") << "<!doctype html><title>matchcast</title>";
    std::ofstream(web_.parent_path() / ("mc-relay-secret-" + std::to_string(::getpid()))) << "s";
    config_.port = 0;
    config_.web_root = web_.string();
    config_.threads = 2;
    channel_ = std::make_shared<Channel>("live");
    channel_->set_hello(R"({"type":"hello"})");
  }
  void TearDown() override {
    if (server_) server_->stop();
    fs::remove_all(web_);
    fs::remove(web_.parent_path() / ("mc-relay-secret-" + std::to_string(::getpid())));
  }
  void start() {
    server_ = std::make_unique<RelayServer>(config_, channel_);
    std::string error;
    ASSERT_TRUE(server_->start(error)) << error;
    ASSERT_NE(server_->port(), 0);
  }
  void wait_for_subscribers(std::size_t n) {
    for (int i = 0; i < 500 && channel_->subscribers() < n; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_EQ(channel_->subscribers(), n);
  }
  http::response<http::string_body> get(const std::string& target) {
    boost::asio::io_context ioc;
    boost::asio::ip::tcp::socket s(ioc);
    s.connect({boost::asio::ip::make_address("127.0.0.1"), server_->port()});
    http::request<http::empty_body> req{http::verb::get, target, 11};
    req.set(http::field::host, "127.0.0.1");
    http::write(s, req);
    boost::beast::flat_buffer buf;
    http::response<http::string_body> res;
    http::read(s, buf, res);
    return res;
  }

  fs::path web_;
  RelayConfig config_;
  std::shared_ptr<Channel> channel_;
  std::unique_ptr<RelayServer> server_;
};

TEST_F(RelayServerTest, EveryClientGetsHelloThenEveryFrameInOrder) {
  start();
  constexpr int kClients = 40, kFrames = 60;
  std::vector<std::unique_ptr<WsTestClient>> clients;
  for (int i = 0; i < kClients; ++i) clients.push_back(std::make_unique<WsTestClient>(server_->port()));
  wait_for_subscribers(kClients);
  for (int f = 0; f < kFrames; ++f) channel_->publish_frame(frame_bytes(f, f % 20 == 0), f % 20 == 0);
  for (auto& c : clients) {
    auto hello = c->read();
    EXPECT_FALSE(hello.binary);
    EXPECT_EQ(hello.data, R"({"type":"hello"})");
    for (int f = 0; f < kFrames; ++f) {
      auto m = c->read();
      ASSERT_TRUE(m.binary);
      ASSERT_EQ(m.data, frame_bytes(f, f % 20 == 0)) << "frame " << f;
    }
  }
}

TEST_F(RelayServerTest, LateJoinerGetsHelloAndTheLatestKeyframeAtOnce) {
  start();
  for (int f = 0; f < 45; ++f) channel_->publish_frame(frame_bytes(f, f % 20 == 0), f % 20 == 0);
  WsTestClient late(server_->port());
  EXPECT_EQ(late.read().data, R"({"type":"hello"})");
  // Keyframe 40, then deltas 41..44: the current state, decodable at once.
  for (int f = 40; f < 45; ++f) EXPECT_EQ(late.read().data, frame_bytes(f, f == 40));
  wait_for_subscribers(1);
  channel_->publish_frame(frame_bytes(45, false), false);
  EXPECT_EQ(late.read().data, frame_bytes(45, false));
}

TEST_F(RelayServerTest, StalledClientNeverDelaysOthersAndIsClosed) {
  config_.max_queue_bytes = 64 * 1024;
  config_.stall_timeout = std::chrono::milliseconds(300);
  start();
  WsTestClient stalled(server_->port());  // never reads again
  WsTestClient healthy(server_->port());
  wait_for_subscribers(2);
  EXPECT_EQ(healthy.read().data, R"({"type":"hello"})");
  // 300 frames of 32 KiB = ~9.6 MB: far beyond socket buffers and the queue.
  constexpr int kFrames = 300;
  std::thread reader([&] {
    for (int f = 0; f < kFrames; ++f) {
      auto m = healthy.read();
      ASSERT_EQ(m.data.substr(0, 1 + std::to_string(f).size()), (f % 20 == 0 ? "K" : "D") + std::to_string(f));
    }
  });
  for (int f = 0; f < kFrames; ++f) {
    channel_->publish_frame(frame_bytes(f, f % 20 == 0, 32 * 1024), f % 20 == 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  reader.join();
  // The stalled one is dropped from the channel within a bounded time.
  for (int i = 0; i < 300 && channel_->subscribers() > 1; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(channel_->subscribers(), 1u);
  EXPECT_GE(server_->stats().closed_slow.load() + server_->stats().frames_dropped.load(), 1u);
}

TEST_F(RelayServerTest, OversizedInboundMessageEndsTheSession) {
  config_.max_inbound_message = 1024;
  start();
  WsTestClient c(server_->port());
  EXPECT_EQ(c.read().data, R"({"type":"hello"})");
  wait_for_subscribers(1);
  c.write_text(std::string(4096, 'x'));
  EXPECT_THROW(
      {
        for (int i = 0; i < 10; ++i) c.read();
      },
      boost::system::system_error);
  wait_for_subscribers(0);
}

TEST_F(RelayServerTest, MessageFloodIsClosedWithPolicyCode) {
  start();
  WsTestClient c(server_->port());
  EXPECT_EQ(c.read().data, R"({"type":"hello"})");
  try {
    for (int i = 0; i < 100; ++i) c.write_text("{}");
  } catch (const boost::system::system_error&) {
  }
  try {
    for (int i = 0; i < 10; ++i) c.read();
    FAIL() << "expected a close";
  } catch (const boost::system::system_error& e) {
    EXPECT_EQ(e.code(), boost::beast::websocket::error::closed);
    EXPECT_EQ(c.stream().reason().code, boost::beast::websocket::close_code::policy_error);
  }
}

TEST_F(RelayServerTest, ServesStaticFilesAndNothingOutsideWeb) {
  start();
  auto index = get("/");
  EXPECT_EQ(index.result(), http::status::ok);
  EXPECT_NE(index.body().find("matchcast"), std::string::npos);
  EXPECT_EQ(get("/healthz").result(), http::status::ok);
  const std::string secret = "mc-relay-secret-" + std::to_string(::getpid());
  for (const std::string& t : std::vector<std::string>{"/../" + secret, "/%2e%2e/" + secret, "/..%2F" + secret, "/missing"})
    EXPECT_EQ(get(t).result(), http::status::not_found) << t;
}

TEST_F(RelayServerTest, ClientLimitRefusesTheExtraConnection) {
  config_.max_clients = 2;
  start();
  WsTestClient a(server_->port()), b(server_->port());
  wait_for_subscribers(2);
  EXPECT_THROW(WsTestClient c(server_->port()), boost::system::system_error);
  EXPECT_EQ(server_->stats().refused_full.load(), 1u);
}

}  // namespace
}  // namespace mc::relay
