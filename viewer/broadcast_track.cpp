#include "viewer/broadcast_track.hpp"

#include <algorithm>

namespace mc::viewer {

void BroadcastTrack::set_stamina(const proto::StaminaUpdate& s) {
  std::lock_guard lock(mutex_);
  for (int i = 0; i < kPlayersPerSide; ++i) {
    stamina_[static_cast<std::size_t>(i)] = s.left[static_cast<std::size_t>(i)];
    stamina_[static_cast<std::size_t>(kPlayersPerSide + i)] = s.right[static_cast<std::size_t>(i)];
  }
}

std::array<int, kMaxPlayers> BroadcastTrack::stamina() const {
  std::lock_guard lock(mutex_);
  return stamina_;
}

void BroadcastTrack::add_cue(const proto::DirectorCue& cue) {
  std::lock_guard lock(mutex_);
  ++added_;
  if (!cues_.empty() && cue.seq + 40 < cues_.back().seq) cues_.clear();  // a new timeline
  const auto at = std::upper_bound(cues_.begin(), cues_.end(), cue.seq,
                                   [](std::uint32_t s, const proto::DirectorCue& c) { return s < c.seq; });
  cues_.insert(at, cue);
  if (cues_.size() > kMaxCues) cues_.erase(cues_.begin(), cues_.begin() + static_cast<std::ptrdiff_t>(cues_.size() - kMaxCues));
}

std::vector<proto::DirectorCue> BroadcastTrack::cues() const {
  std::lock_guard lock(mutex_);
  return cues_;
}

std::uint64_t BroadcastTrack::cues_added() const {
  std::lock_guard lock(mutex_);
  return added_;
}

void BroadcastTrack::reset() {
  std::lock_guard lock(mutex_);
  stamina_ = filled();
  cues_.clear();
}

}  // namespace mc::viewer
