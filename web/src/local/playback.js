// Playing a log opened in the page: the time shift's history (net/timeshift.js)
// holds the whole game, filled as the worker animates it, and the playhead
// is always "in the past": it starts at the first keyframe, pauses, seeks,
// changes speed and jumps between goals with the same replay bar. It never
// goes "live": at the newest frame it waits for the animation, and at the
// end of the game it stops there.
//
// Messages that describe the moment (stamina) arrive long before the
// playhead reaches them; they are handed out when it does.
import { TimeShift } from '../net/timeshift.js';

export class LogPlayback extends TimeShift {
  constructor(opts = {}) {
    // The whole game at once: a game is ~3 MB of frames (SPEC.md 7), a
    // capped file (40,000 states) stays under this.
    super({ maxBytes: 64 * 1024 * 1024, ...opts });
    this.complete = false;     // the worker has sent the last frame
    this.timed = [];           // [seq, message] of moment messages, in seq order
    this.onMessage = null;     // (message) => void, as the playhead reaches it
    this.deliveredUpTo = -1;   // index in this.timed last handed out
    this.ready = null;         // performance.now() when the first keyframe was kept: playable
    this.firstSampled = null;  // performance.now() when the first frame went to the renderer
    this.firstShown = null;    // ... and when the loop came back: that picture was drawn
  }

  reset(makeCodec) {
    super.reset(makeCodec);
    this.active = false;
    this.complete = false;
    this.timed = [];
    this.deliveredUpTo = -1;
  }

  // Keeps a frame; the first keyframe starts the playback.
  record(bytes, header) {
    super.record(bytes, header);
    this.entries[this.entries.length - 1].time = header.time;   // for the clock on the bar
    if (!this.active && header.keyframe) {
      this.enter(header.seq, false);
      this.ready ??= performance.now();
    }
  }

  // A message that belongs to a moment (seq), handed out when the playhead gets there.
  addTimed(seq, msg) { this.timed.push([seq, msg]); }

  // The newest frame is where the playhead waits (not "live").
  live() {
    const end = this.complete ? this.last : this.last - 3;
    this.pos = Math.max(this._firstKeySeq(), end - 0.001);
    if (this.complete) this.paused = true;
    this.active = this.entries.length > 0;
  }

  sample(nowMs) {
    if (this.firstSampled !== null && this.firstShown === null) this.firstShown = performance.now();
    if (this.complete && !this.paused && this.pos >= this.last - 0.001) this.paused = true;
    // At the very end the base class would go live; hold the last frame instead.
    const s = super.sample(nowMs) ?? (this.active ? this._hold() : null);
    if (s && this.firstSampled === null) this.firstSampled = performance.now();
    this._deliver();
    return s;
  }

  // The frame at the playhead, still (the newest one while the rest is made).
  _hold() {
    const i = this._indexAt(this.pos);
    if (i < 0) return null;
    const a = this._frame(i);
    return a ? { a, b: a, t: 0, passed: [] } : null;
  }

  // Hands out the moment messages up to the playhead; after a jump, only
  // the latest of each type before it.
  _deliver() {
    if (!this.onMessage || !this.timed.length) return;
    let hi = this.timed.length - 1;
    // Index of the last message at or before the playhead.
    let lo = 0, ans = -1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (this.timed[mid][0] <= this.pos) { ans = mid; lo = mid + 1; } else hi = mid - 1;
    }
    if (ans === this.deliveredUpTo) return;
    if (ans > this.deliveredUpTo && ans - this.deliveredUpTo <= 40) {
      for (let i = this.deliveredUpTo + 1; i <= ans; i++) this.onMessage(this.timed[i][1]);
    } else if (ans >= 0) {
      const latest = new Map();
      for (let i = ans; i >= 0 && latest.size < 4 && ans - i < 200; i--) {
        const m = this.timed[i][1];
        if (!latest.has(m.type)) latest.set(m.type, m);
      }
      for (const m of latest.values()) this.onMessage(m);
    }
    this.deliveredUpTo = ans;
  }

  // For the replay bar: the game clock at the playhead, and where it is.
  bar(cyclesPerSecond = 10) {
    const e = this.entries;
    const i = this._indexAt(this.pos);
    const time = i >= 0 ? e[i].time ?? 0 : 0;
    const secs = Math.floor(time / cyclesPerSecond);
    const clock = `${String(Math.floor(secs / 60)).padStart(2, '0')}:${String(secs % 60).padStart(2, '0')}`;
    return {
      available: e.length > 0, active: true, paused: this.paused, speed: this.speed,
      fraction: this.fraction(), behindMs: 0,
      label: this.complete ? clock : `${clock} (animating…)`,
    };
  }
}
