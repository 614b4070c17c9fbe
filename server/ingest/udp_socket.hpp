// A small RAII IPv4 UDP socket over POSIX calls, enough for the monitor
// protocol: bind, send to an address, receive with a timeout. No exceptions:
// each call returns a status and keeps errno's text in error().
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

namespace mc::ingest {

struct UdpEndpoint {
  std::uint32_t ip = 0;    // host byte order
  std::uint16_t port = 0;  // host byte order
  bool operator==(const UdpEndpoint&) const = default;
  std::string str() const;
};

// Resolves "127.0.0.1" or a host name to an IPv4 address. False if unknown.
bool resolve_ipv4(const std::string& host, std::uint16_t port, UdpEndpoint& out, std::string& error);

class UdpSocket {
 public:
  UdpSocket() = default;
  ~UdpSocket();
  UdpSocket(UdpSocket&& o) noexcept;
  UdpSocket& operator=(UdpSocket&& o) noexcept;
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;

  // Opens and binds to `local` (port 0 = ephemeral). False + error() on failure.
  bool open(const UdpEndpoint& local);
  bool is_open() const { return fd_ >= 0; }
  void close();
  // The bound port (useful after binding port 0).
  std::uint16_t local_port() const;

  // Sends one datagram. False on failure (e.g. ECONNREFUSED reported by an
  // earlier ICMP error).
  bool send_to(const UdpEndpoint& to, std::string_view bytes);

  // Asks the kernel for a receive buffer of `bytes` (capped by
  // net.core.rmem_max); false if refused.
  bool set_receive_buffer(int bytes);

  // Fixes the peer: later send() goes there, only its datagrams arrive, and
  // an ICMP "port unreachable" shows up as an error on a later call.
  bool connect(const UdpEndpoint& peer);
  bool send(std::string_view bytes);

  enum class Recv { Data, Timeout, Error };
  // Waits up to `timeout` for one datagram into `buf`; `size` is its real
  // length (may exceed `capacity`: then only `capacity` bytes were kept and
  // the caller should refuse it).
  Recv receive(char* buf, std::size_t capacity, std::size_t& size, UdpEndpoint& from,
               std::chrono::milliseconds timeout);

  int fd() const { return fd_; }
  const std::string& error() const { return error_; }

 private:
  int fd_ = -1;
  std::string error_;
};

}  // namespace mc::ingest
