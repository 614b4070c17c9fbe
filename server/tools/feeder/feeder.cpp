#include "server/tools/feeder/feeder.hpp"

#include <poll.h>

#include <cmath>

#include "server/ingest/monitor_decoder.hpp"
#include "server/ingest/monitor_serializer.hpp"
#include "server/ingest/sexp_cursor.hpp"

namespace mc::feeder {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kRecvBuffer = 65536;
constexpr std::chrono::milliseconds kSlice{50};

std::string_view trim_nul(std::string_view d) {
  while (!d.empty() && (d.back() == '\0' || d.back() == '\n' || d.back() == ' ')) d.remove_suffix(1);
  return d;
}

}  // namespace

bool parse_dispinit(std::string_view text, int& version) {
  ingest::SexpCursor c(trim_nul(text));
  if (!c.lit('(') || !c.keyword("dispinit")) return false;
  if (c.lit(')')) {
    version = 1;
    return c.at_end();
  }
  double v = 0;
  if (!c.keyword("version") || !c.number(v) || !c.lit(')') || !c.at_end()) return false;
  if (v < -1000 || v > 1000) return false;
  version = static_cast<int>(v);
  return true;
}

Feeder::Feeder(FeederConfig config) : config_(std::move(config)), buf_(kRecvBuffer) {}

bool Feeder::open(std::string& error) {
  if (!(config_.speed > 0) || !std::isfinite(config_.speed)) {
    error = "speed must be a positive number";
    return false;
  }
  ingest::UdpEndpoint local;
  if (!ingest::resolve_ipv4(config_.bind_host, config_.port, local, error)) return false;
  if (!main_.open(local)) {
    error = main_.error();
    return false;
  }
  if (!open_log(error) || !advance(error)) return false;
  if (!have_pending_) {
    error = "log " + config_.log_path + " has no shows";
    return false;
  }
  return true;
}

bool Feeder::open_log(std::string& error) {
  log_ = ingest::open_log(config_.log_path, error);
  return log_ != nullptr;
}

bool Feeder::advance(std::string& error) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (log_->next(pending_)) {
      have_pending_ = true;
      ingest::SourceEvent ev;
      while (log_->poll_event(ev))
        if (ev.kind == ingest::SourceEvent::Kind::Message) pending_events_.push_back(std::move(ev));
      return true;
    }
    // The (result ..) message after the last show.
    ingest::SourceEvent ev;
    while (log_->poll_event(ev))
      if (ev.kind == ingest::SourceEvent::Kind::Message) pending_events_.push_back(std::move(ev));
    have_pending_ = false;
    if (!config_.loop) return true;
    if (!open_log(error)) return false;
  }
  error = "log " + config_.log_path + " has no shows";
  return false;
}

void Feeder::send_to(Monitor& m, std::string_view payload) {
  if (ingest::serializer_is_binary(m.version)) {
    m.socket.send(payload);  // fixed-size records
    return;
  }
  // Every text/JSON datagram ends in NUL, as rcssserver sends them.
  std::string d(payload);
  d.push_back('\0');
  m.socket.send(d);
}

void Feeder::accept_monitor(const ingest::UdpEndpoint& from, int version) {
  if (!ingest::serializer_supports(version)) {
    main_.send_to(from, std::string_view("(error illegal_client_version)\0", 31));
    return;
  }
  // A second dispinit from the same address replaces the old session.
  std::erase_if(monitors_, [&](const auto& m) { return m->addr == from; });
  if (monitors_.size() >= config_.max_monitors) {
    main_.send_to(from, std::string_view("(error no_more_monitor)\0", 24));
    return;
  }
  auto m = std::make_unique<Monitor>();
  m->addr = from;
  m->version = version;
  ingest::UdpEndpoint local;
  std::string err;
  if (!ingest::resolve_ipv4(config_.bind_host, 0, local, err) || !m->socket.open(local) ||
      !m->socket.connect(from)) {
    main_.send_to(from, std::string_view("(error connection_failed)\0", 26));
    return;
  }
  for (const std::string& p : ingest::serialize_params(log_->params(), version)) send_to(*m, p);
  monitors_.push_back(std::move(m));
  monitor_count_ = monitors_.size();
}

void Feeder::on_init_port() {
  std::size_t size = 0;
  ingest::UdpEndpoint from;
  if (main_.receive(buf_.data(), buf_.size(), size, from, std::chrono::milliseconds(0)) !=
      ingest::UdpSocket::Recv::Data)
    return;
  if (size > ingest::kMaxDatagram) return;  // refused unread
  int version = 0;
  if (parse_dispinit(std::string_view(buf_.data(), size), version)) {
    accept_monitor(from, version);
    return;
  }
  // Like rcssserver for versions >= 2: commands belong on the per-monitor port.
  for (const auto& m : monitors_)
    if (m->addr == from) main_.send_to(from, std::string_view("(error only_init_allowed_on_init_port)\0", 39));
}

void Feeder::on_monitor(std::size_t i) {
  Monitor& m = *monitors_[i];
  std::size_t size = 0;
  ingest::UdpEndpoint from;
  const auto r = m.socket.receive(buf_.data(), buf_.size(), size, from, std::chrono::milliseconds(0));
  if (r == ingest::UdpSocket::Recv::Error) {
    m.socket.close();  // ECONNREFUSED: the monitor went away
    return;
  }
  if (r != ingest::UdpSocket::Recv::Data || size > ingest::kMaxDatagram) return;
  const std::string_view cmd = trim_nul(std::string_view(buf_.data(), size));
  if (cmd == "(dispbye)") m.socket.close();
  // Other monitor commands (dispstart, dispfoul, ...) have no meaning for a replay.
}

void Feeder::tick() {
  for (auto& m : monitors_) {
    for (const auto& ev : pending_events_) send_to(*m, ingest::serialize_msg(ev.message, m->version));
    if (have_pending_) send_to(*m, ingest::serialize_show(pending_, m->version));
  }
  pending_events_.clear();
  if (have_pending_) ++shows_sent_;
}

bool Feeder::run(std::string& error) {
  const auto interval = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double, std::milli>(static_cast<double>(config_.step.count()) / config_.speed));
  bool started = !config_.wait_for_monitor;
  auto next_tick = Clock::now();
  while (!stopping_) {
    // Drop monitors that said (dispbye) or whose port is unreachable.
    std::erase_if(monitors_, [](const auto& m) { return !m->socket.is_open(); });
    monitor_count_ = monitors_.size();
    if (!started && !monitors_.empty()) {
      started = true;
      next_tick = Clock::now();
    }
    const auto now = Clock::now();
    if (started && now >= next_tick) {
      if (!have_pending_ && pending_events_.empty()) return true;  // log over, not looping
      tick();
      if (!have_pending_) return true;
      if (!advance(error)) return false;
      next_tick += interval;
      // After a stall (debugger, overload) don't burst to catch up.
      if (Clock::now() - next_tick > 10 * interval) next_tick = Clock::now();
      continue;
    }
    auto wait = kSlice;
    if (started)
      wait = std::min(wait, std::chrono::ceil<std::chrono::milliseconds>(next_tick - now));
    std::vector<pollfd> fds;
    fds.push_back({main_.fd(), POLLIN, 0});
    for (const auto& m : monitors_) fds.push_back({m->socket.fd(), POLLIN, 0});
    const int rc = ::poll(fds.data(), fds.size(), static_cast<int>(wait.count()));
    if (rc <= 0) continue;
    if (fds[0].revents & (POLLIN | POLLERR)) on_init_port();
    for (std::size_t i = 1; i < fds.size(); ++i)
      if (fds[i].revents & (POLLIN | POLLERR)) on_monitor(i - 1);
  }
  return true;
}

}  // namespace mc::feeder
