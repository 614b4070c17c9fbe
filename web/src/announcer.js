// The announcer: turns match events into what the viewer sees and hears
// (banners, the kick sound) at the moment the picture reaches them.
// Events come from the stream's control messages when it sends them (kick,
// goal, card: SPEC.md 5.2); for types the stream does not send, they are
// derived from the frames (state bits, play modes, score).
import { EventDetector } from './model/events.js';
import { EventTrack } from './model/eventtrack.js';

const LOOKAHEAD_FRAMES = 2;   // kicks are scheduled this far ahead, on the audio clock

export class Announcer {
  constructor(hud, sound) {
    this.hud = hud;
    this.sound = sound;
    this.derived = new EventDetector();
    this.track = new EventTrack();
    this.counts = { kicks: 0, banners: 0, streamEvents: 0 };
  }

  set frameMs(ms) { this.track.frameMs = ms; }

  // A new session (hello): forget everything.
  reset() { this.derived.reset(); this.track.reset(); }

  // A seek or a return to live: play nothing for the jump itself.
  jump() { this.derived.reset(); this.track.jump(); }

  // A control message; returns true if it was an event.
  control(msg) {
    if (msg.type !== 'kick' && msg.type !== 'goal' && msg.type !== 'card') return false;
    this.counts.streamEvents++;
    this.track.add(msg);
    return true;
  }

  // passed: frames the playhead went over; playhead and rate (frames/s) of
  // the picture now.
  step(passed, playhead, rate) {
    for (const f of passed) {
      for (const ev of this.derived.step(f)) {
        if (this.track.seen.has(ev.type)) continue;   // the stream announces these itself
        this._derivedEvent(ev);
      }
    }
    if (playhead === null || playhead === undefined) return;
    // A slow renderer moves the playhead far per picture: up to 1.5 s of
    // stream is a step, more is a jump.
    for (const { at, ev } of this.track.due(playhead + LOOKAHEAD_FRAMES, Math.max(40, rate * 1.5))) {
      const inSec = Math.max(0, (at - playhead) / Math.max(1, rate));
      this._streamEvent(ev, inSec);
    }
  }

  _team(side) {
    const t = this.hud.teams;
    if (side === 'l' || side === 'left' || side === 1) return t?.[1]?.name ?? '';
    if (side === 'r' || side === 'right' || side === -1) return t?.[-1]?.name ?? '';
    return '';
  }

  _kick(inSec) {
    this.counts.kicks++;
    this.sound.kick(0.7, inSec);
  }

  _goal(side, left, right) {
    this.counts.banners++;
    this.hud.banner(`GOAL! ${this._team(side)}  ${left}–${right}`, 'goal', 5000);
  }

  _card(color, unum, side) {
    this.counts.banners++;
    this.hud.banner(`${color === 'red' ? 'Red' : 'Yellow'} card: #${unum} ${this._team(side)}`, `card-${color}`);
  }

  _streamEvent(ev, inSec) {
    if (ev.type === 'kick') this._kick(inSec);
    else if (ev.type === 'goal') {
      const [l, r] = Array.isArray(ev.score) ? ev.score : ['', ''];
      this._goal(ev.side, l, r);
    } else if (ev.type === 'card') this._card(ev.card === 'red' ? 'red' : 'yellow', ev.unum, ev.side);
  }

  _derivedEvent(ev) {
    if (ev.type === 'kick') this._kick(0);
    else if (ev.type === 'goal') this._goal(ev.side, ev.frame.scoreLeft, ev.frame.scoreRight);
    else if (ev.type === 'card') this._card(ev.color, ev.player.unum, ev.player.side);
    else if (ev.type === 'foul') {
      this.counts.banners++;
      // ev.side gets the free kick (the mode names the team that fouled).
      this.hud.banner(`Foul: free kick ${this._team(ev.side)}`, 'foul');
    }
  }
}
