// The relay: an I/O loop on every core, a listener, and the channel it
// broadcasts. Owns the threads; stop() is graceful.
#pragma once

#include <boost/asio/io_context.hpp>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "server/relay/channel.hpp"
#include "server/relay/http_session.hpp"
#include "server/relay/relay_config.hpp"
#include "server/relay/relay_stats.hpp"
#include "server/relay/static_files.hpp"

namespace mc::relay {

class Listener;

class RelayServer {
 public:
  RelayServer(RelayConfig config, std::shared_ptr<Channel> channel);
  ~RelayServer();
  RelayServer(const RelayServer&) = delete;
  RelayServer& operator=(const RelayServer&) = delete;

  // Binds and starts the I/O threads. False with `error` when it cannot.
  bool start(std::string& error);
  // The bound port (useful with port 0).
  std::uint16_t port() const;
  // Stops accepting, ends the I/O loop and joins the threads.
  void stop();

  const RelayStats& stats() const { return stats_; }

 private:
  RelayConfig config_;
  RelayStats stats_;
  StaticFiles files_;
  HttpContext context_;
  boost::asio::io_context ioc_;
  std::shared_ptr<Listener> listener_;
  std::vector<std::thread> threads_;
};

}  // namespace mc::relay
