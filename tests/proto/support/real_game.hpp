// Realistic pose frames for the benchmark and size tests: a real log read
// by ingest, animated by mc::anim::Animator when it is built
// (MATCHCAST_HAVE_ANIMATOR), else by the GaitSynth stand-in.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::proto::testing {

struct RealGame {
  SkeletonDef skeleton;
  std::vector<PoseFrame> frames;
  // The control messages the server sends with these frames (JSON text):
  // anim's events (kicks, goals, play modes, cards) and a stamina update
  // once a second, each with the index of the frame it goes out before.
  // Only with anim::Animator.
  std::vector<std::pair<std::size_t, std::string>> controls;
  std::string animated_by;  // "anim::Animator" or "GaitSynth"
  // Only with anim::Animator: which feet the animator held planted on the
  // grass, kMaxPlayers bytes a frame in slot order, bit 0 the right foot,
  // bit 1 the left (anim::PlayerFrameInfo::planted). For measurements
  // (proto_pose_stream_stats --contacts): the stream does not carry them.
  std::vector<std::uint8_t> contacts;
  std::string left_name, right_name;
};

// Visits the game as the server sends it: control(text) for each control
// message, frame(i) for each frame index, in stream order.
template <class OnFrame, class OnControl>
void for_each_in_stream_order(const RealGame& game, OnFrame frame, OnControl control) {
  std::size_t c = 0;
  for (std::size_t i = 0; i < game.frames.size(); ++i) {
    for (; c < game.controls.size() && game.controls[c].first <= i; ++c) control(game.controls[c].second);
    frame(i);
  }
  for (; c < game.controls.size(); ++c) control(game.controls[c].second);
}

// The default benchmark log: the first full HELIOS game in data/ (tests/data/rcg/full links to it).
std::string default_full_game_log();

// False with `error` when the log cannot be read. `max_states` 0 = all.
bool load_real_game(const std::string& log_path, bool prefer_animator, std::size_t max_states, RealGame& out,
                    std::string& error);

}  // namespace mc::proto::testing
