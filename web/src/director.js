// The director camera (issue 20): the page follows the server's director
// track ("director" messages, proto/SPEC.md 5.5) as a TV viewer follows a
// broadcast. Each cue names a shot (wide, tracking, set_piece, attack,
// scorer, replay), its subject and its framing; the page computes the
// camera from the picture on screen, cuts where the track cuts and moves
// smoothly in between (a critically damped spring: the ball's 10 Hz steps
// do not shake it). A replay cue plays the goal again from the page's own
// history (net/timeshift.js), segment by segment from the cue's angles,
// marked REPLAY, then returns to the moment it left and catches up to live.
//
// No three.js and no DOM here but in Director.mark: the logic runs in node
// (tests/web/director_model.test.mjs).

const DEG = Math.PI / 180;
const SIDE = { left: 1, right: -1 };
const HALF_LENGTH = 52.5;

// The framing each shot uses when a cue carries none (the server's numbers).
export const DEFAULT_FRAMING = Object.freeze({
  wide: { distance: 62, height: 30, fov: 40, lead: 0 },
  tracking: { distance: 40, height: 17, fov: 26, lead: 9 },
  set_piece: { distance: 8, height: 3.2, fov: 50, lead: 0 },
  attack: { distance: 26, height: 10, fov: 30, lead: 5 },
  scorer: { distance: 4, height: 1.8, fov: 32, lead: 0 },
});
export const SHOTS = ['wide', 'tracking', 'set_piece', 'attack', 'scorer', 'replay'];
const ANGLES = ['behind_goal', 'low_side', 'high'];

// A "director" message as the page keeps it, or null when it is not one.
export function readCue(msg) {
  if (!msg || msg.type !== 'director' || !Number.isInteger(msg.seq) || !SHOTS.includes(msg.shot)) return null;
  const side = (s) => SIDE[s] ?? 0;
  const cue = {
    seq: msg.seq, time: msg.time ?? 0, cut: msg.cut !== false, shot: msg.shot,
    subject: msg.subject && SIDE[msg.subject.side] && msg.subject.unum > 0
      ? `${SIDE[msg.subject.side]}:${msg.subject.unum}` : null,
    attack: side(msg.attack), goal: side(msg.goal),
    framing: { ...(DEFAULT_FRAMING[msg.shot] ?? DEFAULT_FRAMING.tracking), ...(msg.framing ?? {}) },
    replay: null,
  };
  if (msg.shot === 'replay') {
    const segs = (Array.isArray(msg.replay) ? msg.replay : []).filter((s) =>
      Number.isInteger(s.from) && Number.isInteger(s.to) && s.from < s.to && ANGLES.includes(s.angle));
    if (!segs.length) return null;
    cue.replay = segs.map((s) => ({ from: s.from, to: s.to, angle: s.angle,
      speed: Math.max(0.1, Math.min(4, Number(s.speed) || 1)) }));
  }
  return cue;
}

// A critically damped spring on a 3-vector: x follows a moving target with
// continuous velocity and acceleration, settling in about 4/omega seconds.
// A target that moves in steps (the ball at 10 Hz) gives a smooth path.
export class SmoothDamp {
  constructor(omega = 2.5) {
    this.omega = omega;
    this.x = null;
    this.v = [0, 0, 0];
  }
  snap(target) { this.x = [...target]; this.v = [0, 0, 0]; return this.x; }
  // Exact step of x'' = -2w x' - w^2 (x - target) over dt seconds.
  step(target, dt) {
    if (!this.x) return this.snap(target);
    const w = this.omega, e = Math.exp(-w * dt);
    for (let i = 0; i < 3; i++) {
      const d = this.x[i] - target[i];
      const c = this.v[i] + w * d;
      this.x[i] = target[i] + (d + c * dt) * e;
      this.v[i] = (c - w * (d + c * dt)) * e;
    }
    return this.x;
  }
}

// Where the camera stands and looks for a shot, from the picture on screen.
// ctx: { shot, framing, ball:{x,y,z}, subject: {x,y,heading}|null, attack, goal,
//        angle (replays), field:{length,width}, aspect }
// Field coordinates (x along the pitch, y across, +y the main stand's side);
// returns scene coordinates { pos:[X,Y,Z], look:[X,Y,Z], fov } with X = x, Y up, Z = y.
export function shotRig(ctx) {
  const F = ctx.field ?? { length: 105, width: 68 };
  const halfW = F.width / 2, halfL = F.length / 2;
  const f = ctx.framing ?? DEFAULT_FRAMING[ctx.shot] ?? DEFAULT_FRAMING.tracking;
  const b = ctx.ball ?? { x: 0, y: 0, z: 0 };
  const bx = clamp(b.x, -halfL - 3, halfL + 3), by = clamp(b.y, -halfW - 3, halfW + 3);
  const portrait = (ctx.aspect ?? 1.78) < 1;
  const widen = portrait ? 1.5 : 1;   // a portrait screen sees less width: step back
  const dir = ctx.attack || 0;        // +1: towards +x
  const goalX = ctx.goal ? -ctx.goal * halfL : dir * halfL;  // the left team's goal is at -x
  const s = ctx.subject;

  switch (ctx.shot) {
    case 'wide': {
      const lx = bx * 0.35;
      return { pos: [lx, f.height * widen, halfW + f.distance * widen * 0.7], look: [lx, 0, by * 0.2], fov: f.fov };
    }
    case 'set_piece': {
      const px = s ? s.x : bx, py = s ? s.y : by;
      let dx = goalX - px, dy = -py;
      const n = Math.hypot(dx, dy) || 1;
      dx /= n; dy /= n;
      return { pos: [px - dx * f.distance, f.height, py - dy * f.distance],
        look: [px + dx * 16, 0.6, py + dy * 16], fov: f.fov * (portrait ? 1.2 : 1) };
    }
    case 'attack': {
      const lx = bx + (goalX - bx) * 0.35, ly = by * 0.7;
      const g = Math.sign(goalX) || 1;
      return { pos: [lx - g * f.distance * 0.3, f.height, Math.min(ly + f.distance * widen, halfW + f.distance)],
        look: [lx, 0.5, ly], fov: f.fov };
    }
    case 'scorer': {
      if (!s) return shotRig({ ...ctx, shot: 'tracking', framing: DEFAULT_FRAMING.tracking });
      // From the main stand's side, a little ahead of him: his body turns
      // (a goal's stoppage is spent looking around), the shot does not.
      const n = Math.hypot(0.5, 1);
      const fx = (dir || 1) * 0.5 / n, fy = 1 / n;
      return { pos: [s.x + fx * f.distance, f.height, s.y + fy * f.distance], look: [s.x, 1.1, s.y], fov: f.fov };
    }
    case 'replay': {
      const gx = ctx.goal ? -ctx.goal * halfL : (bx >= 0 ? halfL : -halfL);
      const g = Math.sign(gx) || 1;
      if (ctx.angle === 'low_side') {
        const z = halfW + 3;
        const d = Math.max(4, Math.abs(z - by));
        return { pos: [bx - g * 3, 1.3, z], look: [bx, 0.6, by], fov: clamp(2 * Math.atan(9 / d) / DEG, 14, 50) };
      }
      if (ctx.angle === 'high') return { pos: [bx, 38, halfW + 45], look: [bx, 0, by * 0.5], fov: 34 };
      // High behind the goal, looking out along the pitch: the goalmouth in
      // front, the play further out as far as the ball is (14 to 40 m).
      const out = clamp(Math.abs(bx - gx) * 0.6, 14, 40);
      return { pos: [gx + g * 9, 9, clamp(by * 0.25, -6, 6)], look: [gx - g * out, 0, by * 0.5], fov: portrait ? 66 : 55 };
    }
    case 'tracking':
    default: {
      const lx = bx + dir * f.lead, ly = by * 0.6;
      return { pos: [lx, f.height * (portrait ? 1.4 : 1), Math.max(ly + f.distance * widen, halfW + 6)],
        look: [lx, 0, ly], fov: f.fov * (portrait ? 1.6 : 1) };
    }
  }
}

function clamp(v, lo, hi) { return Math.max(lo, Math.min(hi, v)); }

// The director track and the replay state machine, on an abstract time
// shift (net/timeshift.js has this shape):
//   shift = { active, pos, enter(pos, paused) -> bool, live(), speed, hasRange(from, to) }
export class DirectorTrack {
  constructor({ maxCues = 20000, catchUp = 3, frameMs = 50 } = {}) {
    this.maxCues = maxCues;
    this.catchUp = catchUp;   // speed of the return to live, x the stream's rate
    this.frameMs = frameMs;
    this.reset();
  }

  reset() {
    this.cues = [];           // sorted by seq
    this.current = null;      // the cue on screen (never a replay)
    this.pin = null;          // after a replay: the shot to come back to
    this.phase = 'live';      // 'live' | 'replay' | 'catchup'
    this.replay = null;       // the replay cue being played
    this.segment = -1;
    this.clock = null;        // { at, pos, rate }: where the replay or catch-up should be by the clock
    this.lastPos = null;
    this.done = new Set();    // replay cues already played
    this.counts = { cues: 0, cuts: 0, replays: 0, segments: 0 };
    this.log = [];            // the last shots shown: { shot, seq, angle?, at }
  }

  // Keeps a cue; false when the message is not one.
  add(msg) {
    const cue = readCue(msg);
    if (!cue) return false;
    this.counts.cues++;
    const c = this.cues;
    if (c.length && cue.seq < c[c.length - 1].seq) {
      // The stream started again (a new session, a seek): a new track.
      if (c[c.length - 1].seq - cue.seq > 40) {
        const keepCounts = this.counts;
        this.reset();
        this.counts = keepCounts;
      }
    }
    let i = this.cues.length;
    while (i > 0 && this.cues[i - 1].seq > cue.seq) i--;
    this.cues.splice(i, 0, cue);
    if (this.cues.length > this.maxCues) this.cues.splice(0, this.cues.length - this.maxCues);
    return true;
  }

  // The last shot cue (not a replay) at or before seq.
  cueAt(seq) {
    for (let i = this.cues.length - 1; i >= 0; i--) {
      const c = this.cues[i];
      if (c.seq <= seq && c.shot !== 'replay') return c;
    }
    return null;
  }

  _show(cue, cut, now) {
    if (cue === this.current) return false;
    const jumped = !this.current || cut;
    this.current = cue;
    if (jumped) {
      this.counts.cuts++;
      this.log.push({ shot: cue.shot, seq: cue.seq, subject: cue.subject, at: now });
      if (this.log.length > 40) this.log.shift();
    }
    return jumped;
  }

  // Once per drawn picture. pos: the seq of the picture on screen (the
  // playhead); shift: the time shift; enabled: the director drives the
  // camera (replays only then); streamSpeed: the stream's rate, x real time.
  // Returns { cut, jumped } : cut = the camera must cut; jumped = the picture
  // left a replay for the user's own time shift or for live at once (no kick
  // sounds for the jump). While `replaying`, the page plays no events at all
  // (a silent replay), so that catching up from the replay cue afterwards
  // goes on from where the sounds and banners stopped.
  update(pos, shift, { enabled = true, streamSpeed = 1, now = 0 } = {}) {
    let cut = false, jumped = false;
    // Replays and the catch-up keep to the clock however slowly the page
    // draws (a time shift alone moves at most 250 ms a picture).
    if (this.clock && shift.active && this.phase !== 'live') {
      const want = this.clock.pos + ((now - this.clock.at) / this.frameMs) * this.clock.rate;
      if (shift.pos < want) shift.pos = want;
    }
    if (this.phase === 'replay') {
      const r = this.replay, seg = r.replay[this.segment];
      if (!shift.active || !enabled) {
        // Ended from outside (a manual camera, the user's own time shift).
        this.phase = 'live';
        this.replay = null;
        this.clock = null;
        if (shift.active && !enabled) shift.live();
        return { cut: true, jumped: true };
      }
      if (shift.pos >= r.seq + seg.to) {
        // A slow page sees the end late: the overshoot is carried on, so
        // that the replay lasts what it should at any picture rate.
        const rate = seg.speed * Math.max(0.25, streamSpeed);
        const over = Math.max(0, Math.min(2000, ((shift.pos - (r.seq + seg.to)) / rate) * this.frameMs));
        now -= over;
        this.segment++;
        if (this.segment < r.replay.length) {
          this._enterSegment(shift, streamSpeed, now);
        } else {
          // Back to where live was left, then catching up.
          this.phase = 'catchup';
          shift.enter(r.seq, false);
          shift.speed = this.catchUp * Math.max(1, streamSpeed);
          this.clock = { at: now, pos: r.seq, rate: shift.speed };
          this.pin = this.cues.find((c) => c.seq > r.seq && c.shot !== 'replay') ?? this.current;
          if (this.pin) this._show(this.pin, true, now);
          this.lastPos = r.seq;
          this.replay = null;
        }
        return { cut: true, jumped: false };
      }
      return { cut: false, jumped: false };
    }
    if (this.phase === 'catchup' && !shift.active) { this.phase = 'live'; this.clock = null; }

    const prev = this.lastPos ?? pos;
    this.lastPos = pos;
    // The picture jumped (a seek, a resync; not a fast stream drawn slowly):
    // the camera cuts, and no replay is started for what was jumped over.
    // Sounds and banners are the announcer's business (it has its own rule).
    const leap = Math.abs(pos - prev) > 60 * Math.max(1, streamSpeed) + 40;
    // A replay cue passed while watching live: play it.
    if (this.phase === 'live' && enabled && !shift.active && !leap) {
      for (const c of this.cues) {
        if (c.shot !== 'replay' || c.seq <= prev || c.seq > pos || this.done.has(c.seq)) continue;
        this.done.add(c.seq);
        const from = c.seq + c.replay[0].from, to = c.seq + c.replay[c.replay.length - 1].to;
        if (!shift.hasRange(from, to)) continue;   // joined too late to have it
        this.replay = c;
        this.segment = 0;
        this.phase = 'replay';
        this.counts.replays++;
        // Live pauses here: the replay is watched, then the catch-up.
        this._enterSegment(shift, streamSpeed, now);
        return { cut: true, jumped: false };
      }
    }
    if (this.pin && pos >= this.pin.seq) this.pin = null;
    const cue = this.pin ?? this.cueAt(pos);
    if (cue && this._show(cue, cue.cut || leap, now)) cut = true;
    return { cut, jumped };
  }

  _enterSegment(shift, streamSpeed, now) {
    const r = this.replay, seg = r.replay[this.segment];
    shift.enter(r.seq + seg.from, false);
    shift.speed = seg.speed * Math.max(0.25, streamSpeed);
    this.clock = { at: now, pos: r.seq + seg.from, rate: shift.speed };
    this.counts.segments++;
    this.log.push({ shot: 'replay', angle: seg.angle, seq: r.seq, at: now });
    if (this.log.length > 40) this.log.shift();
  }

  // The shot to draw now: { shot, subject, attack, goal, framing, angle }.
  shot() {
    if (this.phase === 'replay' && this.replay) {
      const r = this.replay;
      return { shot: 'replay', subject: r.subject, attack: r.attack, goal: r.goal,
        framing: null, angle: r.replay[this.segment]?.angle ?? 'behind_goal' };
    }
    const c = this.current;
    if (!c) return { shot: 'tracking', subject: null, attack: 0, goal: 0, framing: DEFAULT_FRAMING.tracking };
    return { shot: c.shot, subject: c.subject, attack: c.attack, goal: c.goal, framing: c.framing };
  }

  get replaying() { return this.phase === 'replay'; }
}

// The page's time shift (net/timeshift.js) as DirectorTrack drives it;
// get() returns the one in use (the page may swap it).
export function timeshiftPort(get) {
  return {
    get active() { return get().active; },
    get pos() { return get().pos; },
    set pos(v) { get().pos = v; },
    set speed(v) { get().speed = v; },
    get speed() { return get().speed; },
    enter: (pos, paused) => get().enter(pos, paused),
    live: () => get().live(),
    // The history holds [from, to] from a keyframe on.
    hasRange: (from, to) => {
      const ts = get();
      if (typeof ts.hasRange === 'function') return ts.hasRange(from, to);
      return Array.isArray(ts.entries) && ts.entries.length > 0 && !!ts.makeCodec &&
        typeof ts._firstKeySeq === 'function' && ts._firstKeySeq() <= from && ts.last >= to;
    },
  };
}

// The director on the page: the track, the camera it drives, the REPLAY mark.
export class Director {
  // timeshift: () => the page's time shift in use.
  constructor(timeshift) {
    this.track = new DirectorTrack();
    this.shift = timeshiftPort(timeshift);
    this.pos = new SmoothDamp(1.8);
    this.look = new SmoothDamp(3);
    this.fov = null;
    this.cutPending = true;
    this.enabled = true;       // the camera mode is 'director'
    this.mark = null;
  }

  cue(msg) { return this.track.add(msg); }

  // Before sampling the picture: pos = the playhead (seq units).
  update(pos, { streamSpeed = 1, now = 0 } = {}) {
    if (pos === null || pos === undefined || !Number.isFinite(pos)) return { cut: false, jumped: false };
    const r = this.track.update(pos, this.shift, { enabled: this.enabled, streamSpeed, now });
    if (r.cut) this.cutPending = true;
    this._mark(this.enabled && this.track.replaying);
    return r;
  }

  // The user took the time shift (pause, seek, goal jumps): no director replay now.
  userShift() {
    const t = this.track;
    if (t.phase !== 'live') { t.phase = 'live'; t.replay = null; t.pin = null; t.clock = null; }
    this._mark(false);
  }

  setEnabled(on) {
    if (on && !this.enabled) this.cutPending = true;
    this.enabled = on;
    if (!on) this._mark(false);
  }

  // Moves the three.js camera `cam` for this picture. view: { ball (field
  // coordinates), players (scene/players.js) }; field: { length, width }.
  drive(cam, dt, view, aspect, field) {
    const s = this.track.shot();
    let subject = null;
    const rig = s.subject && view.players ? view.players.get(s.subject) : null;
    if (rig?.pose && rig.pose.state !== 0) subject = { x: rig.pose.x, y: rig.pose.y, heading: rig.pose.heading };
    const r = shotRig({ ...s, subject, ball: view.ball, field, aspect });
    let p, l;
    if (this.cutPending) {
      p = this.pos.snap(r.pos);
      l = this.look.snap(r.look);
      this.fov = r.fov;
      this.cutPending = false;
    } else {
      p = this.pos.step(r.pos, dt);
      l = this.look.step(r.look, dt);
      this.fov += (r.fov - this.fov) * (1 - Math.exp(-dt * 2));
    }
    cam.position.set(p[0], Math.max(0.4, p[1]), p[2]);
    cam.up.set(0, 1, 0);
    cam.fov = this.fov;
    cam.updateProjectionMatrix();
    cam.lookAt(l[0], l[1], l[2]);
  }

  _mark(on) {
    if (typeof document === 'undefined') return;
    if (!this.mark) {
      if (!on) return;
      this.mark = document.createElement('div');
      this.mark.id = 'replay-mark';
      this.mark.textContent = 'REPLAY';
      this.mark.setAttribute('role', 'status');
      document.body.appendChild(this.mark);
    }
    if (this.mark.hidden === !on) return;
    this.mark.hidden = !on;
  }

  stats() {
    const t = this.track, s = t.shot();
    return { enabled: this.enabled, phase: t.phase, shot: s.shot, angle: s.angle ?? null, subject: s.subject,
      replaying: t.replaying, mark: !!this.mark && !this.mark.hidden, ...t.counts, log: t.log.slice(),
      received: t.cues.slice(0, 4).map((c) => ({ seq: c.seq, shot: c.shot, cut: c.cut })) };
  }
}
