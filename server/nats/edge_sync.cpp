#include "server/nats/edge_sync.hpp"

#include <algorithm>

#include "proto/control_messages.hpp"
#include "proto/frame_header.hpp"
#include "proto/hello.hpp"
#include "server/relay/log.hpp"

namespace mc::nats {
namespace {

// Live messages kept while a snapshot is fetched: several seconds at 20 Hz,
// more than a fetch takes; past it the oldest go (a gap, resolved by number).
constexpr std::size_t kMaxPending = 512;

std::uint64_t unix_ms() {
  using namespace std::chrono;
  return static_cast<std::uint64_t>(duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count());
}

}  // namespace

void LagHistogram::record(std::uint64_t ms) {
  std::size_t i = 0;
  while (i < kBucketsMs.size() && ms > kBucketsMs[i]) ++i;
  ++counts[i];
  ++count;
  sum_ms += ms;
  last_ms = ms;
}

void LagHistogram::add(const LagHistogram& other) {
  for (std::size_t i = 0; i < counts.size(); ++i) counts[i] += other.counts[i];
  count += other.count;
  sum_ms += other.sum_ms;
  last_ms = std::max(last_ms, other.last_ms);
}

EdgeSync::EdgeSync(std::shared_ptr<relay::Channel> channel) : channel_(std::move(channel)) {}

void EdgeSync::on_live(std::string_view bytes) {
  std::lock_guard lock(mutex_);
  last_live_ = Clock::now();
  if (lost_ && silent_) {
    silent_ = false;
    lost_ = false;
    announce(false, "messages from the origin again");
  }
  Envelope e;
  std::string error;
  const bool parsed = unwrap(bytes, e, error);
  if (buffering_) {
    // A reconnect that lost nothing: the live stream goes on at the next
    // number and the spectators wait for no keyframe. The snapshot has
    // nothing to add; end the resync now rather than hold the picture
    // until it is read (up to 0.5 s on a cluster electing a leader).
    if (!(parsed && pending_.empty() && continues(e))) {
      pending_.emplace_back(bytes);
      if (pending_.size() > kMaxPending) pending_.pop_front();
      return;
    }
    buffering_ = false;
  }
  if (!parsed) return reject(error);
  if (e.kind == Kind::Snapshot) return reject("snapshot on the live subject");
  if (have_last_ && e.number != last_ + 1) {
    ++stats_.gaps;
    waiting_key_ = true;
  }
  apply(e);
}

bool EdgeSync::continues(const Envelope& e) const {
  return !hello_.empty() && have_last_ && !waiting_key_ && e.kind != Kind::Snapshot && e.number == last_ + 1;
}

void EdgeSync::apply(const Envelope& e) {
  last_ = e.number;
  have_last_ = true;
  std::string error;
  switch (e.kind) {
    case Kind::Hello: {
      proto::Hello h;
      if (!proto::hello_from_json(e.payload, h, error)) return reject("hello: " + error);
      apply_hello(e.payload);
      break;
    }
    case Kind::Keyframe:
    case Kind::Delta: {
      const bool key = e.kind == Kind::Keyframe;
      proto::FrameHeader header;
      if (!proto::peek_header(e.payload, header, error)) {
        waiting_key_ = true;  // the next delta's base is not with the spectators
        return reject("frame: " + error);
      }
      if (header.keyframe != key) {
        waiting_key_ = true;
        return reject("frame header and envelope disagree on keyframe");
      }
      if (hello_.empty() || (!key && waiting_key_)) {
        ++stats_.held_back;
        return;
      }
      last_frame_seq_ = header.seq;
      channel_->publish_frame(std::string(e.payload), key);
      if (header.server_time_ms) {
        const std::uint64_t now = unix_ms();
        stats_.lag.record(now > header.server_time_ms ? now - header.server_time_ms : 0);
      }
      if (key) waiting_key_ = false;
      break;
    }
    case Kind::Control:
      if (proto::control_type(e.payload, error).empty()) return reject("control: " + error);
      if (hello_.empty()) {  // spectators get the hello first, always
        ++stats_.held_back;
        return;
      }
      channel_->publish_control(std::string(e.payload));
      break;
    case Kind::Snapshot: return reject("snapshot among live messages");
  }
  ++stats_.applied;
}

void EdgeSync::apply_hello(std::string_view hello) {
  if (hello == hello_) return;  // a resync re-reads the same hello: say nothing
  hello_ = std::string(hello);
  channel_->set_hello(hello_);
  waiting_key_ = true;  // the channel dropped its keyframe group
  if (!lost_) channel_->set_feed_state(relay::FeedState::Live);
}

void EdgeSync::begin_resync() {
  std::lock_guard lock(mutex_);
  buffering_ = true;
  pending_.clear();
}

void EdgeSync::on_snapshot(const std::string* bytes) {
  std::lock_guard lock(mutex_);
  if (!buffering_) return;  // the live stream resumed without a gap meanwhile
  if (bytes) {
    Envelope e;
    Snapshot s;
    std::string error;
    proto::Hello h;
    proto::FrameHeader header;
    if (!unwrap(*bytes, e, error) || !unwrap_snapshot(e, s, error)) {
      reject("snapshot: " + error);
    } else if (!proto::hello_from_json(s.hello, h, error)) {
      reject("snapshot hello: " + error);
    } else if (!s.keyframe.empty() &&
               (!proto::peek_header(s.keyframe, header, error) || !header.keyframe)) {
      reject("snapshot keyframe: " + (error.empty() ? std::string("not a keyframe") : error));
    } else if (!have_last_ || e.number > last_ || hello_.empty()) {
      // Newer than what the spectators have, or the first hello there is:
      // it replaces what they have at once (live frames resume at the next
      // keyframe when the numbers do not follow).
      apply_hello(s.hello);
      if (!s.keyframe.empty()) {
        last_frame_seq_ = header.seq;
        channel_->publish_frame(std::string(s.keyframe), true);
        waiting_key_ = false;
      }
      last_ = e.number;
      have_last_ = true;
      ++stats_.resyncs;
    }
  }
  // The live messages that came meanwhile, minus those the snapshot covers.
  buffering_ = false;
  std::deque<std::string> pending;
  pending.swap(pending_);
  for (const std::string& bytes_live : pending) {
    Envelope e;
    std::string error;
    if (!unwrap(bytes_live, e, error)) {
      reject(error);
      continue;
    }
    if (e.kind == Kind::Snapshot) {
      reject("snapshot on the live subject");
      continue;
    }
    if (have_last_ && e.number <= last_) {
      ++stats_.duplicates;
      continue;
    }
    if (have_last_ && e.number != last_ + 1) {
      ++stats_.gaps;
      waiting_key_ = true;
    }
    apply(e);
  }
}

void EdgeSync::on_link_lost(const std::string& detail) {
  std::lock_guard lock(mutex_);
  silent_ = false;
  if (lost_) return;
  lost_ = true;
  announce(true, detail);
}

void EdgeSync::on_link_back(const std::string& detail) {
  std::lock_guard lock(mutex_);
  last_live_ = Clock::now();
  silent_ = false;
  if (!lost_) return;
  lost_ = false;
  announce(false, detail);
}

void EdgeSync::check_silence(Clock::time_point now, std::chrono::milliseconds timeout) {
  std::lock_guard lock(mutex_);
  if (lost_ || hello_.empty() || now - last_live_ < timeout) return;
  lost_ = true;
  silent_ = true;
  announce(true, "no message from the origin for " + std::to_string(timeout.count()) + " ms");
}

void EdgeSync::announce(bool lost, const std::string& detail) {
  channel_->set_feed_state(lost ? relay::FeedState::Lost : relay::FeedState::Live);
  relay::log_event(lost ? "feed_lost" : "feed_back", channel_->name() + ": " + detail);
  if (hello_.empty()) return;  // nothing before the hello; /metrics has the state
  proto::FeedStatus status;
  status.lost = lost;
  status.seq = last_frame_seq_;
  status.server_time_ms = unix_ms();
  status.detail = detail;
  channel_->publish_control(proto::to_json(proto::ControlMessage{status}));
}

void EdgeSync::reject(const std::string& why) {
  // Logged sparingly: a hostile publisher must not flood the log either.
  if (stats_.rejected++ < 10 || stats_.rejected % 1000 == 0)
    relay::log_event("nats_message_rejected", channel_->name() + ": " + why);
}

bool EdgeSync::has_hello() const {
  std::lock_guard lock(mutex_);
  return !hello_.empty();
}

bool EdgeSync::resync_pending() const {
  std::lock_guard lock(mutex_);
  return buffering_;
}

bool EdgeSync::in_sync() const {
  std::lock_guard lock(mutex_);
  return !buffering_ && !hello_.empty() && !waiting_key_;
}

EdgeSyncStats EdgeSync::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

}  // namespace mc::nats
