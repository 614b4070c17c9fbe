// Command line and config file of matchcast-server. Every option can be
// given on the command line (--port 8080) or in a config file (port = 8080);
// the command line wins. README.md lists them all.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "server/app/log_feed.hpp"
#include "server/app/recordings.hpp"
#include "server/nats/nats_config.hpp"
#include "server/relay/relay_config.hpp"

namespace mc::app {

// One log broadcast on one channel.
struct ChannelFeed {
  std::string channel;
  FeedConfig feed;
};

struct ServerOptions {
  relay::RelayConfig relay;
  std::vector<ChannelFeed> feeds;  // at least one, except on an edge (none)
  // Every live channel is recorded here, and its recordings are offered for
  // replay. Empty = no recording, no replay.
  std::string record_dir = "recordings";
  // One file per game; past either bound the oldest recordings are deleted
  // (--record-max-bytes, --record-max-age): recording never fills the disk.
  // 2 GiB is ~5 days of the looping demo (~430 MB a day), or ~700 games.
  RetentionPolicy retention{2ull << 30, std::chrono::hours(24 * 30)};
  // Origin / edge over NATS (server/nats/README.md); standalone by default.
  nats::NatsConfig nats;
};

// Parses argv. Returns nullopt when the program should exit: after --help
// (exit_code 0, text in `message`) or on an error (exit_code 2, message).
std::optional<ServerOptions> parse_server_options(int argc, const char* const argv[],
                                                  std::string& message, int& exit_code);

}  // namespace mc::app
