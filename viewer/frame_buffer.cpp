#include "viewer/frame_buffer.hpp"

#include <algorithm>
#include <cmath>

namespace mc::viewer {

void FrameBuffer::clear_locked() {
  frames_.clear();
  ++timeline_;
}

void FrameBuffer::set_hello(const proto::Hello& hello) {
  std::lock_guard lock(mutex_);
  clear_locked();
  meta_.hello = std::make_shared<const proto::Hello>(hello);
  ++meta_.hello_generation;
  meta_.pen_left = meta_.pen_right = 0;
}

void FrameBuffer::push(const PoseFrame& frame, bool keyframe) {
  std::lock_guard lock(mutex_);
  if (!frames_.empty() && frame.seq <= frames_.back().frame.seq) clear_locked();
  if (frames_.size() >= config_.capacity) {
    frames_.pop_front();
    ++dropped_;
  }
  frames_.push_back({frame, keyframe});
}

void FrameBuffer::clear_frames() {
  std::lock_guard lock(mutex_);
  clear_locked();
}

void FrameBuffer::set_status(std::string status) {
  std::lock_guard lock(mutex_);
  meta_.status = std::move(status);
}

void FrameBuffer::set_connected(bool connected) {
  std::lock_guard lock(mutex_);
  meta_.connected = connected;
}

void FrameBuffer::set_teams(const proto::TeamHello& left, const proto::TeamHello& right) {
  std::lock_guard lock(mutex_);
  if (!meta_.hello) return;
  auto copy = std::make_shared<proto::Hello>(*meta_.hello);
  copy->left = left;
  copy->right = right;
  meta_.hello = std::move(copy);
  ++meta_.hello_generation;
}

void FrameBuffer::set_penalties(int left, int right) {
  std::lock_guard lock(mutex_);
  meta_.pen_left = left;
  meta_.pen_right = right;
}

StreamMeta FrameBuffer::meta() const {
  std::lock_guard lock(mutex_);
  return meta_;
}

bool FrameBuffer::sample(double& playhead, double frames, Sample& out) {
  std::lock_guard lock(mutex_);
  out.skipped = false;
  if (frames_.empty()) return false;
  const double oldest = frames_.front().frame.seq;
  const double newest = frames_.back().frame.seq;
  if (playhead <= kPlayheadUnset || seen_timeline_ != timeline_) {
    // A new timeline: start just behind its newest frame, even before the
    // oldest one held (its first frame holds until the playhead gets there),
    // so that the jitter buffer exists from the start.
    seen_timeline_ = timeline_;
    playhead = newest - config_.delay_frames;
  } else {
    const double behind = newest - playhead - config_.catch_up_after;
    playhead += behind > 0 ? frames * (1.0 + std::min(1.0, behind / 10.0)) : frames;
  }
  if (newest - playhead > config_.max_lag_frames) {
    // Behind live: jump to the newest keyframe (held frames may not reach it).
    for (auto it = frames_.rbegin(); it != frames_.rend(); ++it) {
      if (it->keyframe) {
        playhead = it->frame.seq;
        break;
      }
    }
    if (newest - playhead > config_.max_lag_frames) playhead = newest - config_.delay_frames;
    out.skipped = true;
    ++skips_;
  }
  playhead = std::min(playhead, newest);
  // The last frame at or before the playhead, and the one after it.
  const double at = std::max(playhead, oldest);
  const auto after = std::upper_bound(frames_.begin(), frames_.end(), at,
                                      [](double p, const Entry& e) { return p < e.frame.seq; });
  const auto a = after == frames_.begin() ? after : std::prev(after);
  out.a = a->frame;
  if (after == frames_.end()) {
    out.b = a->frame;
    out.t = 0;
  } else {
    out.b = after->frame;
    // Across a gap the older frame holds until the playhead reaches the newer.
    const double span = static_cast<double>(after->frame.seq) - a->frame.seq;
    out.t = span == 1.0 ? static_cast<float>(at - a->frame.seq) : 0.0f;
  }
  out.playhead = playhead;
  out.newest = newest;
  // Frames well behind the playhead are no longer needed.
  while (frames_.size() > 2 && frames_[1].frame.seq + 1 < playhead) frames_.pop_front();
  return true;
}

std::optional<PoseFrame> FrameBuffer::frame_at_time(int time) const {
  std::lock_guard lock(mutex_);
  for (const auto& e : frames_)
    if (e.frame.time >= time) return e.frame;
  return std::nullopt;
}

std::uint64_t FrameBuffer::skips() const {
  std::lock_guard lock(mutex_);
  return skips_;
}
std::uint64_t FrameBuffer::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}
std::size_t FrameBuffer::size() const {
  std::lock_guard lock(mutex_);
  return frames_.size();
}
std::uint64_t FrameBuffer::timeline() const {
  std::lock_guard lock(mutex_);
  return timeline_;
}

}  // namespace mc::viewer
