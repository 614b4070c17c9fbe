#include "server/app/nats_roles.hpp"

#include <set>

#include "server/relay/log.hpp"

namespace mc::app {

bool NatsRoles::start(const ServerOptions& options, const std::shared_ptr<relay::ChannelRegistry>& channels,
                      nats::EdgeRelay::ReadyHandler on_edge_game, std::string& error) {
  const auto& cfg = options.nats;
  std::vector<std::string> local;
  for (const auto& f : options.feeds) local.push_back(f.channel);
  if (cfg.origin()) {
    origin_ = std::make_unique<nats::Origin>(cfg, channels);
    if (!origin_->start(local, error)) return false;
  }
  if (cfg.edge()) {
    edge_ = std::make_unique<nats::EdgeRelay>(cfg, channels, std::move(on_edge_game));
    if (!edge_->start(std::set<std::string>(local.begin(), local.end()), error)) return false;
  }
  if (cfg.role != nats::Role::Standalone)
    relay::log_event("nats_role", std::string(nats::role_name(cfg.role)) + " via " + cfg.url);
  return true;
}

void NatsRoles::stop() {
  if (origin_) origin_->stop();
  if (edge_) edge_->stop();
}

bool records_local_feeds(const ServerOptions& options) {
  if (options.record_dir.empty()) return false;
  if (options.nats.role == nats::Role::Standalone) return true;
  return options.nats.origin() && options.nats.record_at == nats::RecordAt::Origin;
}

bool records_edge_games(const ServerOptions& options) {
  return !options.record_dir.empty() && options.nats.edge() && options.nats.record_at == nats::RecordAt::Edge;
}

}  // namespace mc::app
