// Counts open connections per client address and refuses one past the
// limit, so that one host cannot take every slot. A connection holds a
// Ticket; dropping it frees the slot.
#pragma once

#include <boost/asio/ip/address.hpp>
#include <map>
#include <memory>
#include <mutex>

namespace mc::relay {

class ConnectionLimiter : public std::enable_shared_from_this<ConnectionLimiter> {
 public:
  // 0 = no per-address limit.
  explicit ConnectionLimiter(std::size_t per_address) : per_address_(per_address) {}

  class Ticket {
   public:
    Ticket(std::shared_ptr<ConnectionLimiter> owner, boost::asio::ip::address a)
        : owner_(std::move(owner)), address_(a) {}
    ~Ticket() { owner_->release(address_); }
    Ticket(const Ticket&) = delete;
    Ticket& operator=(const Ticket&) = delete;

   private:
    std::shared_ptr<ConnectionLimiter> owner_;
    boost::asio::ip::address address_;
  };

  // A ticket, or nullptr when `address` already holds the limit.
  std::unique_ptr<Ticket> acquire(const boost::asio::ip::address& address);
  std::size_t count(const boost::asio::ip::address& address) const;

 private:
  void release(const boost::asio::ip::address& address);

  const std::size_t per_address_;
  mutable std::mutex mutex_;
  std::map<boost::asio::ip::address, std::size_t> open_;
};

}  // namespace mc::relay
