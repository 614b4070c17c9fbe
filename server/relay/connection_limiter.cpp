#include "server/relay/connection_limiter.hpp"

namespace mc::relay {

std::unique_ptr<ConnectionLimiter::Ticket> ConnectionLimiter::acquire(
    const boost::asio::ip::address& address) {
  std::lock_guard lock(mutex_);
  auto& n = open_[address];
  if (per_address_ != 0 && n >= per_address_) {
    if (n == 0) open_.erase(address);
    return nullptr;
  }
  ++n;
  return std::make_unique<Ticket>(shared_from_this(), address);
}

std::size_t ConnectionLimiter::count(const boost::asio::ip::address& address) const {
  std::lock_guard lock(mutex_);
  auto it = open_.find(address);
  return it == open_.end() ? 0 : it->second;
}

void ConnectionLimiter::release(const boost::asio::ip::address& address) {
  std::lock_guard lock(mutex_);
  auto it = open_.find(address);
  if (it != open_.end() && --it->second == 0) open_.erase(it);
}

}  // namespace mc::relay
