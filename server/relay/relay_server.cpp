#include "server/relay/relay_server.hpp"

#include <boost/asio/steady_timer.hpp>

#include <boost/asio/ip/address.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "server/relay/heap_trimmer.hpp"
#include "server/relay/listener.hpp"
#include "server/relay/log.hpp"
#include "server/relay/websocket_session.hpp"

namespace net = boost::asio;

namespace mc::relay {

RelayServer::RelayServer(RelayConfig config, std::shared_ptr<ChannelRegistry> channels,
                         ControlHandler* control, ReplayFactory* replays)
    : config_(std::move(config)),
      files_(config_.web_root),
      channels_(std::move(channels)),
      context_{config_, stats_, files_, *channels_,
               std::make_shared<ConnectionLimiter>(config_.max_connections_per_ip), control, replays,
               &sessions_} {}

RelayServer::~RelayServer() { stop(); }

bool RelayServer::start(std::string& error) {
  if (!config_.tls_cert_file.empty() || !config_.tls_key_file.empty()) {
    if (!load_tls(error)) return false;
  }
  boost::system::error_code ec;
  const auto address = net::ip::make_address(config_.address, ec);
  if (ec) {
    error = "bad listen address '" + config_.address + "': " + ec.message();
    return false;
  }
  const unsigned n = config_.threads ? config_.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<net::io_context*> iocs;
  try {
    for (unsigned i = 0; i < n; ++i) {
      iocs_.push_back(std::make_unique<net::io_context>(1));
      guards_.push_back(net::make_work_guard(*iocs_.back()));
      iocs.push_back(iocs_.back().get());
      // Asio makes a context's reactor (an epoll and an eventfd descriptor)
      // when its first socket or timer is made, and throws when it cannot.
      // Made now: not later, at a connection's socket, when the process
      // may be out of descriptors and the throw would end the server.
      net::steady_timer make_the_reactor(*iocs_.back());
    }
  } catch (const std::exception& e) {
    error = std::string("cannot set up the I/O threads: ") + e.what();
    return false;
  }
  for (const auto& file : files_.missing_page_files()) {
    log_event("web_page_incomplete", files_.root() + "/" + file +
                                         " is missing, so the page cannot start: run scripts/install-deps.sh "
                                         "(or npm ci in web/), then reload the page");
  }
  listener_ = std::make_shared<Listener>(iocs, context_);
  if (!listener_->open({address, config_.port}, error)) return false;
  listener_->run();
  trimmer_ = std::make_shared<HeapTrimmer>(*iocs_.front(), stats_);
  trimmer_->start();
  for (auto& ioc : iocs_) threads_.emplace_back([&ioc = *ioc] { ioc.run(); });
  return true;
}

bool RelayServer::load_tls(std::string& error) {
  if (config_.tls_cert_file.empty() || config_.tls_key_file.empty()) {
    error = "TLS needs both --tls-cert and --tls-key";
    return false;
  }
  for (const auto* file : {&config_.tls_cert_file, &config_.tls_key_file}) {
    // OpenSSL's own message for a missing file is only "asio.ssl error".
    if (std::FILE* f = std::fopen(file->c_str(), "rb")) {
      std::fclose(f);
    } else {
      error = std::string("cannot load the TLS ") + (file == &config_.tls_cert_file ? "certificate " : "key ") +
              *file + ": " + std::strerror(errno);
      return false;
    }
  }
  tls_.emplace(net::ssl::context::tls_server);
  tls_->set_options(net::ssl::context::default_workarounds | net::ssl::context::no_sslv2 |
                    net::ssl::context::no_sslv3 | net::ssl::context::no_tlsv1 | net::ssl::context::no_tlsv1_1);
  boost::system::error_code ec;
  tls_->use_certificate_chain_file(config_.tls_cert_file, ec);
  if (ec) {
    error = "cannot load the TLS certificate " + config_.tls_cert_file + ": " + ec.message();
    tls_.reset();
    return false;
  }
  tls_->use_private_key_file(config_.tls_key_file, net::ssl::context::pem, ec);
  if (ec) {
    error = "cannot load the TLS key " + config_.tls_key_file + ": " + ec.message();
    tls_.reset();
    return false;
  }
  if (SSL_CTX_check_private_key(tls_->native_handle()) != 1) {
    error = "the TLS key " + config_.tls_key_file + " does not match the certificate " + config_.tls_cert_file;
    tls_.reset();
    return false;
  }
  context_.tls = &*tls_;
  return true;
}

std::uint16_t RelayServer::port() const { return listener_ ? listener_->port() : 0; }

void RelayServer::stop(std::chrono::milliseconds grace) {
  if (threads_.empty()) return;
  listener_->close();
  if (trimmer_) trimmer_->stop();
  // Every spectator, live or replaying: a close frame each.
  for (const auto& s : sessions_.snapshot()) s->shutdown();
  for (const auto& ch : channels_->all()) ch->shutdown_subscribers();
  const auto deadline = std::chrono::steady_clock::now() + grace;
  while (stats_.clients.load() > 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  guards_.clear();
  for (auto& ioc : iocs_) ioc->stop();
  for (auto& t : threads_) t.join();
  threads_.clear();
}

}  // namespace mc::relay
