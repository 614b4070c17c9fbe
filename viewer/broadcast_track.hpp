// What the stream says beside the frames that the viewer's picture follows
// (issue 20): each player's stamina (the fatigue pose) and the director's
// cues (the director camera). Sources add from their thread, the render
// loop reads; every member is thread-safe.
#pragma once

#include <array>
#include <cstdint>
#include <mutex>
#include <vector>

#include "proto/control_messages.hpp"
#include "proto/pose_frame.hpp"

namespace mc::viewer {

class BroadcastTrack {
 public:
  void set_stamina(const proto::StaminaUpdate& s);
  // By player slot (player_index), -1 for unknown or no stamina message yet.
  std::array<int, kMaxPlayers> stamina() const;

  // Cues in seq order; a cue far before the last one starts a new track (a
  // new stream, a seek). At most `kMaxCues` are kept.
  void add_cue(const proto::DirectorCue& cue);
  std::vector<proto::DirectorCue> cues() const;
  std::uint64_t cues_added() const;

  void reset();

  static constexpr std::size_t kMaxCues = 4000;

 private:
  mutable std::mutex mutex_;
  std::array<int, kMaxPlayers> stamina_ = filled();
  std::vector<proto::DirectorCue> cues_;
  std::uint64_t added_ = 0;
  static std::array<int, kMaxPlayers> filled() {
    std::array<int, kMaxPlayers> a{};
    a.fill(-1);
    return a;
  }
};

}  // namespace mc::viewer
