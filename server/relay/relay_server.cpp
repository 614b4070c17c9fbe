#include "server/relay/relay_server.hpp"

#include <boost/asio/ip/address.hpp>

#include "server/relay/listener.hpp"

namespace net = boost::asio;

namespace mc::relay {

RelayServer::RelayServer(RelayConfig config, std::shared_ptr<Channel> channel)
    : config_(std::move(config)),
      files_(config_.web_root),
      context_{config_, stats_, files_, std::move(channel)},
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

void RelayServer::stop() {
  if (threads_.empty()) return;
  listener_->close();
  ioc_.stop();
  for (auto& t : threads_) t.join();
  threads_.clear();
}

}  // namespace mc::relay
