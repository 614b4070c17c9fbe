// Stamps WorldState::index (stream order, from 0) and WorldState::stoppage
// (how many shows at this same time came before this one). rcssserver repeats
// TIME during stoppages (~50 shows after a goal), so order is the key.
#pragma once

#include <cstdint>

#include "proto/world_state.hpp"

namespace mc::ingest {

class ShowSequencer {
 public:
  void stamp(WorldState& s) {
    s.index = next_index_++;
    stoppage_ = (have_last_ && s.time == last_time_) ? stoppage_ + 1 : 0;
    s.stoppage = stoppage_;
    last_time_ = s.time;
    have_last_ = true;
  }
  // The index the next stamped state will get.
  std::uint64_t next_index() const { return next_index_; }

 private:
  std::uint64_t next_index_ = 0;
  int last_time_ = 0;
  int stoppage_ = 0;
  bool have_last_ = false;
};

}  // namespace mc::ingest
