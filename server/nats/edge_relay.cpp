#include "server/nats/edge_relay.hpp"

#include <vector>

#include "server/nats/subjects.hpp"
#include "server/relay/log.hpp"

namespace mc::nats {

EdgeRelay::EdgeRelay(NatsConfig config, std::shared_ptr<relay::ChannelRegistry> channels, ReadyHandler on_ready)
    : config_(std::move(config)), channels_(std::move(channels)), on_ready_(std::move(on_ready)) {}

EdgeRelay::~EdgeRelay() { stop(); }

bool EdgeRelay::start(const std::set<std::string>& local, std::string& error) {
  if (!valid_prefix(config_.subject_prefix)) {
    error = "NATS subject prefix '" + config_.subject_prefix + "' must be tokens of letters, digits, '_', '-' joined by '.'";
    return false;
  }
  for (const auto& g : config_.edge_games)
    if (!valid_game(g)) {
      error = "edge game '" + g + "' is not a subject token: use letters, digits, '_' and '-' only";
      return false;
    }
  local_ = local;
  {
    std::lock_guard lock(mutex_);
    for (const auto& g : config_.edge_games)
      if (!local_.count(g) && !games_.count(g))
        games_[g].sync = std::make_shared<EdgeSync>(channels_->open(g));
  }
  NatsLink::Events events;
  events.connected = [this] { on_connected(); };
  events.disconnected = [this] { on_disconnected(); };
  link_ = NatsLink::open(config_, "matchcast-edge", std::move(events), true, error);
  if (!link_) return false;
  if (config_.edge_games.empty()) {
    if (!link_->subscribe(live_wildcard(config_.subject_prefix),
                          [this](std::string_view subject, std::string_view data) { on_wildcard(subject, data); },
                          error))
      return false;
  } else {
    std::lock_guard lock(mutex_);
    for (auto& [name, g] : games_) {
      auto sync = g.sync;
      if (!link_->subscribe(live_subject(config_.subject_prefix, name),
                            [sync](std::string_view, std::string_view data) { sync->on_live(data); }, error))
        return false;
    }
  }
  worker_ = std::thread([this] { run(); });
  return true;
}

std::shared_ptr<EdgeSync> EdgeRelay::game(const std::string& name) {
  std::lock_guard lock(mutex_);
  auto it = games_.find(name);
  if (it != games_.end()) return it->second.sync;
  if (stopping_ || local_.count(name)) return nullptr;
  if (games_.size() >= config_.max_games) return nullptr;
  Game& g = games_[name];
  g.sync = std::make_shared<EdgeSync>(channels_->open(name));
  relay::log_event("edge_game_discovered", name);
  wake_.notify_all();
  return g.sync;
}

void EdgeRelay::on_wildcard(std::string_view subject, std::string_view data) {
  const std::string name = game_of_live_subject(config_.subject_prefix, subject);
  auto sync = name.empty() ? nullptr : game(name);
  if (!sync) {
    ++rejected_subjects_;
    return;
  }
  sync->on_live(data);
}

void EdgeRelay::on_connected() {
  relay::log_event("nats_connected", "edge");
  // Hold live messages from now until each game's snapshot is read.
  std::lock_guard lock(mutex_);
  for (auto& [name, g] : games_) {
    g.sync->on_link_back("NATS link back");
    g.sync->begin_resync();
    g.fetch = true;
    g.next_fetch = Clock::now();
  }
  wake_.notify_all();
}

void EdgeRelay::on_disconnected() {
  relay::log_event("nats_disconnected", "edge: reconnecting");
  std::lock_guard lock(mutex_);
  for (auto& [name, g] : games_) g.sync->on_link_lost("NATS link lost; reconnecting");
}

void EdgeRelay::run() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    lock.unlock();
    sync_games();
    lock.lock();
    // A 200 ms tick: silence checks and snapshot retries need no more.
    wake_.wait_for(lock, std::chrono::milliseconds(200));
  }
}

void EdgeRelay::sync_games() {
  const auto now = Clock::now();
  struct Due {
    std::string name;
    std::shared_ptr<EdgeSync> sync;
    bool fetch;
  };
  std::vector<Due> due;
  {
    std::lock_guard lock(mutex_);
    for (auto& [name, g] : games_) due.push_back({name, g.sync, g.fetch && now >= g.next_fetch});
  }
  const bool up = link_->connected();
  for (auto& d : due) {
    if (d.fetch && up) {
      if (!d.sync->resync_pending()) d.sync->begin_resync();
      std::string bytes, error;
      const auto r = link_->last_message(stream_name(config_.subject_prefix),
                                         key_subject(config_.subject_prefix, d.name), bytes, error);
      // No JetStream (or not yet): the live messages go on meanwhile, and
      // the hello the origin repeats on the live subject arrives by itself.
      if (r == NatsLink::Fetch::Failed && snapshot_failures_++ % 100 == 0)
        relay::log_event("edge_snapshot_failed", d.name + ": " + error + " (" +
                                                     std::to_string(snapshot_failures_) + " so far)");
      d.sync->on_snapshot(r == NatsLink::Fetch::Found ? &bytes : nullptr);
      std::lock_guard lock(mutex_);
      Game& g = games_[d.name];
      // Ask again later while no hello is known yet.
      g.fetch = !d.sync->has_hello();
      g.next_fetch = Clock::now() + config_.reconnect_wait;
    }
    if (!d.sync->resync_pending()) d.sync->check_silence(Clock::now(), config_.origin_silence);
    bool notify = false;
    if (d.sync->has_hello()) {
      std::lock_guard lock(mutex_);
      Game& g = games_[d.name];
      notify = !g.ready;
      g.ready = true;
    }
    if (notify && on_ready_) on_ready_(d.sync->channel());
  }
}

void EdgeRelay::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (worker_.joinable()) worker_.join();
  link_.reset();
  std::lock_guard lock(mutex_);
  for (auto& [name, g] : games_) g.sync->channel()->set_feed_state(relay::FeedState::Ended);
}

std::optional<EdgeSyncStats> EdgeRelay::stats(const std::string& game) const {
  std::lock_guard lock(mutex_);
  auto it = games_.find(game);
  if (it == games_.end()) return std::nullopt;
  return it->second.sync->stats();
}

}  // namespace mc::nats
