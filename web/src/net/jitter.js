// Jitter buffer: frames arrive at 20 Hz with network jitter; the renderer
// samples at the display's rate. The buffer keeps every frame it receives
// (a slow renderer never drops stream frames) and runs a playhead a few
// frames behind the newest one, in units of frame sequence numbers.
//
// The playhead advances at the stream's rate and is nudged towards its
// target (newest frame minus the delay), so it absorbs jitter without jumps.
// A large error (a seek, a restart, a tab that slept) snaps it: a resync.

export class JitterBuffer {
  // frameMs: time between frames at 1x; delayFrames: how far behind the
  // newest frame to play; capacity: frames kept at most.
  constructor({ frameMs = 50, delayFrames = 3, capacity = 400 } = {}) {
    this.frameMs = frameMs;
    this.delayFrames = delayFrames;
    this.capacity = capacity;
    this.reset();
  }

  reset() {
    this.arrivals = [];        // [nowMs, seq] of the last second, for the rate
    this.rate = 1000 / this.frameMs;  // frames per second the stream delivers
    this.frames = [];          // sorted by seq
    this.playhead = null;      // seq units, fractional
    this.lastNow = null;
    this.newestArrival = 0;
    this.firstArrival = null;
    this.dropped = 0;          // stream frames that never arrived (seq gaps)
    this.late = 0;             // frames that arrived behind the playhead
    this.resyncs = 0;
  }

  get size() { return this.frames.length; }
  get newest() { return this.frames[this.frames.length - 1] ?? null; }

  // Adds a decoded frame (needs an integer `seq`). Returns false if dropped.
  push(frame, nowMs) {
    const newest = this.newest;
    if (newest) {
      const gap = frame.seq - newest.seq;
      if (gap <= 0 || gap > 200) {
        if (gap === 0) return false;  // duplicate
        if (gap < -200 || gap > 200) {
          // The stream restarted or jumped (seek): start over from here.
          const { dropped, late, resyncs } = this;
          this.reset();
          Object.assign(this, { dropped, late, resyncs: resyncs + 1 });
        } else {
          // Out of order: insert in place if it is still ahead of the playhead.
          if (this.playhead !== null && frame.seq < this.playhead) { this.late++; return false; }
          const i = this.frames.findIndex((f) => f.seq >= frame.seq);
          if (this.frames[i].seq === frame.seq) return false;
          this.frames.splice(i, 0, frame);
          if (this.dropped > 0) this.dropped--;
          return true;
        }
      } else if (gap > 1) {
        this.dropped += gap - 1;
      }
    }
    this.frames.push(frame);
    this.newestArrival = nowMs;
    this._measureRate(frame.seq, nowMs);
    if (this.frames.length > this.capacity) this.frames.splice(0, this.frames.length - this.capacity);
    return true;
  }

  // The stream's rate over the last second or so: a relay that plays a
  // recording at 4x sends frames four times as fast, and the playhead
  // follows. Clamped to 1/8x .. 16x of the nominal rate.
  _measureRate(seq, nowMs) {
    // A new connection starts with a burst (the relay's catch-up from the
    // last keyframe): it says nothing about the rate.
    this.firstArrival ??= nowMs;
    if (nowMs - this.firstArrival < 150) return;
    const a = this.arrivals;
    a.push([nowMs, seq]);
    while (a.length > 2 && nowMs - a[0][0] > 2000) a.shift();
    const span = nowMs - a[0][0];
    if (a.length >= 6 && span > 250) {
      const nominal = 1000 / this.frameMs;
      const r = ((seq - a[0][1]) * 1000) / span;
      this.rate = Math.max(nominal / 8, Math.min(nominal * 16, r));
    }
  }

  // Playback speed relative to the nominal frame rate (1 = real time).
  get speed() { return (this.rate * this.frameMs) / 1000; }

  // Where the playhead should be now: delayFrames (at the nominal rate)
  // of time behind the newest frame.
  target(nowMs) {
    const newest = this.newest;
    const perMs = this.rate / 1000;
    const age = Math.min(nowMs - this.newestArrival, this.frameMs * 2) * perMs;
    return newest.seq + age - this.delayFrames * this.speed;
  }

  // Advances the playhead to nowMs. Returns null if there is nothing to show,
  // else { a, b, t, passed } : draw a*(1-t) + b*t; `passed` lists the frames
  // the playhead went over since the last call (for events such as kicks).
  sample(nowMs) {
    if (this.frames.length === 0) return null;
    const first = this.frames[0];
    const newest = this.newest;
    const target = this.target(nowMs);
    let prev = this.playhead;
    if (this.playhead === null) {
      this.playhead = Math.max(first.seq, target);
      prev = this.playhead;
    } else {
      const dt = Math.max(0, Math.min(nowMs - this.lastNow, 1000));
      this.playhead += (dt * this.rate) / 1000;
      const err = target - this.playhead;
      if (Math.abs(err) > 20 * Math.max(1, this.speed)) {
        this.playhead = target;
        prev = target;
        this.resyncs++;
      } else {
        // Converge in about a second; never run past the newest frame.
        this.playhead += err * Math.min(1, dt / 1000);
      }
    }
    this.lastNow = nowMs;
    this.playhead = Math.max(first.seq, Math.min(this.playhead, newest.seq));

    // Frames the playhead went over in (prev, playhead].
    const passed = [];
    for (const f of this.frames) {
      if (f.seq > prev && f.seq <= this.playhead) passed.push(f);
    }
    // a = last frame at or before the playhead, b = the one after it.
    let i = this.frames.length - 1;
    while (i > 0 && this.frames[i].seq > this.playhead) i--;
    const a = this.frames[i];
    const b = this.frames[Math.min(i + 1, this.frames.length - 1)];
    const t = b.seq > a.seq ? (this.playhead - a.seq) / (b.seq - a.seq) : 0;
    // Keep two frames behind the playhead, drop older ones.
    if (i > 2) this.frames.splice(0, i - 2);
    return { a, b, t: Math.max(0, Math.min(1, t)), passed };
  }

  // How far behind the newest received frame the picture is, in ms.
  lagMs() {
    if (this.playhead === null || !this.newest) return 0;
    return ((this.newest.seq - this.playhead) * 1000) / this.rate;
  }
}
