// One connection to a NATS cluster (the C client, libnats), with what the
// origin and the edge need and nothing more: publish, subscribe, the
// keyframe stream, and the link's ups and downs. The client reconnects by
// itself, forever, and resubscribes; this class only reports.
//
// Callbacks run on libnats' own threads: they must not block. The
// destructor closes the connection and waits (bounded) until no callback
// can run any more, so closures may point at the owner.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "server/nats/nats_config.hpp"

struct __natsConnection;
struct __natsSubscription;
struct __jsCtx;

namespace mc::nats {

class NatsLink {
 public:
  struct Events {
    std::function<void()> connected;     // first connection, and every reconnect
    std::function<void()> disconnected;  // the link dropped; the client retries
  };
  using Handler = std::function<void(std::string_view subject, std::string_view data)>;

  // Starts connecting to config.url. Returns at once even when no server is
  // up yet (the client keeps trying); nullptr + error only on bad options.
  // `buffer_while_reconnecting` false: what is published while the link is
  // down fails at once instead of reaching spectators seconds late (the
  // origin's frames); true: subscriptions made meanwhile are kept (the edge).
  static std::unique_ptr<NatsLink> open(const NatsConfig& config, const std::string& name, Events events,
                                        bool buffer_while_reconnecting, std::string& error);
  ~NatsLink();
  NatsLink(const NatsLink&) = delete;
  NatsLink& operator=(const NatsLink&) = delete;

  bool connected() const { return connected_.load(); }
  // Queues one message (core NATS, at most once). False when not connected
  // or the client refused it: the message is dropped, never replayed late.
  bool publish(const std::string& subject, std::string_view data);
  // Subscribes `handler` to `subject` (wildcards allowed), now and across
  // reconnects. Messages of one subscription arrive in order, on one thread.
  bool subscribe(const std::string& subject, Handler handler, std::string& error);
  // Ends the subscription to exactly `subject`; when it returns, its handler
  // is not running and will not run again (bounded wait). False: none.
  bool unsubscribe(const std::string& subject);

  // What the client has counted since open(): every message received
  // (subscriptions and JetStream replies) and successful reconnects.
  struct Counters {
    std::uint64_t messages_in = 0;
    std::uint64_t bytes_in = 0;
    std::uint64_t reconnects = 0;
  };
  Counters counters() const;

  // Creates or updates the stream keeping the last message of each subject
  // in `subjects` (file storage, `replicas` copies). Needs a connection.
  bool ensure_last_per_subject_stream(const std::string& stream, const std::string& subjects, int replicas,
                                      std::string& error);
  enum class Fetch { Found, NotFound, Failed };
  // The last message stored for `subject` in `stream`. Asks STREAM.INFO
  // first and reads a message only from a stream that answered with at
  // least one message stored: nats-server 2.9 crashes on a message-get
  // that reaches a stream still being created (server/nats/README.md, "The
  // broker crash"). NotFound: no such stream, or nothing stored yet.
  // Failed within 0.5 s when the cluster does not answer.
  Fetch last_message(const std::string& stream, const std::string& subject, std::string& out, std::string& error);

 private:
  struct Sub;
  explicit NatsLink(Events events);
  static void on_connected(__natsConnection*, void* self);
  static void on_disconnected(__natsConnection*, void* self);
  static void on_closed(__natsConnection*, void* self);

  Events events_;
  __natsConnection* conn_ = nullptr;
  __jsCtx* js_ = nullptr;
  std::atomic<bool> connected_{false};
  std::mutex mutex_;
  std::condition_variable closed_cv_;
  bool closed_ = false;
  std::vector<std::unique_ptr<Sub>> subs_;
};

}  // namespace mc::nats
