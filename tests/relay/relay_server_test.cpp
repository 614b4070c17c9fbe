// The relay end to end on loopback: fan-out order, late join, a stalled
// client that never slows the others, inbound limits, static files over HTTP.
#include "server/relay/relay_server.hpp"

#include "server/relay/http_session.hpp"

#include <gtest/gtest.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

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
    channels_ = std::make_shared<ChannelRegistry>();
    channel_ = channels_->open("live");
    channel_->set_hello(R"({"type":"hello"})");
  }
  void TearDown() override {
    if (server_) server_->stop();
    fs::remove_all(web_);
    fs::remove(web_.parent_path() / ("mc-relay-secret-" + std::to_string(::getpid())));
  }
  void start() {
    server_ = std::make_unique<RelayServer>(config_, channels_, control_);
    std::string error;
    ASSERT_TRUE(server_->start(error)) << error;
    ASSERT_NE(server_->port(), 0);
  }
  void wait_for_subscribers(std::size_t n) {
    for (int i = 0; i < 500 && channel_->subscribers() != n; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_EQ(channel_->subscribers(), n);
  }
  http::response<http::string_body> get(const std::string& target, http::verb verb = http::verb::get,
                                        const std::string& authorization = "") {
    boost::asio::io_context ioc;
    boost::asio::ip::tcp::socket s(ioc);
    s.connect({boost::asio::ip::make_address("127.0.0.1"), server_->port()});
    http::request<http::empty_body> req{verb, target, 11};
    req.set(http::field::host, "127.0.0.1");
    if (!authorization.empty()) req.set(http::field::authorization, authorization);
    http::write(s, req);
    boost::beast::flat_buffer buf;
    http::response<http::string_body> res;
    http::read(s, buf, res);
    return res;
  }

  fs::path web_;
  RelayConfig config_;
  std::shared_ptr<ChannelRegistry> channels_;
  std::shared_ptr<Channel> channel_;
  ControlHandler* control_ = nullptr;
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

TEST_F(RelayServerTest, LateJoinerGetsTheLatestTeamsAndScoreRightAfterTheHello) {
  start();
  const std::string teams0 = R"({"left":{"name":""},"right":{"name":""},"seq":0,"type":"teams"})";
  const std::string teams1 = R"({"left":{"name":"A"},"right":{"name":"B"},"seq":3,"type":"teams"})";
  const std::string score0 = R"({"left":0,"right":0,"seq":0,"time":0,"type":"score"})";
  // Named through an escape: still a score (the channel's quick look for a
  // kept type's name must not miss it).
  const std::string score1 = R"({"left":0,"right":1,"seq":22,"time":11,"type":"\u0073core"})";
  const std::string about_teams = R"({"type":"note","text":"teams"})";
  const std::string stamina = R"({"left":[],"right":[],"seq":20,"time":10,"type":"stamina"})";
  const std::string goal = R"({"score":[0,1],"seq":22,"time":11,"type":"goal"})";
  // Published in another order than a joiner gets them; events and stamina are not kept.
  channel_->publish_control(score0);
  channel_->publish_control(teams0);
  for (int f = 0; f < 45; ++f) {
    if (f == 3) channel_->publish_control(teams1);
    if (f == 4) channel_->publish_control(about_teams);
    if (f == 20) channel_->publish_control(stamina);
    if (f == 22) channel_->publish_control(goal), channel_->publish_control(score1);
    channel_->publish_frame(frame_bytes(f, f % 20 == 0), f % 20 == 0);
  }
  WsTestClient late(server_->port());
  EXPECT_EQ(late.read().data, R"({"type":"hello"})");
  auto m = late.read();
  EXPECT_FALSE(m.binary);
  EXPECT_EQ(m.data, teams1);
  m = late.read();
  EXPECT_FALSE(m.binary);
  EXPECT_EQ(m.data, score1);
  for (int f = 40; f < 45; ++f) EXPECT_EQ(late.read().data, frame_bytes(f, f == 40));

  // A new hello (another game) forgets the old game's metadata.
  channel_->set_hello(R"({"type":"hello","match_id":"next"})");
  WsTestClient next(server_->port());
  EXPECT_EQ(next.read().data, R"({"type":"hello","match_id":"next"})");
  wait_for_subscribers(2);
  channel_->publish_frame(frame_bytes(100, true), true);
  EXPECT_EQ(next.read().data, frame_bytes(100, true));
}

TEST_F(RelayServerTest, StalledClientNeverDelaysOthersAndIsClosed) {
  // Room for ~32 frames (~64 ms of this burst): a healthy reader
  // descheduled on a busy machine keeps up; the stalled one (9.6 MB behind)
  // cannot.
  config_.max_queue_bytes = 1024 * 1024;
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

TEST_F(RelayServerTest, QueuedFramesGoOutTogetherInOneGatheredWrite) {
  // Room for the whole burst: nothing is skipped, only batched.
  config_.max_queue_bytes = 32 * 1024 * 1024;
  config_.stall_timeout = std::chrono::seconds(60);
  start();
  WsTestClient c(server_->port());
  // A small receive buffer: otherwise loopback autotuning takes megabytes,
  // and on a loaded machine the writer can send frame after frame into it
  // while the publishing thread waits for a core.
  c.stream().next_layer().set_option(boost::asio::socket_base::receive_buffer_size(16 * 1024));
  EXPECT_EQ(c.read().data, R"({"type":"hello"})");
  wait_for_subscribers(1);
  // The client does not read while 12 MB are published: the kernel buffers
  // fill, one write stays in flight, and the rest queues behind it.
  constexpr int kFrames = 400;
  for (int f = 0; f < kFrames; ++f) channel_->publish_frame(frame_bytes(f, f % 20 == 0, 30000), f % 20 == 0);
  for (int f = 0; f < kFrames; ++f) {
    auto m = c.read();
    ASSERT_TRUE(m.binary);
    ASSERT_EQ(m.data, frame_bytes(f, f % 20 == 0, 30000)) << "frame " << f;
  }
  // The counters move once the kernel has taken a batch, which may be just
  // after the client read its last byte.
  for (int i = 0; i < 200 && server_->stats().messages_sent.load() < kFrames + 1u; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const auto writes = server_->stats().writes.load();
  const auto messages = server_->stats().messages_sent.load();
  EXPECT_EQ(messages, kFrames + 1u);
  // One write per batch: far fewer writes than messages.
  EXPECT_LT(writes * 4, messages) << writes << " writes for " << messages << " messages";
  // The socket filled: batches went out in part at once and in part later,
  // and every frame above still arrived byte for byte.
  EXPECT_GT(server_->stats().partial_writes.load(), 0u);
}

TEST_F(RelayServerTest, PreFramedMessagesOfEveryLengthClassDecode) {
  start();
  WsTestClient c(server_->port());
  EXPECT_EQ(c.read().data, R"({"type":"hello"})");
  wait_for_subscribers(1);
  // Around the 7-bit, 16-bit and 64-bit length encodings of RFC 6455.
  const std::vector<std::size_t> sizes{3, 125, 126, 127, 65535, 65536, 70000};
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    channel_->publish_frame(frame_bytes(static_cast<int>(i), true, sizes[i]), true);
    channel_->publish_control(std::string(sizes[i], 'j'));
  }
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    auto f = c.read();
    EXPECT_TRUE(f.binary);
    EXPECT_EQ(f.data, frame_bytes(static_cast<int>(i), true, sizes[i])) << sizes[i];
    auto t = c.read();
    EXPECT_FALSE(t.binary);
    EXPECT_EQ(t.data, std::string(sizes[i], 'j')) << sizes[i];
  }
}

TEST_F(RelayServerTest, PongsNeverInterleaveWithGatheredWrites) {
  config_.max_queue_bytes = 32 * 1024 * 1024;
  start();
  WsTestClient c(server_->port());
  EXPECT_EQ(c.read().data, R"({"type":"hello"})");
  wait_for_subscribers(1);
  constexpr int kFrames = 300;
  std::thread publisher([&] {
    for (int f = 0; f < kFrames; ++f) {
      channel_->publish_frame(frame_bytes(f, f % 20 == 0, 8000), f % 20 == 0);
      if (f % 10 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  // Pings between reads: the server's pongs (queued like frames) land between
  // its gathered writes of frames, never inside one, or the stream breaks.
  int pongs = 0;
  c.stream().control_callback([&](boost::beast::websocket::frame_type kind, boost::beast::string_view) {
    if (kind == boost::beast::websocket::frame_type::pong) ++pongs;
  });
  for (int f = 0; f < kFrames; ++f) {
    if (f % 3 == 0) c.stream().ping({});
    auto m = c.read();
    ASSERT_EQ(m.data, frame_bytes(f, f % 20 == 0, 8000)) << "frame " << f;
  }
  publisher.join();
  EXPECT_GT(pongs, 0);
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

TEST_F(RelayServerTest, ChannelsAreChosenByQueryAndListed) {
  auto second = channels_->open("second");
  second->set_hello(R"({"type":"hello","game":2})");
  start();
  WsTestClient a(server_->port(), "/ws?channel=second");
  EXPECT_EQ(a.read().data, R"({"type":"hello","game":2})");
  WsTestClient b(server_->port(), "/ws");
  EXPECT_EQ(b.read().data, R"({"type":"hello"})");
  EXPECT_THROW(WsTestClient c(server_->port(), "/ws?channel=nope"), boost::system::system_error);
  wait_for_subscribers(1);
  auto list = get("/channels");
  EXPECT_EQ(list.result(), http::status::ok);
  EXPECT_NE(list.body().find("\"name\":\"second\""), std::string::npos) << list.body();
  EXPECT_NE(list.body().find("\"name\":\"live\""), std::string::npos) << list.body();
}

TEST_F(RelayServerTest, MetricsExposeClientsFramesAndDelay) {
  start();
  WsTestClient c(server_->port());
  c.read();
  wait_for_subscribers(1);
  channel_->publish_frame(frame_bytes(0, true), true);
  c.read();
  // The write's completion is counted just after the client sees the bytes.
  for (int i = 0; i < 100 && server_->stats().delay_count.load() == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  auto m = get("/metrics");
  EXPECT_EQ(m.result(), http::status::ok);
  const std::string& body = m.body();
  EXPECT_NE(body.find("matchcast_clients 1\n"), std::string::npos) << body;
  EXPECT_NE(body.find("matchcast_channel_frames_total{channel=\"live\"} 1\n"), std::string::npos) << body;
  EXPECT_NE(body.find("matchcast_frame_delay_ms_count 1\n"), std::string::npos) << body;
  EXPECT_NE(body.find("# TYPE matchcast_frame_delay_ms histogram"), std::string::npos);
}

TEST_F(RelayServerTest, TheHeapIsTrimmedWithinSecondsOfConnectionsComingAndGoing) {
  start();
  const auto at_start = server_->stats().heap_trims.load();  // the trim at start, on glibc
  {
    WsTestClient c(server_->port());
    c.read();
    wait_for_subscribers(1);
  }
  // One trim a second while connections come and go: a steady churn must
  // not leave garbage in the heap for long (the soak's RSS check).
  for (int i = 0; i < 300 && server_->stats().heap_trims.load() == at_start; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
#if defined(__GLIBC__)
  EXPECT_GT(server_->stats().heap_trims.load(), at_start);
  const std::string body = get("/metrics").body();
  EXPECT_NE(body.find("\nmatchcast_heap_in_use_bytes "), std::string::npos) << body;
  EXPECT_NE(body.find("\nmatchcast_heap_free_bytes "), std::string::npos) << body;
  EXPECT_NE(body.find("\nmatchcast_heap_trims_total "), std::string::npos) << body;
#endif
  // With nothing coming or going, no more trims.
  std::this_thread::sleep_for(std::chrono::milliseconds(1200));
  const auto settled = server_->stats().heap_trims.load();
  std::this_thread::sleep_for(std::chrono::milliseconds(2200));
  EXPECT_EQ(server_->stats().heap_trims.load(), settled);
}

#if defined(__GLIBC__)
// After a relay started, a mid-sized block (a frame encoder's 128 KB partner
// table, say) is mapped on its own even after a larger one was freed. With
// glibc's moving threshold the large free raises the threshold, and the
// next such block comes from the heap, where its pages outlive it.
TEST_F(RelayServerTest, MidSizedBlocksAreMappedOnTheirOwnAfterALargeOneWasFreed) {
  start();
  auto* large = static_cast<char*>(std::malloc(4 << 20));
  large[0] = 1;
  std::free(large);  // glibc's default would now put blocks under 4 MB in the heap
  const auto mapped_before = ::mallinfo2().hblks;
  auto* mid = static_cast<char*>(std::malloc(100 * 1024));
  mid[0] = 1;
  EXPECT_EQ(::mallinfo2().hblks, mapped_before + 1) << "a 100 KB block came from the heap";
  std::free(mid);
  EXPECT_EQ(::mallinfo2().hblks, mapped_before);
}
#endif

TEST_F(RelayServerTest, PerAddressLimitRefusesTheExtraConnection) {
  config_.max_connections_per_ip = 2;
  start();
  WsTestClient a(server_->port()), b(server_->port());
  wait_for_subscribers(2);
  EXPECT_THROW(WsTestClient c(server_->port()), boost::system::system_error);
  EXPECT_EQ(server_->stats().refused_per_ip.load(), 1u);
  // A slot frees when a spectator leaves.
  a.stream().close(boost::beast::websocket::close_code::normal);
  wait_for_subscribers(1);
  for (int i = 0; i < 100 && server_->stats().clients.load() > 1; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_NO_THROW(WsTestClient d(server_->port()));
}

TEST_F(RelayServerTest, OriginAllowListRefusesOtherOrigins) {
  config_.allowed_origins = {"https://good.example"};
  start();
  auto with_origin = [&](const std::string& origin) {
    boost::asio::io_context ioc;
    boost::beast::websocket::stream<boost::asio::ip::tcp::socket> ws(ioc);
    ws.next_layer().connect({boost::asio::ip::make_address("127.0.0.1"), server_->port()});
    ws.set_option(boost::beast::websocket::stream_base::decorator(
        [origin](boost::beast::websocket::request_type& r) { r.set(http::field::origin, origin); }));
    ws.handshake("127.0.0.1", "/ws");
  };
  EXPECT_NO_THROW(with_origin("https://good.example"));
  EXPECT_THROW(with_origin("https://evil.example"), boost::system::system_error);
  EXPECT_EQ(server_->stats().refused_origin.load(), 1u);
}

TEST_F(RelayServerTest, ShutdownSendsEverySpectatorACloseFrame) {
  start();
  WsTestClient a(server_->port()), b(server_->port());
  a.read();
  b.read();
  wait_for_subscribers(2);
  // Spectators keep reading while the server stops, as browsers do.
  std::vector<std::uint16_t> codes(2, 0);
  std::vector<std::thread> readers;
  int i = 0;
  for (auto* c : {&a, &b}) {
    readers.emplace_back([c, &code = codes[i++]] {
      try {
        for (int n = 0; n < 100; ++n) c->read();
      } catch (const boost::system::system_error& e) {
        if (e.code() == boost::beast::websocket::error::closed) code = c->stream().reason().code;
      }
    });
  }
  const auto t0 = std::chrono::steady_clock::now();
  server_->stop();
  for (auto& t : readers) t.join();
  for (auto code : codes) EXPECT_EQ(code, static_cast<std::uint16_t>(boost::beast::websocket::close_code::going_away));
  // Everyone answered the close: the stop did not need its whole grace time.
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(1900));
}

struct RecordingControl : ControlHandler {
  std::vector<std::string> calls;
  bool control(const std::string& action, const std::string& channel, std::string& message) override {
    calls.push_back(action + "@" + channel);
    message = "done";
    return true;
  }
};

TEST_F(RelayServerTest, ControlNeedsTheTokenAndPost) {
  RecordingControl handler;
  control_ = &handler;
  config_.control_token = "s3cret";
  start();
  EXPECT_EQ(get("/control/feed/stop?channel=live", http::verb::post).result(), http::status::unauthorized);
  EXPECT_EQ(get("/control/feed/stop?channel=live", http::verb::post, "Bearer wrong!").result(),
            http::status::unauthorized);
  EXPECT_EQ(get("/control/feed/stop?channel=live", http::verb::get, "Bearer s3cret").result(),
            http::status::method_not_allowed);
  EXPECT_TRUE(handler.calls.empty());
  EXPECT_EQ(get("/control/feed/stop?channel=live", http::verb::post, "Bearer s3cret").result(), http::status::ok);
  ASSERT_EQ(handler.calls.size(), 1u);
  EXPECT_EQ(handler.calls[0], "feed/stop@live");
}

TEST_F(RelayServerTest, ControlIsDisabledWithoutAToken) {
  RecordingControl handler;
  control_ = &handler;
  start();
  EXPECT_EQ(get("/control/feed/stop?channel=live", http::verb::post, "Bearer ").result(), http::status::forbidden);
  EXPECT_TRUE(handler.calls.empty());
}

TEST(QueryParam, FindsDecodesAndMisses) {
  EXPECT_EQ(query_param("/ws?channel=a%20b&x=1", "channel"), "a b");
  EXPECT_EQ(query_param("/ws?x=1&channel=c", "channel"), "c");
  EXPECT_EQ(query_param("/ws?channelx=1", "channel"), "");
  EXPECT_EQ(query_param("/ws", "channel"), "");
  EXPECT_EQ(query_param("/ws?channel", "channel"), "");
  EXPECT_EQ(query_param("/ws?channel=%zz", "channel"), "");
}

}  // namespace
}  // namespace mc::relay
