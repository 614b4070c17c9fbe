#include "server/nats/origin_publisher.hpp"

#include "proto/control_messages.hpp"
#include "server/nats/envelope.hpp"
#include "server/nats/subjects.hpp"

namespace mc::nats {

OriginPublisher::OriginPublisher(NatsLink& link, const std::string& prefix, std::shared_ptr<relay::Channel> channel)
    : link_(link),
      channel_(std::move(channel)),
      live_subject_(live_subject(prefix, channel_->name())),
      key_subject_(key_subject(prefix, channel_->name())) {}

std::shared_ptr<OriginPublisher> OriginPublisher::start(NatsLink& link, const std::string& prefix,
                                                        std::shared_ptr<relay::Channel> channel) {
  auto p = std::shared_ptr<OriginPublisher>(new OriginPublisher(link, prefix, std::move(channel)));
  std::lock_guard lock(p->mutex_);
  // Join first, under our lock: the catch-up goes out before anything the
  // feed publishes next, in order.
  for (const auto& m : p->channel_->join(p)) p->send(m);
  return p;
}

OriginPublisher::~OriginPublisher() { stop(); }

void OriginPublisher::stop() {
  channel_->leave(this);
  // A deliver() already under way finishes before the link may go away.
  std::lock_guard lock(mutex_);
  stopped_ = true;
}

void OriginPublisher::deliver(const relay::Message& m) {
  std::lock_guard lock(mutex_);
  if (!stopped_) send(m);
}

void OriginPublisher::send(const relay::Message& m) {
  if (!m.bytes) return;
  const std::string& bytes = *m.bytes;
  Kind kind = Kind::Control;
  if (m.kind == relay::Message::Kind::Keyframe) kind = Kind::Keyframe;
  if (m.kind == relay::Message::Kind::Delta) kind = Kind::Delta;
  if (kind == Kind::Control) {
    // The channel sends its hello as a control message: tell it apart.
    std::string error;
    if (proto::control_type(bytes, error) == "hello") kind = Kind::Hello;
  }
  // Every 10th keyframe goes with the hello again: an edge that joined
  // without the keyframe stream (no JetStream) still learns it. Edges that
  // have it ignore an identical hello.
  if (kind == Kind::Keyframe && !hello_.empty() && ++keyframes_since_hello_ >= kHelloEveryKeyframes) {
    keyframes_since_hello_ = 0;
    put(live_subject_, wrap(Kind::Hello, ++number_, hello_));
  }
  const std::uint64_t number = ++number_;
  put(live_subject_, wrap(kind, number, bytes));
  if (kind == Kind::Hello) {
    hello_ = bytes;
    keyframes_since_hello_ = 0;
    snapshot_ = wrap_snapshot(number, hello_, {});
    put(key_subject_, snapshot_);
  } else if (kind == Kind::Keyframe && !hello_.empty()) {
    snapshot_ = wrap_snapshot(number, hello_, bytes);
    put(key_subject_, snapshot_);
  }
}

void OriginPublisher::republish_snapshot() {
  std::lock_guard lock(mutex_);
  if (!stopped_ && !snapshot_.empty()) put(key_subject_, snapshot_);
}

void OriginPublisher::put(const std::string& subject, const std::string& bytes) {
  if (link_.publish(subject, bytes)) ++published_;
  else ++dropped_;
}

}  // namespace mc::nats
