// The live relay as a source, against small local servers: a refused port,
// a server that hangs up, and a relay that sends the golden stream with a
// corrupt frame in it. Every failure is a status line and a retry.
#include "viewer/ws_source.hpp"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

namespace mc::viewer {
namespace {

namespace asio = boost::asio;
namespace websocket = boost::beast::websocket;
using tcp = asio::ip::tcp;

template <class F>
bool eventually(F done, double seconds = 10) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return done();
}

WsUrl local(unsigned short port) {
  WsUrl u;
  u.host = "127.0.0.1";
  u.port = std::to_string(port);
  return u;
}

std::string unhex(const std::string& hex) {
  std::string out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2) out.push_back(static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  return out;
}

TEST(WsSource, ARefusedConnectionIsShownAndRetried) {
  unsigned short port;
  {
    asio::io_context ioc;
    tcp::acceptor a(ioc, {asio::ip::make_address("127.0.0.1"), 0});
    port = a.local_endpoint().port();
  }  // closed: nothing listens there now
  FrameBuffer buffer;
  WsSource source(local(port), buffer, RetryPolicy{0.05, 0.1});
  source.start();
  ASSERT_TRUE(eventually([&] { return source.attempts() >= 3; }));
  const std::string status = buffer.meta().status;
  EXPECT_NE(status.find("cannot connect to ws://127.0.0.1:" + std::to_string(port)), std::string::npos) << status;
  EXPECT_NE(status.find("refused"), std::string::npos) << status;
  EXPECT_NE(status.find("retrying"), std::string::npos) << status;
  EXPECT_FALSE(buffer.meta().connected);
  const auto t0 = std::chrono::steady_clock::now();
  source.stop();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(2));
}

TEST(WsSource, AServerThatHangsUpIsRetried) {
  asio::io_context ioc;
  tcp::acceptor acceptor(ioc, {asio::ip::make_address("127.0.0.1"), 0});
  std::atomic<bool> stop{false};
  std::thread server([&] {
    acceptor.non_blocking(true);
    while (!stop) {
      boost::system::error_code ec;
      tcp::socket s = acceptor.accept(ec);
      if (!ec) s.close();  // hang up before the WebSocket handshake
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  FrameBuffer buffer;
  WsSource source(local(acceptor.local_endpoint().port()), buffer, RetryPolicy{0.05, 0.1});
  source.start();
  ASSERT_TRUE(eventually([&] { return source.attempts() >= 3; }));
  const std::string status = buffer.meta().status;
  EXPECT_NE(status.find("handshake"), std::string::npos) << status;
  EXPECT_NE(status.find("retrying"), std::string::npos) << status;
  source.stop();
  stop = true;
  server.join();
}

TEST(WsSource, DecodesTheStreamSkipsACorruptFrameAndSurvivesTheDrop) {
  std::ifstream in(std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/frames_v1.json");
  const auto golden = nlohmann::json::parse(in);
  auto hello = golden["hello"];
  hello["type"] = "hello";

  asio::io_context ioc;
  tcp::acceptor acceptor(ioc, {asio::ip::make_address("127.0.0.1"), 0});
  std::thread server([&] {
    websocket::stream<tcp::socket> ws(acceptor.accept());
    ws.accept();
    ws.text(true);
    ws.write(asio::buffer(hello.dump()));
    ws.binary(true);
    ws.write(asio::buffer(std::string("not a frame")));
    for (const auto& f : golden["frames"]) ws.write(asio::buffer(unhex(f["hex"].get<std::string>())));
    ws.text(true);
    ws.write(asio::buffer(std::string(R"({"type":"teams","seq":19,"left":{"name":"NEW_A","color":"#ff0000","color2":"#000000"},"right":{"name":"NEW_B","color":"#0000ff","color2":"#ffffff"}})")));
    ws.write(asio::buffer(std::string(R"({"type":"something_new","x":1})")));
    ws.close(websocket::close_code::going_away);
    acceptor.close();  // later attempts are refused
  });
  FrameBuffer buffer;
  WsSource source(local(acceptor.local_endpoint().port()), buffer, RetryPolicy{0.05, 0.1});
  source.start();
  ASSERT_TRUE(eventually([&] { return source.attempts() >= 2; }));
  server.join();
  EXPECT_EQ(source.frames(), golden["frames"].size());
  EXPECT_EQ(source.corrupt_frames(), 1u);
  EXPECT_EQ(buffer.size(), golden["frames"].size());  // the last picture stays
  const auto meta = buffer.meta();
  ASSERT_TRUE(meta.hello);
  EXPECT_EQ(meta.hello->left.name, "NEW_A");
  EXPECT_FALSE(meta.status.empty());  // lost, then refused, retrying
  EXPECT_NE(meta.status.find("retrying"), std::string::npos) << meta.status;
  source.stop();
}

TEST(WsSource, SteersTheRelaysReplayOfARecording) {
  std::ifstream in(std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/frames_v1.json");
  auto hello = nlohmann::json::parse(in)["hello"];
  hello["type"] = "hello";
  asio::io_context ioc;
  tcp::acceptor acceptor(ioc, {asio::ip::make_address("127.0.0.1"), 0});
  std::string received;
  std::thread server([&] {
    websocket::stream<tcp::socket> ws(acceptor.accept());
    ws.accept();
    ws.text(true);
    ws.write(asio::buffer(hello.dump()));
    ws.write(asio::buffer(std::string(R"({"type":"replay","time":120,"paused":true,"speed":2})")));
    boost::beast::flat_buffer buffer;
    ws.read(buffer);  // the viewer's command
    received = boost::beast::buffers_to_string(buffer.data());
    ws.close(websocket::close_code::normal);
  });
  WsUrl url = local(acceptor.local_endpoint().port());
  url.target = "/ws?recording=game1";
  FrameBuffer buffer;
  WsSource source(url, buffer, RetryPolicy{0.05, 0.1});
  source.start();
  ASSERT_TRUE(eventually([&] { return source.paused(); }));
  EXPECT_DOUBLE_EQ(source.speed(), 2.0);
  source.toggle_pause();
  server.join();
  EXPECT_EQ(received, R"({"type":"replay","action":"toggle"})");
  source.stop();
}

}  // namespace
}  // namespace mc::viewer
