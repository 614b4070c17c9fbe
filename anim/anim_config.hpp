// Settings of an Animator, one struct with defaults that say why.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>

namespace mc::anim {

class MotionSource;  // motion_source.hpp

// Levels of animation detail of the Virtual RoboCup perception study
// (section 6): what is animated, selectable per stream.
enum class DetailLevel : std::uint8_t {
  None = 0,  // players glide in a standing pose: no running, no kicking
  Run = 1,   // locomotion only; kicks, tackles and catches are not shown
  Kick = 2,  // kicks, tackles and catches only; players glide standing otherwise
  Full = 3,  // everything
};

// "none", "run", "kick" or "full"; nullopt for anything else.
inline std::optional<DetailLevel> detail_from_name(std::string_view name) {
  if (name == "none") return DetailLevel::None;
  if (name == "run") return DetailLevel::Run;
  if (name == "kick") return DetailLevel::Kick;
  if (name == "full") return DetailLevel::Full;
  return std::nullopt;
}

struct AnimConfig {
  // Following 10 Hz states an output frame waits for. Two is the paper's
  // choice: it classifies and smooths with two following cycles and gives a
  // kick 0.15 s of preparation. At least 1 (a half-way frame needs the next
  // state); larger values lengthen the kick preparation and the latency
  // (each cycle adds 100 ms).
  int lookahead_cycles = 2;
  DetailLevel detail = DetailLevel::Full;
  // Human cadence ceiling (steps/s): at higher speed the stride grows instead.
  // Sprinters reach 4.3-4.5, but touch-downs fall on 20 Hz frames, and a
  // foot landing every 9 frames shows 5 steps/s over a 2-s window.
  float cadence_cap = 4.0f;
  // Cycles on each side of a cycle over which the body heading is averaged
  // (zig-zags and pirouettes are softened); capped by the look-ahead.
  int heading_half_window = 2;
  // Mocap mode (issue 9): kicks from captured motion (motion_source.hpp),
  // shared and read-only. Null: the keyframe animation (the default).
  std::shared_ptr<const MotionSource> motion_source;
};

}  // namespace mc::anim
