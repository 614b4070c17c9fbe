// Match events read from the frames the playhead passes: kicks (for the
// sound), goals, cards and fouls (for the banners). The detector remembers
// the previous frame, so each event fires once, when the picture reaches it.
import { STATE, freeKickSide, isGoalMode, isFoulMode, playModeName, playModeSide } from './playmodes.js';

export class EventDetector {
  constructor() { this.prev = null; }

  reset() { this.prev = null; }

  // Returns a list of { type: 'kick'|'goal'|'card'|'foul', ... } for frame f.
  step(f) {
    const out = [];
    const prev = this.prev;
    this.prev = f;
    if (!prev || f.seq !== prev.seq + 1) {
      // First frame or a gap: no edges to compare against, nothing fires.
      if (!prev || f.seq <= prev.seq) return out;
    }
    if (f.playMode !== prev.playMode) {
      const name = playModeName(f.playMode);
      if (isGoalMode(f.playMode)) out.push({ type: 'goal', side: playModeSide(f.playMode), frame: f });
      else if (isFoulMode(f.playMode)) {
        // side: the team that gets the free kick; offender: the one the mode names.
        out.push({ type: 'foul', side: freeKickSide(f.playMode), offender: playModeSide(f.playMode), mode: name, frame: f });
      }
    }
    if (f.scoreLeft + f.scoreRight > prev.scoreLeft + prev.scoreRight && !isGoalMode(f.playMode) &&
        !isGoalMode(prev.playMode)) {
      out.push({ type: 'goal', side: f.scoreLeft > prev.scoreLeft ? 'l' : 'r', frame: f });
    }
    for (let i = 0; i < f.players.length; i++) {
      const p = f.players[i];
      const q = prev.players[i];
      if (!q || q.unum !== p.unum || q.side !== p.side) continue;
      const rising = (bit) => (p.state & bit) !== 0 && (q.state & bit) === 0;
      if (rising(STATE.KICK) || rising(STATE.TACKLE)) out.push({ type: 'kick', player: p, frame: f });
      if (rising(STATE.RED)) out.push({ type: 'card', color: 'red', player: p, frame: f });
      else if (rising(STATE.YELLOW)) out.push({ type: 'card', color: 'yellow', player: p, frame: f });
    }
    return out;
  }
}
