// Time shift on a live game: the page keeps the encoded frames it has
// received (a few megabytes: about an hour at the demo's rate) so that the
// viewer can pause, rewind, seek, change speed and jump between goals, then
// return to live. A moment is redrawn by decoding again, with a private
// decoder, from the keyframe at or before it (at most one keyframe interval
// of frames). The live stream keeps being received and decoded meanwhile.
import { isGoalMode } from '../model/playmodes.js';

export class TimeShift {
  // makeCodec(): a fresh decoder for this stream ({ decode(bytes) -> frame }).
  constructor({ maxBytes = 32 * 1024 * 1024, frameMs = 50 } = {}) {
    this.maxBytes = maxBytes;
    this.frameMs = frameMs;
    this.reset(null);
  }

  reset(makeCodec) {
    this.makeCodec = makeCodec;
    this.entries = [];   // { seq, key, mode, bytes } in arrival (= seq) order
    this.bytes = 0;
    this.goals = [];     // seq of each goal's first frame
    this.active = false; // false: live
    this.paused = false;
    this.speed = 1;
    this.pos = 0;        // playhead, seq units
    this.codec = null;
    this.cursor = -1;    // index of the last entry decoded by this.codec
    this.decoded = [];   // [[index, frame]] of the last few decoded entries
    this.lastNow = null;
    this.resyncs = 0;
  }

  get first() { return this.entries.length ? this.entries[0].seq : 0; }
  get last() { return this.entries.length ? this.entries[this.entries.length - 1].seq : 0; }

  // Keeps a live frame (bytes as received, frame as decoded).
  record(bytes, frame) {
    const e = this.entries;
    if (e.length && frame.seq <= e[e.length - 1].seq) {
      // The stream started again (new server or new session): a new history.
      this.reset(this.makeCodec);
    }
    const prevMode = e.length ? e[e.length - 1].mode : null;
    e.push({ seq: frame.seq, key: frame.keyframe, mode: frame.playMode, bytes });
    this.bytes += bytes.byteLength;
    if (isGoalMode(frame.playMode) && !isGoalMode(prevMode)) this.goals.push(frame.seq);
    // Over budget: drop the oldest frames, up to the next keyframe.
    while (this.bytes > this.maxBytes && e.length > 1) {
      let n = 1;
      while (n < e.length && !e[n].key) n++;
      for (const x of e.splice(0, n)) this.bytes -= x.bytes.byteLength;
      this.cursor = -1;
      this.decoded = [];
    }
    while (this.goals.length && this.goals[0] < this.first) this.goals.shift();
  }

  // Leaves live at the given playhead (the picture on screen), paused or not.
  enter(pos, paused = false) {
    if (!this.entries.length || !this.makeCodec) return false;
    this.active = true;
    this.paused = paused;
    this.pos = Math.max(this._firstKeySeq(), Math.min(pos, this.last));
    this.lastNow = null;
    return true;
  }

  live() { this.active = false; this.paused = false; this.speed = 1; }

  // Seek to a fraction of the kept history (0 = oldest, 1 = live edge).
  seek(frac) {
    const lo = this._firstKeySeq(), hi = this.last;
    this.enter(lo + Math.max(0, Math.min(1, frac)) * (hi - lo), this.paused);
  }

  // The previous/next goal: 5 s of build-up before it.
  jumpGoal(dir) {
    const lead = 5000 / this.frameMs;
    const at = this.active ? this.pos + lead : this.last;
    const list = dir < 0 ? this.goals.filter((g) => g < at - lead).reverse()
      : this.goals.filter((g) => g > at + 1);
    if (!list.length) return false;
    return this.enter(list[0] - lead, false);
  }

  // Fraction of the history the playhead is at (for the seek bar).
  fraction() {
    const lo = this._firstKeySeq(), hi = this.last;
    if (!this.active || hi <= lo) return 1;
    return (this.pos - lo) / (hi - lo);
  }

  // How far behind live the picture is, in ms.
  behindMs() { return this.active ? (this.last - this.pos) * this.frameMs : 0; }

  _firstKeySeq() {
    const k = this.entries.find((x) => x.key);
    return k ? k.seq : this.last;
  }

  // Index of the last entry with seq <= s (binary search), or -1.
  _indexAt(s) {
    const e = this.entries;
    let lo = 0, hi = e.length - 1, ans = -1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (e[mid].seq <= s) { ans = mid; lo = mid + 1; } else hi = mid - 1;
    }
    return ans;
  }

  // The decoded frame of entry i, decoding forward from a keyframe if needed.
  _frame(i) {
    const hit = this.decoded.find(([j]) => j === i);
    if (hit) return hit[1];
    if (!this.codec || this.cursor < 0 || i <= this.cursor || i - this.cursor > 40) {
      let k = i;
      while (k > 0 && !this.entries[k].key) k--;
      if (!this.entries[k].key) return null;
      this.codec = this.makeCodec();
      this.cursor = k - 1;
    }
    let f = null;
    for (let j = this.cursor + 1; j <= i; j++) {
      try {
        f = this.codec.decode(this.entries[j].bytes);
      } catch {
        f = null;   // a gap in what was kept: wait for the next keyframe
      }
      this.cursor = j;
      if (f) {
        this.decoded.push([j, f]);
        if (this.decoded.length > 4) this.decoded.shift();
      }
    }
    return f;
  }

  // Like JitterBuffer.sample: { a, b, t, passed } or null when back at live.
  sample(nowMs) {
    if (!this.active) return null;
    const dt = this.lastNow === null ? 0 : Math.max(0, Math.min(nowMs - this.lastNow, 250));
    this.lastNow = nowMs;
    const prev = this.pos;
    if (!this.paused) this.pos += (dt / this.frameMs) * this.speed;
    // Caught up with live (3 frames of margin, like the jitter buffer).
    if (this.pos >= this.last - 3) { this.live(); return null; }
    const i = this._indexAt(this.pos);
    if (i < 0) { this.pos = this._firstKeySeq(); return null; }
    // Frames the playhead went over (for kicks and banners), a few at most.
    const passed = [];
    const prevIdx = this._indexAt(prev);
    if (i > prevIdx && i - prevIdx <= 10) {
      for (let j = prevIdx + 1; j < i; j++) {
        const f = this._frame(j);
        if (f) passed.push(f);
      }
    }
    const a = this._frame(i);
    if (!a) {
      this.resyncs++;
      this.pos = this.entries[Math.min(i + 1, this.entries.length - 1)].seq;
      return null;
    }
    if (i > prevIdx && i - prevIdx <= 10) passed.push(a);
    const b = (i + 1 < this.entries.length ? this._frame(i + 1) : null) ?? a;
    const t = b.seq > a.seq ? Math.max(0, Math.min(1, (this.pos - a.seq) / (b.seq - a.seq))) : 0;
    return { a, b, t, passed };
  }
}
