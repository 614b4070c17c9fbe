#include "server/relay/relay_server.hpp"

#include <boost/asio/ip/address.hpp>

#include "server/relay/listener.hpp"

namespace net = boost::asio;

namespace mc::relay {

RelayServer::RelayServer(RelayConfig config, std::shared_ptr<ChannelRegistry> channels,
                         ControlHandler* control, ReplayFactory* replays)
    : config_(std::move(config)),
      files_(config_.web_root),
      channels_(std::move(channels)),
      context_{config_, stats_, files_, *channels_,
               std::make_shared<ConnectionLimiter>(config_.max_connections_per_ip), control, replays},
      ioc_(config_.threads ? static_cast<int>(config_.threads)
                           : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))) {}

RelayServer::~RelayServer() { stop(); }

bool RelayServer::start(std::string& error) {
  boost::system::error_code ec;
  const auto address = net::ip::make_address(config_.address, ec);
  if (ec) {
    error = "bad listen address '" + config_.address + "': " + ec.message();
    return false;
  }
  listener_ = std::make_shared<Listener>(ioc_, context_);
  if (!listener_->open({address, config_.port}, error)) return false;
  listener_->run();
  const unsigned n = config_.threads ? config_.threads : std::max(1u, std::thread::hardware_concurrency());
  for (unsigned i = 0; i < n; ++i) threads_.emplace_back([this] { ioc_.run(); });
  return true;
}

std::uint16_t RelayServer::port() const { return listener_ ? listener_->port() : 0; }

void RelayServer::stop(std::chrono::milliseconds grace) {
  if (threads_.empty()) return;
  listener_->close();
  for (const auto& ch : channels_->all()) ch->shutdown_subscribers();
  const auto deadline = std::chrono::steady_clock::now() + grace;
  while (stats_.clients.load() > 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ioc_.stop();
  for (auto& t : threads_) t.join();
  threads_.clear();
}

}  // namespace mc::relay
