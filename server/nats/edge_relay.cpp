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
  wildcard_ = config_.edge_games.empty();
  if (wildcard_) {
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
      g.subscribed = true;
    }
  }
  worker_ = std::thread([this] { run(); });
  channels_->set_provider(this);
  return true;
}

std::shared_ptr<relay::Channel> EdgeRelay::request(const std::string& name) {
  if (config_.on_demand_wait.count() <= 0 || !valid_game(name)) return nullptr;
  std::lock_guard lock(mutex_);
  if (stopping_ || local_.count(name)) return nullptr;
  if (auto it = games_.find(name); it != games_.end()) return it->second.sync->channel();
  if (games_.size() >= config_.max_games) {
    ++on_demand_refused_;
    return nullptr;
  }
  // The worker subscribes (unless the wildcard covers it) and reads the
  // snapshot at once; spectators get the hello when it comes.
  Game& g = games_[name];
  g.sync = std::make_shared<EdgeSync>(channels_->open(name));
  g.on_demand = true;
  g.give_up = Clock::now() + config_.on_demand_wait;
  ++on_demand_requested_;
  relay::log_event("edge_game_requested", name);
  wake_.notify_all();
  return g.sync->channel();
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
    bool subscribe;
    bool on_demand;
    Clock::time_point give_up;
  };
  std::vector<Due> due;
  {
    std::lock_guard lock(mutex_);
    for (auto& [name, g] : games_)
      due.push_back({name, g.sync, g.fetch && now >= g.next_fetch, !g.subscribed && !wildcard_, g.on_demand,
                     g.give_up});
  }
  const bool up = link_->connected();
  for (auto& d : due) {
    if (d.subscribe) {
      // A game asked for while this edge has a list: its own subscription.
      std::string error;
      auto sync = d.sync;
      const bool ok = link_->subscribe(live_subject(config_.subject_prefix, d.name),
                                       [sync](std::string_view, std::string_view data) { sync->on_live(data); }, error);
      if (!ok) relay::log_event("edge_subscribe_failed", error);
      std::lock_guard lock(mutex_);
      if (auto it = games_.find(d.name); it != games_.end()) it->second.subscribed = ok;
    }
    if (d.fetch && up && !d.sync->resync_pending() && d.sync->in_sync()) {
      // The live stream resumed without a gap before the read: none needed.
      std::lock_guard lock(mutex_);
      if (auto it = games_.find(d.name); it != games_.end()) it->second.fetch = false;
    } else if (d.fetch && up) {
      if (!d.sync->resync_pending()) d.sync->begin_resync();
      std::string bytes, error;
      const auto r = link_->last_message(stream_name(config_.subject_prefix),
                                         key_subject(config_.subject_prefix, d.name), bytes, error);
      // No JetStream (or not yet): the live messages go on meanwhile, and
      // the hello the origin repeats on the live subject arrives by itself.
      if (r == NatsLink::Fetch::Failed && snapshot_failures_++ % 100 == 0)
        relay::log_event("edge_snapshot_failed", d.name + ": " + error + " (" +
                                                     std::to_string(snapshot_failures_) + " so far)");
      (r == NatsLink::Fetch::Found ? fetches_found_ : r == NatsLink::Fetch::NotFound ? fetches_not_found_
                                                                                       : fetches_failed_)++;
      d.sync->on_snapshot(r == NatsLink::Fetch::Found ? &bytes : nullptr);
      std::lock_guard lock(mutex_);
      if (auto it = games_.find(d.name); it != games_.end()) {
        // Ask again later while no hello is known yet.
        it->second.fetch = !d.sync->has_hello();
        it->second.next_fetch = Clock::now() + config_.reconnect_wait;
      }
    }
    if (!d.sync->resync_pending()) d.sync->check_silence(Clock::now(), config_.origin_silence);
    bool notify = false;
    if (d.sync->has_hello()) {
      std::lock_guard lock(mutex_);
      auto it = games_.find(d.name);
      if (it == games_.end()) continue;
      Game& g = it->second;
      notify = !g.ready;
      g.ready = true;
      if (g.on_demand) {
        g.on_demand = false;
        ++on_demand_found_;
        relay::log_event("edge_game_found", d.name + ": asked for, now carried");
      }
    } else if (d.on_demand && Clock::now() >= d.give_up) {
      give_up(d.name);
    }
    if (notify && on_ready_) on_ready_(d.sync->channel());
  }
  // Spectators who were joining a dropped game as it went.
  for (auto it = closing_.begin(); it != closing_.end();) {
    it->channel->close_subscribers(kCloseUnknownGame, it->reason);
    it = now >= it->until ? closing_.erase(it) : it + 1;
  }
}

void EdgeRelay::give_up(const std::string& name) {
  std::shared_ptr<EdgeSync> sync;
  bool subscribed = false;
  {
    std::lock_guard lock(mutex_);
    auto it = games_.find(name);
    if (it == games_.end() || it->second.sync->has_hello()) return;
    sync = it->second.sync;
    subscribed = it->second.subscribed;
    games_.erase(it);
    // Under the same lock: a game discovered or asked for from now on
    // gets a new channel.
    if (channels_->find(name) == sync->channel()) channels_->remove(name);
  }
  if (subscribed) link_->unsubscribe(live_subject(config_.subject_prefix, name));
  ++on_demand_unknown_;
  const std::string reason =
      link_->connected()
          ? "no game '" + name + "' here: nothing published on NATS for it in " +
                std::to_string(config_.on_demand_wait.count()) + " ms"
          : "game '" + name + "' unavailable: this edge has no NATS connection";
  relay::log_event("edge_game_unknown", reason);
  sync->channel()->set_feed_state(relay::FeedState::Ended);
  sync->channel()->close_subscribers(kCloseUnknownGame, reason);
  // Closed again on the next ticks for 2 s: a spectator whose upgrade was
  // under way joins after the first close.
  closing_.push_back({sync->channel(), Clock::now() + std::chrono::seconds(2), reason});
}

void EdgeRelay::stop() {
  // First: no request() or metrics() runs after this.
  if (link_) channels_->set_provider(nullptr);
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

EdgeReport EdgeRelay::report() const {
  EdgeReport r;
  if (link_) {
    r.connected = link_->connected();
    const auto c = link_->counters();
    r.messages_in = c.messages_in;
    r.bytes_in = c.bytes_in;
    r.reconnects = c.reconnects;
  }
  r.fetches_found = fetches_found_;
  r.fetches_not_found = fetches_not_found_;
  r.fetches_failed = fetches_failed_;
  r.on_demand_requested = on_demand_requested_;
  r.on_demand_found = on_demand_found_;
  r.on_demand_unknown = on_demand_unknown_;
  r.on_demand_refused = on_demand_refused_;
  r.rejected_subjects = rejected_subjects_;
  std::vector<std::pair<EdgeReport::Game, std::shared_ptr<EdgeSync>>> games;
  {
    std::lock_guard lock(mutex_);
    for (const auto& [name, g] : games_) games.push_back({{name, false, g.on_demand, {}}, g.sync});
  }
  for (auto& [game, sync] : games) {
    game.ready = sync->has_hello();
    game.stats = sync->stats();
    r.games.push_back(std::move(game));
  }
  return r;
}

std::string EdgeRelay::metrics() const { return render_edge_metrics(report()); }

}  // namespace mc::nats
