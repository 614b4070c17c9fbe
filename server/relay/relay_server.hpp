// The relay: an I/O loop on every core, a listener, and the channel it
// broadcasts. Owns the threads; stop() is graceful.
#pragma once

#include <boost/asio/io_context.hpp>
#include <boost/asio/ssl/context.hpp>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <chrono>

#include "server/relay/channel_registry.hpp"
#include "server/relay/connection_limiter.hpp"
#include "server/relay/http_session.hpp"
#include "server/relay/relay_config.hpp"
#include "server/relay/relay_stats.hpp"
#include "server/relay/static_files.hpp"

namespace mc::relay {

class Listener;
class HeapTrimmer;

class RelayServer {
 public:
  // `control` and `replays` may be nullptr (no control endpoints, no
  // replays); they must outlive the server.
  RelayServer(RelayConfig config, std::shared_ptr<ChannelRegistry> channels,
              ControlHandler* control = nullptr, ReplayFactory* replays = nullptr);
  ~RelayServer();
  RelayServer(const RelayServer&) = delete;
  RelayServer& operator=(const RelayServer&) = delete;

  // Loads the TLS certificate if configured, binds and starts the I/O
  // threads. False with `error` when it cannot.
  bool start(std::string& error);
  // The bound port (useful with port 0).
  std::uint16_t port() const;
  // Graceful stop: stops accepting, sends every spectator a close frame
  // ("going away"), waits up to `grace` for them to go, then ends the I/O
  // loop and joins the threads.
  void stop(std::chrono::milliseconds grace = std::chrono::milliseconds(2000));

  const RelayStats& stats() const { return stats_; }
  bool tls() const { return context_.tls != nullptr; }

 private:
  bool load_tls(std::string& error);

  RelayConfig config_;
  RelayStats stats_;
  StaticFiles files_;
  std::shared_ptr<ChannelRegistry> channels_;
  SessionSet sessions_;
  std::optional<boost::asio::ssl::context> tls_;
  HttpContext context_;
  // One io_context per I/O thread (see listener.hpp), kept running by a guard.
  std::vector<std::unique_ptr<boost::asio::io_context>> iocs_;
  std::vector<boost::asio::executor_work_guard<boost::asio::io_context::executor_type>> guards_;
  std::shared_ptr<Listener> listener_;
  std::shared_ptr<HeapTrimmer> trimmer_;  // free heap pages back after connect and disconnect bursts
  std::vector<std::thread> threads_;
};

}  // namespace mc::relay
