#include "proto/world_state.hpp"

#include <array>

namespace mc {
namespace {
// rcssserver src/types.h PLAYMODE_STRINGS, in enum order.
constexpr std::array<std::string_view, kPlayModeCount> kNames = {
    "", "before_kick_off", "time_over", "play_on", "kick_off_l", "kick_off_r",
    "kick_in_l", "kick_in_r", "free_kick_l", "free_kick_r", "corner_kick_l",
    "corner_kick_r", "goal_kick_l", "goal_kick_r", "goal_l", "goal_r", "drop_ball",
    "offside_l", "offside_r", "penalty_kick_l", "penalty_kick_r", "first_half_over",
    "pause", "human_judge", "foul_charge_l", "foul_charge_r", "foul_push_l",
    "foul_push_r", "foul_multiple_attack_l", "foul_multiple_attack_r",
    "foul_ballout_l", "foul_ballout_r", "back_pass_l", "back_pass_r",
    "free_kick_fault_l", "free_kick_fault_r", "catch_fault_l", "catch_fault_r",
    "indirect_free_kick_l", "indirect_free_kick_r", "penalty_setup_l",
    "penalty_setup_r", "penalty_ready_l", "penalty_ready_r", "penalty_taken_l",
    "penalty_taken_r", "penalty_miss_l", "penalty_miss_r", "penalty_score_l",
    "penalty_score_r", "illegal_defense_l", "illegal_defense_r"};
}  // namespace

std::string_view play_mode_name(PlayMode mode) {
  const auto i = static_cast<std::size_t>(mode);
  return i < kNames.size() ? kNames[i] : std::string_view{};
}

std::optional<PlayMode> play_mode_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<PlayMode>(i);
  return std::nullopt;
}

}  // namespace mc
