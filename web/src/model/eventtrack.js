// Events the stream announces (SPEC.md 5.2: kick, goal, card, ...), kept in
// stream order and played when the picture reaches them. A kick is placed
// at its contact time, which may fall between two frames.

export class EventTrack {
  constructor({ capacity = 4000, frameMs = 50 } = {}) {
    this.capacity = capacity;
    this.frameMs = frameMs;
    this.reset();
  }

  reset() {
    this.list = [];            // { at (seq units, fractional), ev }, sorted by at
    this.seen = new Set();     // event types this stream sends
    this.firedUpTo = null;     // playhead up to which events were played
  }

  // Stream position of an event, in seq units.
  at(ev) {
    if (ev.type === 'kick' && Number.isFinite(ev.contact_time_ms)) return ev.contact_time_ms / this.frameMs;
    return Number(ev.seq);
  }

  add(ev) {
    if (!Number.isFinite(Number(ev.seq))) return;
    this.seen.add(ev.type);
    const at = this.at(ev);
    const l = this.list;
    let i = l.length;
    while (i > 0 && l[i - 1].at > at) i--;
    l.splice(i, 0, { at, ev });
    if (l.length > this.capacity) l.splice(0, l.length - this.capacity);
  }

  // Events with prev < at <= upTo, in order. A jump (backwards, or more than
  // `maxStep` frames forward) plays nothing: it only moves the mark.
  due(upTo, maxStep = 40) {
    const from = this.firedUpTo;
    this.firedUpTo = upTo;
    if (from === null || upTo <= from || upTo - from > maxStep) return [];
    return this.list.filter((e) => e.at > from && e.at <= upTo);
  }

  // Drops the mark, so that the next call to due() plays nothing (a seek).
  jump() { this.firedUpTo = null; }
}
