#include "server/ingest/monitor_client.hpp"

#include <algorithm>
#include <thread>

namespace mc::ingest {
namespace {
// Receive buffer: well above rcssserver's 8192-byte MaxMesg, so an oversized
// datagram is seen whole (and refused) rather than silently cut.
constexpr std::size_t kRecvBuffer = 65536;
// Longest single wait, so stop() is noticed promptly.
constexpr std::chrono::milliseconds kSlice{50};
// Kernel receive buffer: a synch-mode server sends shows as fast as it
// runs; ~300 shows of slack ride out a stalled consumer.
constexpr int kSocketBuffer = 1 << 20;

bool open_socket(UdpSocket& s) {
  if (!s.open(UdpEndpoint{0, 0})) return false;
  s.set_receive_buffer(kSocketBuffer);  // best effort
  return true;
}
}  // namespace

MonitorClient::MonitorClient(MonitorClientConfig config)
    : config_(std::move(config)), buf_(kRecvBuffer), backoff_(config_.backoff_initial) {
  if (!resolve_ipv4(config_.host, config_.port, init_addr_, error_)) return;
  if (!open_socket(socket_)) {
    error_ = socket_.error();
    return;
  }
  resolved_ = true;
  server_.ip = init_addr_.ip;
  next_init_ = Clock::now();
}

MonitorClient::~MonitorClient() {
  if (connected_) send_command("(dispbye)");
}

bool MonitorClient::send_command(std::string_view command) {
  if (!connected_ || !socket_.is_open()) return false;
  // Monitors send commands with their terminating NUL, as rcssmonitor does.
  std::string d(command);
  d.push_back('\0');
  return socket_.send_to(server_, d);
}

void MonitorClient::send_dispinit() {
  std::string d = "(dispinit version " + std::to_string(config_.version) + ")";
  d.push_back('\0');
  if (!socket_.send_to(init_addr_, d)) error_ = socket_.error();
  next_init_ = Clock::now() + backoff_;
  backoff_ = std::min(backoff_ * 2, config_.backoff_max);
}

void MonitorClient::check_timers() {
  const auto now = Clock::now();
  if (connected_ && now - last_rx_ >= config_.lost_after) {
    send_command("(dispbye)");  // in case the server is alive but silent
    connected_ = false;
    backoff_ = config_.backoff_initial;
    next_init_ = now;
    // A fresh local port: a server that still lists our old address as a
    // monitor would refuse a second (dispinit) from it
    // ("only_init_allowed_on_init_port").
    UdpSocket fresh;
    if (open_socket(fresh)) socket_ = std::move(fresh);
    stream_.push_event(SourceEvent::Kind::FeedLost,
                       "no datagram from " + server_.str() + " for " +
                           std::to_string(config_.lost_after.count()) + " ms; reconnecting");
  }
  if (!connected_ && now >= next_init_) send_dispinit();
}

void MonitorClient::on_datagram(std::size_t size, const UdpEndpoint& from, WorldState& out, bool& got_state) {
  // Only the server's host talks to us; while connected, only its
  // per-monitor port and its init port (which sends init errors).
  if (from.ip != init_addr_.ip) return;
  if (connected_ && from.port != server_.port && from.port != init_addr_.port) return;
  if (size > buf_.size()) {
    // Truncated by the kernel: refuse it, numbered like any bad datagram.
    stream_.refuse_oversized(size);
    return;
  }
  const std::string_view d(buf_.data(), size);
  if (!connected_ && from.port != init_addr_.port) {
    // First datagram from a per-monitor port: handshake done.
    server_.port = from.port;
    connected_ = true;
    backoff_ = config_.backoff_initial;
    stream_.push_event(SourceEvent::Kind::FeedBack,
                       (ever_connected_ ? "feed back from " : "connected to ") + server_.str());
    ever_connected_ = true;
  }
  if (connected_ && from.port == server_.port) last_rx_ = Clock::now();
  got_state = stream_.push(d, out);
}

StateSource::Wait MonitorClient::next_for(WorldState& out, std::chrono::milliseconds timeout) {
  if (!resolved_) return Wait::End;
  const auto deadline = Clock::now() + timeout;
  while (!stopping_) {
    check_timers();
    const auto now = Clock::now();
    if (now >= deadline) return Wait::Idle;
    auto wait = std::min<Clock::duration>(deadline - now, kSlice);
    if (!connected_) wait = std::min<Clock::duration>(wait, std::max<Clock::duration>(next_init_ - now, {}));
    if (connected_) wait = std::min<Clock::duration>(wait, std::max<Clock::duration>(last_rx_ + config_.lost_after - now, {}));
    std::size_t size = 0;
    UdpEndpoint from;
    const auto ms = std::chrono::ceil<std::chrono::milliseconds>(wait);
    switch (socket_.receive(buf_.data(), buf_.size(), size, from, ms)) {
      case UdpSocket::Recv::Data: {
        bool got = false;
        on_datagram(size, from, out, got);
        if (got) return Wait::State;
        break;
      }
      case UdpSocket::Recv::Timeout:
        break;
      case UdpSocket::Recv::Error:
        // e.g. ECONNREFUSED from an earlier send: the server is gone; the
        // silence timer turns this into FeedLost. Pause briefly so that a
        // persistent error cannot spin the loop.
        error_ = socket_.error();
        std::this_thread::sleep_for(std::min<std::chrono::milliseconds>(ms, std::chrono::milliseconds(10)));
        break;
    }
  }
  return Wait::End;
}

bool MonitorClient::next(WorldState& out) {
  for (;;) {
    switch (next_for(out, std::chrono::milliseconds(1000))) {
      case Wait::State: return true;
      case Wait::End: return false;
      case Wait::Idle: break;
    }
  }
}

}  // namespace mc::ingest
