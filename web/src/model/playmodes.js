// Play modes: rcssserver's names in its own numbering (proto/world_state.hpp
// `PlayMode`, rcssserver src/types.h PLAYMODE_STRINGS), and the few
// questions the page asks about them.

export const PLAY_MODE_NAMES = [
  '', 'before_kick_off', 'time_over', 'play_on', 'kick_off_l', 'kick_off_r',
  'kick_in_l', 'kick_in_r', 'free_kick_l', 'free_kick_r', 'corner_kick_l',
  'corner_kick_r', 'goal_kick_l', 'goal_kick_r', 'goal_l', 'goal_r', 'drop_ball',
  'offside_l', 'offside_r', 'penalty_kick_l', 'penalty_kick_r', 'first_half_over',
  'pause', 'human_judge', 'foul_charge_l', 'foul_charge_r', 'foul_push_l',
  'foul_push_r', 'foul_multiple_attack_l', 'foul_multiple_attack_r',
  'foul_ballout_l', 'foul_ballout_r', 'back_pass_l', 'back_pass_r',
  'free_kick_fault_l', 'free_kick_fault_r', 'catch_fault_l', 'catch_fault_r',
  'indirect_free_kick_l', 'indirect_free_kick_r', 'penalty_setup_l',
  'penalty_setup_r', 'penalty_ready_l', 'penalty_ready_r', 'penalty_taken_l',
  'penalty_taken_r', 'penalty_miss_l', 'penalty_miss_r', 'penalty_score_l',
  'penalty_score_r', 'illegal_defense_l', 'illegal_defense_r',
];

// A play mode as a name, whether the wire gives a number or a name.
export function playModeName(mode) {
  if (typeof mode === 'string') return mode;
  return PLAY_MODE_NAMES[mode] ?? `mode ${mode}`;
}

// Human label for the HUD: "corner kick (L)".
export function playModeLabel(mode) {
  const name = playModeName(mode);
  if (!name) return '';
  const m = /^(.*)_([lr])$/.exec(name);
  if (!m) return name.replaceAll('_', ' ');
  return `${m[1].replaceAll('_', ' ')} (${m[2].toUpperCase()})`;
}

// The team a mode names, 'l', 'r' or '': for a restart the team that
// restarts, for a goal the team that scored, for an infringement (offside,
// a foul, a back pass...) the team that committed it.
export function playModeSide(mode) {
  const m = /_([lr])$/.exec(playModeName(mode));
  return m ? m[1] : '';
}

// For an infringement, the team that gets the free kick: the other one
// (rcssserver's referee: foul_charge_r is followed by free_kick_l).
export function freeKickSide(mode) {
  const side = playModeSide(mode);
  return side === 'l' ? 'r' : side === 'r' ? 'l' : '';
}

export function isGoalMode(mode) {
  return /^goal_[lr]$/.test(playModeName(mode));
}

// Referee calls the page announces with a "foul" banner.
export function isFoulMode(mode) {
  return /^(foul_|back_pass_|free_kick_fault_|catch_fault_|illegal_defense_)/
    .test(playModeName(mode));
}

// Player state bits (rcssserver src/types.h, proto/world_state.hpp).
export const STATE = Object.freeze({
  STAND: 0x1, KICK: 0x2, KICK_FAULT: 0x4, GOALIE: 0x8, CATCH: 0x10,
  TACKLE: 0x1000, FOUL_CHARGED: 0x20000, YELLOW: 0x40000, RED: 0x80000,
});
