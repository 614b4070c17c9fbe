// What the NATS end-to-end tests start: nats-server and matchcast-server
// processes on loopback, on free ports. Every wait is bounded.
#pragma once

#include <unistd.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "tests/nats/child_process.hpp"

namespace mc::nats::testing {

// nats-server from $NATS_SERVER or Debian's places; "" when not installed.
inline std::string find_nats_server() {
  if (const char* env = std::getenv("NATS_SERVER")) return env;
  for (const char* p : {"/usr/sbin/nats-server", "/usr/bin/nats-server", "/usr/local/bin/nats-server"})
    if (::access(p, X_OK) == 0) return p;
  return {};
}

// A port that was free on 127.0.0.1 a moment ago, taken from below the
// kernel's ephemeral range. Why: a port from bind(0) is an ephemeral one,
// and until the child process binds it, any outgoing connection on the
// machine (another test's clients, a reconnecting edge, nats-server's own
// routes) may take it as its local port; the child then fails with
// EADDRINUSE. CI saw exactly that as "node 1 did not join the cluster".
// Below the range only a listener can take it, and the bind check sees one.
// Never the same port twice in one process (a test takes several before
// starting anything on them).
inline std::uint16_t free_port() {
  static std::set<std::uint16_t> given;
  static std::mt19937 rng(static_cast<unsigned>(::getpid()) ^
                          static_cast<unsigned>(std::chrono::steady_clock::now().time_since_epoch().count()));
  int low = 32768;
  if (std::FILE* f = std::fopen("/proc/sys/net/ipv4/ip_local_port_range", "r")) {
    if (std::fscanf(f, "%d", &low) != 1) low = 32768;
    std::fclose(f);
  }
  boost::asio::io_context io;
  const auto loopback = boost::asio::ip::make_address("127.0.0.1");
  if (low > 12000) {
    std::uniform_int_distribution<int> pick(10000, low - 1);
    for (int attempt = 0; attempt < 200; ++attempt) {
      const auto port = static_cast<std::uint16_t>(pick(rng));
      boost::asio::ip::tcp::acceptor a(io);
      boost::system::error_code ec;
      a.open(boost::asio::ip::tcp::v4(), ec);
      if (!ec) a.bind({loopback, port}, ec);
      if (!ec && given.insert(port).second) return port;
    }
  }
  boost::asio::ip::tcp::acceptor a(io, {loopback, 0});  // no room below the range: the old way
  return a.local_endpoint().port();
}

inline bool port_open(std::uint16_t port) {
  boost::asio::io_context io;
  boost::asio::ip::tcp::socket s(io);
  boost::system::error_code ec;
  s.connect({boost::asio::ip::make_address("127.0.0.1"), port}, ec);
  return !ec;
}

// matchcast-server's arguments for a test: port 0, one I/O thread, the
// given NATS URL, reconnects every `reconnect_ms`; then `extra`.
inline std::vector<std::string> matchcast_argv(const std::string& nats_url, const std::string& record_dir,
                                               const std::vector<std::string>& extra, int reconnect_ms = 200) {
  std::vector<std::string> argv = {MATCHCAST_SERVER, "--port", "0", "--record-dir", record_dir, "--threads", "1",
                                   "--web", std::string(MATCHCAST_SOURCE_DIR) + "/web", "--nats-url", nats_url,
                                   "--nats-reconnect-wait-ms", std::to_string(reconnect_ms)};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

// The HTTP port a started matchcast-server prints ("Matchcast: open
// http://HOST:PORT/"), or 0 when it did not within `timeout`.
inline std::uint16_t wait_for_port(ChildProcess& p, std::chrono::milliseconds timeout) {
  const std::string line = p.wait_for_line("Matchcast: open http://", timeout);
  const auto colon = line.rfind(':');
  if (line.empty() || colon == std::string::npos) return 0;
  return static_cast<std::uint16_t>(std::stoi(line.substr(colon + 1)));
}

// The body of `GET target` on 127.0.0.1:port, or "" (every step bounded).
inline std::string http_get(std::uint16_t port, const std::string& target) {
  namespace http = boost::beast::http;
  try {
    boost::asio::io_context io;
    boost::beast::tcp_stream s(io);
    s.expires_after(std::chrono::seconds(5));
    s.connect({boost::asio::ip::make_address("127.0.0.1"), port});
    http::request<http::empty_body> req{http::verb::get, target, 11};
    req.set(http::field::host, "127.0.0.1");
    http::write(s, req);
    boost::beast::flat_buffer buf;
    http::response<http::string_body> res;
    http::read(s, buf, res);
    return res.result() == http::status::ok ? res.body() : std::string();
  } catch (const std::exception&) {
    return {};
  }
}

// The value of the Prometheus sample `series` (name with its labels, as
// rendered: `matchcast_edge_games{state="ready"}`) in `text`, or -1.
inline double metric(const std::string& text, const std::string& series) {
  for (std::size_t at = 0; (at = text.find(series + ' ', at)) != std::string::npos; at += series.size()) {
    if (at != 0 && text[at - 1] != '\n') continue;
    return std::stod(text.substr(at + series.size() + 1));
  }
  return -1;
}

// The game the tests broadcast (the bundled one).
inline std::string test_game_log() {
  return std::string(MATCHCAST_SOURCE_DIR) + "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";
}

}  // namespace mc::nats::testing
