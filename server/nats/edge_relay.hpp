// The edge role: subscribes to games on NATS and serves them from local
// channels, one EdgeSync per game. The games are a fixed list, or every game
// an origin publishes (discovered from <prefix>.*.live), plus any game a
// spectator asks for (/ws?channel=NAME, through ChannelProvider::request);
// at most NatsConfig::max_games in all. A game asked for that shows no hello
// within NatsConfig::on_demand_wait is dropped, and its spectators are
// closed with code 4404 and a reason.
//
// On start and after every reconnect each game resyncs: live messages are
// held while the game's snapshot (hello + latest keyframe) is read from the
// keyframe stream, so spectators get a picture at once and then the live
// frames, each once. A game with no snapshot yet is asked again every
// reconnect_wait until its hello is known; without JetStream at all, the
// hello the origin repeats on the live subject (every 10 keyframes) serves.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "server/nats/edge_metrics.hpp"
#include "server/nats/edge_sync.hpp"
#include "server/nats/nats_config.hpp"
#include "server/nats/nats_link.hpp"
#include "server/relay/channel_registry.hpp"

namespace mc::nats {

class EdgeRelay : public relay::ChannelProvider {
 public:
  // Called once per game, from the edge's worker thread, when its channel
  // first has a hello (for example to start recording it).
  using ReadyHandler = std::function<void(const std::shared_ptr<relay::Channel>&)>;

  EdgeRelay(NatsConfig config, std::shared_ptr<relay::ChannelRegistry> channels, ReadyHandler on_ready = {});
  ~EdgeRelay() override;

  // Opens the channels of config.edge_games (in that order: the first is
  // what "/ws" shows), subscribes and starts syncing. Games named in
  // `local` are this process's own feeds (role both) and are never taken
  // from NATS. False + error on bad names or NATS options only.
  bool start(const std::set<std::string>& local, std::string& error);
  void stop();

  bool connected() const { return link_ && link_->connected(); }
  // A game's counters, or nullopt when the edge does not carry it.
  std::optional<EdgeSyncStats> stats(const std::string& game) const;
  // Messages on the prefix that name no acceptable game.
  std::uint64_t rejected_subjects() const { return rejected_subjects_.load(); }
  // Everything /metrics shows about this edge.
  EdgeReport report() const;

  // relay::ChannelProvider, installed on the registry between start() and
  // stop(): a game not carried yet is subscribed to at once (I/O threads).
  std::shared_ptr<relay::Channel> request(const std::string& name) override;
  std::string metrics() const override;

  // The WebSocket close code for a game asked for that never showed up.
  static constexpr std::uint16_t kCloseUnknownGame = 4404;

 private:
  using Clock = std::chrono::steady_clock;
  struct Game {
    std::shared_ptr<EdgeSync> sync;
    bool fetch = true;  // a snapshot read is due at next_fetch
    Clock::time_point next_fetch{};
    bool ready = false;  // on_ready was called
    bool subscribed = false;  // its own <prefix>.<game>.live subscription
    bool on_demand = false;   // asked for by a spectator, no hello yet
    Clock::time_point give_up{};  // on demand: dropped if no hello by then
  };
  // The channel of a game that was dropped: its spectators are closed
  // again on every tick for a while, to catch one that was joining.
  struct Closing {
    std::shared_ptr<relay::Channel> channel;
    Clock::time_point until;
    std::string reason;
  };
  // The game's sync, created (with its channel) when absent and allowed.
  std::shared_ptr<EdgeSync> game(const std::string& name);
  void on_wildcard(std::string_view subject, std::string_view data);
  void on_connected();
  void on_disconnected();
  void run();
  void sync_games();
  // Drops an on-demand game that never showed up and closes its spectators.
  void give_up(const std::string& name);

  NatsConfig config_;
  std::shared_ptr<relay::ChannelRegistry> channels_;
  ReadyHandler on_ready_;
  std::set<std::string> local_;
  std::unique_ptr<NatsLink> link_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::string, Game> games_;
  bool stopping_ = false;
  bool wildcard_ = false;  // <prefix>.*.live: every game published (no --edge-games)
  std::thread worker_;
  std::atomic<std::uint64_t> rejected_subjects_{0};
  std::atomic<std::uint64_t> fetches_found_{0}, fetches_not_found_{0}, fetches_failed_{0};
  std::atomic<std::uint64_t> on_demand_requested_{0}, on_demand_found_{0}, on_demand_unknown_{0},
      on_demand_refused_{0};
  std::uint64_t snapshot_failures_ = 0;  // worker thread only
  std::vector<Closing> closing_;          // worker thread only
};

}  // namespace mc::nats
