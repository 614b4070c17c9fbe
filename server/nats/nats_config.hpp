// How one matchcast-server takes part in a multi-machine broadcast over NATS
// (server/nats/README.md). The default, standalone, uses no NATS at all: one
// machine needs nothing more than the relay.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace mc::nats {

enum class Role {
  Standalone,  // local feeds, local spectators, no NATS
  Origin,      // local feeds, each frame also published once to NATS
  Edge,        // no local feeds: games come from NATS, spectators are local
  Both,        // an origin for its own feeds and an edge for other games
};

// Where recordings are made in a NATS deployment: exactly one place records.
enum class RecordAt {
  Origin,  // the origin records its feeds; edges never record
  Edge,    // the origin does not record; an edge configured so records its games
};

struct NatsConfig {
  Role role = Role::Standalone;
  // One URL or a comma-separated list (the cluster's nodes); the client
  // fails over between them and learns the others from the cluster.
  std::string url = "nats://127.0.0.1:4222";
  // Try the servers of `url` in random order (the client's default, which
  // spreads edges over the nodes), or in the order listed.
  bool randomize_servers = true;
  // Subjects are <prefix>.<game>.live and <prefix>.<game>.key; the stream
  // holding the latest keyframes is <PREFIX>_KEY. One prefix per deployment.
  std::string subject_prefix = "matchcast";
  // Games an edge carries. Empty = every game any origin announces.
  std::vector<std::string> edge_games;
  RecordAt record_at = RecordAt::Origin;
  // Replicas of the keyframe stream: 1 on one NATS server, 3 on the cluster.
  int stream_replicas = 1;
  // Between two reconnect attempts; the client retries forever.
  std::chrono::milliseconds reconnect_wait{1000};
  // An edge with no message from the origin this long tells its spectators
  // "feed lost" (the origin stopped or was cut off). 20 frames/s normally.
  std::chrono::milliseconds origin_silence{3000};
  // A spectator asking an edge for a game it does not carry yet
  // (/ws?channel=NAME) makes it subscribe to that game; with no hello from
  // NATS this long, the spectator is closed with a reason (code 4404).
  // 5 s: a game being played has its snapshot in the keyframe stream (read
  // at once) or, without JetStream, repeats its hello every 10 s on the live
  // subject; 5 s covers the first and a NATS reconnect or two, not always
  // the second. 0 = no subscription on demand.
  std::chrono::milliseconds on_demand_wait{5000};
  // Most games one edge carries (announced, listed or asked for): neither a
  // stranger publishing on the prefix nor spectators asking for made-up
  // names can make it open channels without bound.
  std::size_t max_games = 64;

  bool origin() const { return role == Role::Origin || role == Role::Both; }
  bool edge() const { return role == Role::Edge || role == Role::Both; }
};

inline const char* role_name(Role role) {
  switch (role) {
    case Role::Standalone: return "standalone";
    case Role::Origin: return "origin";
    case Role::Edge: return "edge";
    case Role::Both: return "both";
  }
  return "unknown";
}

}  // namespace mc::nats
