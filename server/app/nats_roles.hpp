// The NATS side of matchcast-server, chosen by --role: nothing when
// standalone, an Origin publishing the local feeds, an EdgeRelay serving
// games from NATS, or both. Kept apart from main() so the one-machine path
// stays as it was.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "server/app/server_options.hpp"
#include "server/nats/edge_relay.hpp"
#include "server/nats/origin.hpp"
#include "server/relay/channel_registry.hpp"

namespace mc::app {

class NatsRoles {
 public:
  // Starts what options.nats.role asks for, after the local feeds exist.
  // `on_edge_game` is called once per edge game when it first has a hello.
  bool start(const ServerOptions& options, const std::shared_ptr<relay::ChannelRegistry>& channels,
             nats::EdgeRelay::ReadyHandler on_edge_game, std::string& error);
  // Stop after the feeds (nothing publishes any more) and before the relay.
  void stop();

 private:
  std::unique_ptr<nats::Origin> origin_;
  std::unique_ptr<nats::EdgeRelay> edge_;
};

// Whether this process records its local feeds / the games it gets as an
// edge: exactly one place records in a NATS deployment (--record-at).
bool records_local_feeds(const ServerOptions& options);
bool records_edge_games(const ServerOptions& options);

}  // namespace mc::app
