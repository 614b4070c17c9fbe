#include "server/ingest/udp_socket.hpp"

#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mc::ingest {
namespace {

sockaddr_in to_sockaddr(const UdpEndpoint& e) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(e.ip);
  a.sin_port = htons(e.port);
  return a;
}

}  // namespace

std::string UdpEndpoint::str() const {
  return std::to_string(ip >> 24) + '.' + std::to_string((ip >> 16) & 255) + '.' +
         std::to_string((ip >> 8) & 255) + '.' + std::to_string(ip & 255) + ':' + std::to_string(port);
}

bool resolve_ipv4(const std::string& host, std::uint16_t port, UdpEndpoint& out, std::string& error) {
  in_addr a{};
  if (inet_pton(AF_INET, host.c_str(), &a) == 1) {
    out.ip = ntohl(a.s_addr);
    out.port = port;
    return true;
  }
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* res = nullptr;
  const int rc = getaddrinfo(host.c_str(), nullptr, &hints, &res);
  if (rc != 0 || res == nullptr) {
    error = "cannot resolve " + host + ": " + gai_strerror(rc);
    return false;
  }
  out.ip = ntohl(reinterpret_cast<sockaddr_in*>(res->ai_addr)->sin_addr.s_addr);
  out.port = port;
  freeaddrinfo(res);
  return true;
}

UdpSocket::~UdpSocket() { close(); }

UdpSocket::UdpSocket(UdpSocket&& o) noexcept : fd_(o.fd_), error_(std::move(o.error_)) { o.fd_ = -1; }

UdpSocket& UdpSocket::operator=(UdpSocket&& o) noexcept {
  if (this != &o) {
    close();
    fd_ = o.fd_;
    error_ = std::move(o.error_);
    o.fd_ = -1;
  }
  return *this;
}

bool UdpSocket::open(const UdpEndpoint& local) {
  close();
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) {
    error_ = std::string("socket: ") + std::strerror(errno);
    return false;
  }
  const sockaddr_in a = to_sockaddr(local);
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
    error_ = "bind " + local.str() + ": " + std::strerror(errno);
    close();
    return false;
  }
  return true;
}

void UdpSocket::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

std::uint16_t UdpSocket::local_port() const {
  sockaddr_in a{};
  socklen_t len = sizeof a;
  if (fd_ < 0 || ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len) != 0) return 0;
  return ntohs(a.sin_port);
}

bool UdpSocket::send_to(const UdpEndpoint& to, std::string_view bytes) {
  const sockaddr_in a = to_sockaddr(to);
  const ssize_t n = ::sendto(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL,
                             reinterpret_cast<const sockaddr*>(&a), sizeof a);
  if (n < 0 || static_cast<std::size_t>(n) != bytes.size()) {
    error_ = "sendto " + to.str() + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

bool UdpSocket::set_receive_buffer(int bytes) {
  return ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &bytes, sizeof bytes) == 0;
}

bool UdpSocket::connect(const UdpEndpoint& peer) {
  const sockaddr_in a = to_sockaddr(peer);
  if (::connect(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
    error_ = "connect " + peer.str() + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

bool UdpSocket::send(std::string_view bytes) {
  const ssize_t n = ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
  if (n < 0 || static_cast<std::size_t>(n) != bytes.size()) {
    error_ = std::string("send: ") + std::strerror(errno);
    return false;
  }
  return true;
}

UdpSocket::Recv UdpSocket::receive(char* buf, std::size_t capacity, std::size_t& size, UdpEndpoint& from,
                                   std::chrono::milliseconds timeout) {
  pollfd p{fd_, POLLIN, 0};
  const int rc = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, timeout.count())));
  if (rc == 0) return Recv::Timeout;
  if (rc < 0) {
    if (errno == EINTR) return Recv::Timeout;
    error_ = std::string("poll: ") + std::strerror(errno);
    return Recv::Error;
  }
  sockaddr_in a{};
  socklen_t len = sizeof a;
  // MSG_TRUNC: the return value is the datagram's real size even if larger.
  const ssize_t n = ::recvfrom(fd_, buf, capacity, MSG_TRUNC, reinterpret_cast<sockaddr*>(&a), &len);
  if (n < 0) {
    error_ = std::string("recvfrom: ") + std::strerror(errno);
    return Recv::Error;
  }
  size = static_cast<std::size_t>(n);
  from.ip = ntohl(a.sin_addr.s_addr);
  from.port = ntohs(a.sin_port);
  return Recv::Data;
}

}  // namespace mc::ingest
