// A blocking WebSocket client for relay tests. Every read has a deadline, so
// a broken server fails the test instead of hanging it (asio's blocking
// reads ignore SO_RCVTIMEO, hence the async read run for a bounded time).
#pragma once

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <string>

namespace mc::relay::testing {

struct Received {
  bool binary = false;
  std::string data;
};

class WsTestClient {
 public:
  // `source`: the local address to connect from ("127.0.0.2" is another
  // client address on loopback); empty = the system's choice.
  explicit WsTestClient(std::uint16_t port, const std::string& target = "/ws", const std::string& source = "")
      : ws_(ioc_) {
    boost::asio::ip::tcp::endpoint ep(boost::asio::ip::make_address("127.0.0.1"), port);
    if (!source.empty()) {
      ws_.next_layer().open(boost::asio::ip::tcp::v4());
      ws_.next_layer().bind({boost::asio::ip::make_address(source), 0});
    }
    ws_.next_layer().connect(ep);
    ws_.handshake("127.0.0.1", target);
  }
  // Reads one message; throws boost::system::system_error on close, or
  // timed_out after `timeout`.
  Received read(std::chrono::milliseconds timeout = std::chrono::seconds(5)) {
    boost::beast::flat_buffer buf;
    boost::system::error_code result = boost::asio::error::timed_out;
    bool done = false;
    ws_.async_read(buf, [&](boost::system::error_code ec, std::size_t) {
      result = ec;
      done = true;
    });
    ioc_.restart();
    ioc_.run_for(timeout);
    if (!done) {
      // Abandon the read: the connection is unusable after a timeout.
      boost::system::error_code ignored;
      ws_.next_layer().close(ignored);
      ioc_.restart();
      ioc_.run_for(std::chrono::seconds(1));
      throw boost::system::system_error(boost::asio::error::timed_out);
    }
    if (result) throw boost::system::system_error(result);
    return {ws_.got_binary(), boost::beast::buffers_to_string(buf.data())};
  }
  void write_text(const std::string& s) {
    ws_.text(true);
    ws_.write(boost::asio::buffer(s));
  }
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket>& stream() { return ws_; }

 private:
  boost::asio::io_context ioc_;
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket> ws_;
};

}  // namespace mc::relay::testing
