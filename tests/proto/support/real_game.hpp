// Realistic pose frames for the benchmark and size tests: a real log read
// by ingest, animated by mc::anim::Animator when it is built
// (MATCHCAST_HAVE_ANIMATOR), else by the GaitSynth stand-in.
#pragma once

#include <string>
#include <vector>

#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::proto::testing {

struct RealGame {
  SkeletonDef skeleton;
  std::vector<PoseFrame> frames;
  std::string animated_by;  // "anim::Animator" or "GaitSynth"
  std::string left_name, right_name;
};

// The default benchmark log: the first full HELIOS game in shared/data.
std::string default_full_game_log();

// False with `error` when the log cannot be read. `max_states` 0 = all.
bool load_real_game(const std::string& log_path, bool prefer_animator, std::size_t max_states, RealGame& out,
                    std::string& error);

}  // namespace mc::proto::testing
