// The relay over TLS on loopback: a self-signed certificate made by the
// test (openssl CLI), a WSS spectator that decodes every frame of a batched
// burst, HTTPS for the other endpoints, and clear startup errors for a
// missing, unreadable or mismatched certificate.
#include "server/relay/relay_server.hpp"

#include <gtest/gtest.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/beast/websocket/ssl.hpp>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
namespace net = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;

namespace mc::relay {
namespace {

std::string frame_bytes(int seq, bool key, std::size_t size) {
  std::string s = (key ? "K" : "D") + std::to_string(seq);
  s.resize(std::max(size, s.size()), '.');
  return s;
}

// A WSS client whose reads give up after a deadline instead of hanging.
class WssClient {
 public:
  WssClient(std::uint16_t port, const std::string& ca_file) : tls_(net::ssl::context::tls_client), ws_(ioc_, tls_) {
    tls_.load_verify_file(ca_file);
    ws_.next_layer().set_verify_mode(net::ssl::verify_peer);
    beast::get_lowest_layer(ws_).connect({net::ip::make_address("127.0.0.1"), port});
    ws_.next_layer().handshake(net::ssl::stream_base::client);
    ws_.handshake("127.0.0.1", "/ws");
  }
  std::string read(std::chrono::seconds timeout = std::chrono::seconds(10)) {
    beast::flat_buffer buf;
    beast::error_code result = net::error::timed_out;
    bool done = false;
    ws_.async_read(buf, [&](beast::error_code ec, std::size_t) {
      result = ec;
      done = true;
    });
    ioc_.restart();
    ioc_.run_for(timeout);
    if (!done) {
      beast::get_lowest_layer(ws_).close();
      throw boost::system::system_error(net::error::timed_out);
    }
    if (result) throw boost::system::system_error(result);
    return beast::buffers_to_string(buf.data());
  }

 private:
  net::io_context ioc_;
  net::ssl::context tls_;
  beast::websocket::stream<beast::ssl_stream<net::ip::tcp::socket>> ws_;
};

class RelayTlsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("mc-relay-tls-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    const auto make = [](const std::string& name) {
      const std::string cmd = "openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days 1 "
                              "-subj /CN=127.0.0.1 -addext subjectAltName=IP:127.0.0.1 -keyout " +
                              (dir_ / (name + ".key")).string() + " -out " + (dir_ / (name + ".crt")).string() +
                              " >/dev/null 2>&1";
      return std::system(cmd.c_str()) == 0;
    };
    ASSERT_TRUE(make("a")) << "openssl CLI failed";
    ASSERT_TRUE(make("b"));
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  void SetUp() override {
    config_.port = 0;
    config_.web_root = dir_.string();
    config_.threads = 2;
    config_.tls_cert_file = (dir_ / "a.crt").string();
    config_.tls_key_file = (dir_ / "a.key").string();
    channels_ = std::make_shared<ChannelRegistry>();
    channel_ = channels_->open("live");
    channel_->set_hello(R"({"type":"hello"})");
  }
  void wait_for_subscribers(std::size_t n) {
    for (int i = 0; i < 500 && channel_->subscribers() != n; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_EQ(channel_->subscribers(), n);
  }
  std::string start_error() {
    RelayServer server(config_, channels_);
    std::string error;
    EXPECT_FALSE(server.start(error));
    return error;
  }

  static inline fs::path dir_;
  RelayConfig config_;
  std::shared_ptr<ChannelRegistry> channels_;
  std::shared_ptr<Channel> channel_;
};

TEST_F(RelayTlsTest, WssSpectatorDecodesEveryFrameOfABatchedBurst) {
  config_.max_queue_bytes = 32 * 1024 * 1024;
  config_.stall_timeout = std::chrono::seconds(60);
  RelayServer server(config_, channels_);
  std::string error;
  ASSERT_TRUE(server.start(error)) << error;
  ASSERT_TRUE(server.tls());
  WssClient c(server.port(), (dir_ / "a.crt").string());
  EXPECT_EQ(c.read(), R"({"type":"hello"})");
  wait_for_subscribers(1);
  constexpr int kFrames = 300;
  for (int f = 0; f < kFrames; ++f) channel_->publish_frame(frame_bytes(f, f % 20 == 0, 20000), f % 20 == 0);
  for (int f = 0; f < kFrames; ++f) ASSERT_EQ(c.read(), frame_bytes(f, f % 20 == 0, 20000)) << "frame " << f;
  // The counters move in the write's completion handler, which may run after
  // the client has read the bytes: wait for them, within a bound.
  for (int i = 0; i < 200 && server.stats().messages_sent.load() < kFrames + 1u; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(server.stats().messages_sent.load(), kFrames + 1u);
  EXPECT_LT(server.stats().writes.load(), server.stats().messages_sent.load());
}

TEST_F(RelayTlsTest, HttpsServesHealthz) {
  RelayServer server(config_, channels_);
  std::string error;
  ASSERT_TRUE(server.start(error)) << error;
  net::io_context ioc;
  net::ssl::context tls(net::ssl::context::tls_client);
  tls.load_verify_file((dir_ / "a.crt").string());
  beast::ssl_stream<net::ip::tcp::socket> s(ioc, tls);
  s.set_verify_mode(net::ssl::verify_peer);
  beast::get_lowest_layer(s).connect({net::ip::make_address("127.0.0.1"), server.port()});
  s.handshake(net::ssl::stream_base::client);
  http::request<http::empty_body> req{http::verb::get, "/healthz", 11};
  req.set(http::field::host, "127.0.0.1");
  http::write(s, req);
  beast::flat_buffer buf;
  http::response<http::string_body> res;
  http::read(s, buf, res);
  EXPECT_EQ(res.result(), http::status::ok);
  EXPECT_EQ(res.body(), "ok\n");
}

TEST_F(RelayTlsTest, PlainHttpGetsNothingFromATlsPort) {
  RelayServer server(config_, channels_);
  std::string error;
  ASSERT_TRUE(server.start(error)) << error;
  net::io_context ioc;
  net::ip::tcp::socket s(ioc);
  s.connect({net::ip::make_address("127.0.0.1"), server.port()});
  http::request<http::empty_body> req{http::verb::get, "/healthz", 11};
  req.set(http::field::host, "127.0.0.1");
  http::write(s, req);
  beast::flat_buffer buf;
  http::response<http::string_body> res;
  beast::error_code ec;
  http::read(s, buf, res, ec);
  EXPECT_TRUE(ec) << "a plain request was answered over TLS: " << res.result_int();
}

TEST_F(RelayTlsTest, BadCertificateSettingsFailAtStartWithAClearError) {
  config_.tls_cert_file = (dir_ / "missing.crt").string();
  EXPECT_NE(start_error().find("cannot load the TLS certificate " + config_.tls_cert_file + ": No such file"),
            std::string::npos);

  config_.tls_cert_file = (dir_ / "a.crt").string();
  config_.tls_key_file = (dir_ / "a.crt").string();  // not a key
  EXPECT_NE(start_error().find("cannot load the TLS key"), std::string::npos);

  config_.tls_key_file = (dir_ / "b.key").string();  // another certificate's key
  const std::string mismatch = start_error();
  EXPECT_TRUE(mismatch.find("does not match") != std::string::npos ||
              mismatch.find("mismatch") != std::string::npos)
      << mismatch;

  config_.tls_key_file.clear();
  EXPECT_NE(start_error().find("needs both"), std::string::npos);
}

}  // namespace
}  // namespace mc::relay
