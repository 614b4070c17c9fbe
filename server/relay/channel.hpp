// A channel is one game's broadcast: the hello every spectator gets first,
// the match's current metadata (the latest "teams" and "score" messages),
// the current group of pictures (the latest keyframe and the deltas since),
// and the set of spectators. Frames are encoded once by the publisher and
// the same immutable bytes go to every subscriber.
//
// Thread safety: every member may be called from any thread. publish_*() is
// expected from one producer thread, so subscribers see frames in order.
#pragma once

#include <boost/asio/io_context.hpp>
#include <array>
#include <atomic>
#include <cstdint>
#include <iterator>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "server/relay/message.hpp"

namespace mc::relay {

// Anything that receives a channel's messages (a WebSocket session, a recorder).
class Subscriber {
 public:
  virtual ~Subscriber() = default;
  // Called from the publisher's thread; must not block.
  virtual void deliver(const Message& m) = 0;
  // The server is stopping: say goodbye (a close frame) and end.
  virtual void shutdown() {}
  // The channel ends for a reason the spectator should read (a NATS edge
  // found no such game): a close frame with `code` and `reason`.
  virtual void close(std::uint16_t /*code*/, const std::string& /*reason*/) { shutdown(); }

  // A subscriber that lives on one single-threaded io_context (a spectator's
  // session) returns it, and joins and leaves on that thread. The channel
  // then delivers to all the subscribers of that thread with one posted
  // task per message, which calls deliver_here() on that thread: no post,
  // lock or allocation per subscriber and frame. nullptr = deliver() from
  // the publisher's thread.
  virtual boost::asio::io_context* home() { return nullptr; }
  virtual void deliver_here(const Message& m) { deliver(m); }
};

// Where a channel's input stands, for spectators' banners and /metrics.
enum class FeedState : int { Starting = 0, Live = 1, Lost = 2, Ended = 3 };
const char* feed_state_name(FeedState s);

class Channel {
 public:
  explicit Channel(std::string name) : name_(std::move(name)) {}

  const std::string& name() const { return name_; }

  // The hello a joiner receives first. Replacing it also sends it to the
  // current spectators (the game or its metadata changed) and forgets the
  // kept metadata, which belonged to the game the old hello announced.
  void set_hello(std::string json);
  // One encoded pose frame. A keyframe starts a new catch-up group.
  void publish_frame(std::string bytes, bool keyframe);
  // A JSON event or metadata change, sent to the current spectators. The
  // latest message of each type in kKeptControlTypes is also kept for
  // joiners (proto/SPEC.md section 5.3).
  void publish_control(std::string json);

  // The control messages whose latest copy a joiner receives right after
  // the hello, in this order: what a scoreboard needs before the first
  // picture. Any publisher (a feed, a replay, a NATS edge) gets this for free.
  static constexpr const char* kKeptControlTypes[] = {"teams", "score"};

  // Registers `s` and returns what it must send first, atomically with
  // respect to publishing: the hello, the kept metadata (kKeptControlTypes
  // order, those published so far), then the latest keyframe and every
  // delta since. A late joiner thus shows the current state at once.
  std::vector<Message> join(const std::shared_ptr<Subscriber>& s);
  void leave(const Subscriber* s);

  std::size_t subscribers() const;
  // Asks every subscriber to shut down (graceful server stop).
  void shutdown_subscribers();
  // Asks every subscriber to close with `code` and `reason` (Subscriber::close).
  void close_subscribers(std::uint16_t code, const std::string& reason);

  void set_feed_state(FeedState s) { feed_state_.store(static_cast<int>(s)); }
  FeedState feed_state() const { return static_cast<FeedState>(feed_state_.load()); }
  std::uint64_t frames_published() const { return frames_published_.load(); }

 private:
  struct Group;
  // Who receives a message: copied under the lock, served outside it, so a
  // slow subscriber never blocks joins or the next publish.
  struct Audience;
  Audience audience_locked();
  static void send(Audience& a, const Message& m);
  // Runs `f(subscriber)` for every subscriber of `g`, on g's thread.
  template <class F>
  static void for_each_at_home(const std::shared_ptr<Group>& g, F f);

  const std::string name_;
  mutable std::mutex mutex_;
  Message hello_;  // bytes == nullptr until set_hello
  // The latest message of each kKeptControlTypes entry (bytes == nullptr: none yet).
  std::array<Message, std::size(kKeptControlTypes)> kept_;
  std::vector<Message> gop_;  // latest keyframe + deltas since
  std::vector<std::weak_ptr<Subscriber>> subscribers_;  // those without a home()
  // Subscribers by home thread. A group's list is touched only on its own
  // thread: by joins and leaves (a session's own thread) and by the fan-out
  // tasks. So a join costs a push_back, not a copy of every other
  // spectator's entry (which made a connect storm quadratic). Each message
  // carries its publish number: a joiner skips what its catch-up already
  // held, as a task posted before the join can run after it.
  struct Entry {
    // Kept alive while listed: a session destroyed without leaving (its
    // thread stopped) leaves a Tap that delivers to nobody, never a dangling one.
    std::shared_ptr<Subscriber> subscriber;
    std::uint64_t after;   // deliver only messages published after this
    bool gone = false;     // left while the list was being walked
  };
  struct Group {
    explicit Group(boost::asio::io_context* h) : home(h) {}
    boost::asio::io_context* const home;
    std::vector<Entry> list;          // home thread only
    bool walking = false, holes = false;  // home thread only
    std::atomic<std::size_t> count{0};    // any thread (subscribers())
  };
  struct Audience {
    std::vector<std::shared_ptr<Subscriber>> targets;
    std::vector<std::shared_ptr<Group>> groups;
  };
  std::vector<std::shared_ptr<Group>> groups_;  // grows, never shrinks
  std::uint64_t published_ = 0;  // messages published so far (under mutex_)
  std::atomic<std::uint64_t> frames_published_{0};
  std::atomic<int> feed_state_{0};
};

}  // namespace mc::relay
