// A blocking WebSocket client for relay tests, with a receive timeout so a
// broken server fails the test instead of hanging it.
#pragma once

#include <sys/socket.h>
#include <sys/time.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <string>

namespace mc::relay::testing {

struct Received {
  bool binary = false;
  std::string data;
};

class WsTestClient {
 public:
  explicit WsTestClient(std::uint16_t port, const std::string& target = "/ws") : ws_(ioc_) {
    boost::asio::ip::tcp::endpoint ep(boost::asio::ip::make_address("127.0.0.1"), port);
    ws_.next_layer().connect(ep);
    timeval tv{5, 0};
    ::setsockopt(ws_.next_layer().native_handle(), SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    ws_.handshake("127.0.0.1", target);
  }
  // Reads one message; throws boost::system::system_error on close or timeout.
  Received read() {
    boost::beast::flat_buffer buf;
    ws_.read(buf);
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
