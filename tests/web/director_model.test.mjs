// The page's director logic in node (web/src/director.js): reading cues,
// the smoothing spring, the shot rigs, and the track's state machine (cuts
// by seq, the replay's segments on a time shift, the catch-up, overrides).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const WEB = process.env.MATCHCAST_WEB_DIR ?? path.resolve(import.meta.dirname, '../../web');
const { readCue, SmoothDamp, shotRig, DirectorTrack } =
  await import(pathToFileURL(path.join(WEB, 'src/director.js')).href);

const cue = (seq, shot, extra = {}) => ({ type: 'director', seq, time: seq >> 1, cut: true, shot, ...extra });
const replayCue = (seq) => cue(seq, 'replay', {
  goal: 'left', attack: 'right', subject: { side: 'right', unum: 9 },
  replay: [{ from: -240, to: -120, angle: 'behind_goal', speed: 1 }, { from: -120, to: -50, angle: 'low_side', speed: 0.6 }],
});

test('a director message becomes a cue; anything else is refused', () => {
  const c = readCue(cue(100, 'set_piece', { subject: { side: 'right', unum: 10 }, attack: 'right', goal: 'left',
    framing: { distance: 8, height: 3.2, fov: 50, lead: 0 } }));
  assert.equal(c.subject, '-1:10');
  assert.equal(c.attack, -1);
  assert.equal(c.goal, 1);
  assert.equal(c.framing.distance, 8);
  assert.equal(readCue(cue(1, 'dolly')), null);
  assert.equal(readCue({ type: 'kick', seq: 1 }), null);
  assert.equal(readCue(cue(1, 'replay', { replay: [{ from: 5, to: 2, angle: 'low_side', speed: 1 }] })), null);
  assert.deepEqual(readCue(cue(1, 'tracking')).framing, { distance: 40, height: 17, fov: 26, lead: 9 }, 'default framing');
});

test('the spring follows a ball moving in 10 Hz steps without jerks', () => {
  // The target: a ball that moves 1 m every 100 ms (10 Hz), sampled at 60 Hz.
  const s = new SmoothDamp(1.8);
  const dt = 1 / 60;
  let prevV = null, worstTarget = 0, worstCam = 0, prevTargetV = null, prevX = null;
  let prevTarget = 0;
  for (let i = 0; i < 600; i++) {
    const t = i * dt;
    const target = Math.floor(t * 10);   // steps of 1 m
    const x = s.step([target, 0, 0], dt)[0];
    if (prevX !== null) {
      const v = (x - prevX) / dt, tv = (target - prevTarget) / dt;
      if (prevV !== null && i > 60) {
        worstCam = Math.max(worstCam, Math.abs(v - prevV) / dt);
        worstTarget = Math.max(worstTarget, Math.abs(tv - prevTargetV) / dt);
      }
      prevV = v; prevTargetV = tv;
    }
    prevX = x; prevTarget = target;
  }
  assert.ok(worstCam < 40, `camera acceleration ${worstCam.toFixed(1)} m/s²`);
  assert.ok(worstCam < worstTarget / 50, `${worstCam} vs the steps' ${worstTarget}`);
  // It arrives: the lag behind a steady 10 m/s is bounded (2 / omega seconds).
  assert.ok(Math.abs(prevX - (prevTarget - 10 * 2 / 1.8)) < 1.5, `lag ${prevTarget - prevX}`);
  // A snap is a cut: exactly there, at rest.
  assert.deepEqual(s.snap([5, 6, 7]), [5, 6, 7]);
  assert.deepEqual(s.v, [0, 0, 0]);
});

test('each shot frames its subject as described', () => {
  const field = { length: 105, width: 68 };
  const ball = { x: 10, y: 5, z: 0 };
  const tr = shotRig({ shot: 'tracking', framing: { distance: 40, height: 17, fov: 26, lead: 9 }, ball, attack: 1, field, aspect: 16 / 9 });
  assert.ok(tr.look[0] > ball.x, 'the play ahead of the ball (left attacks +x)');
  assert.ok(tr.pos[2] > field.width / 2, 'from the main stand');
  const tl = shotRig({ shot: 'tracking', framing: { distance: 40, height: 17, fov: 26, lead: 9 }, ball, attack: -1, field, aspect: 16 / 9 });
  assert.ok(tl.look[0] < ball.x, 'the right team attacks -x');
  const sp = shotRig({ shot: 'set_piece', framing: { distance: 8, height: 3.2, fov: 50, lead: 0 }, ball: { x: -52, y: 33, z: 0 },
    subject: { x: -51, y: 32, heading: 0 }, attack: -1, goal: 1, field });
  // Behind the taker: the taker lies between the camera and the goal he attacks (-x).
  const toGoal = [-52.5 - -51, 0 - 32];
  const toCam = [sp.pos[0] - -51, sp.pos[2] - 32];
  assert.ok(toGoal[0] * toCam[0] + toGoal[1] * toCam[1] < 0, 'behind the taker');
  assert.ok(sp.pos[1] < 5, 'at eye level');
  const at = shotRig({ shot: 'attack', framing: { distance: 26, height: 10, fov: 30, lead: 5 }, ball: { x: 35, y: 0, z: 0 }, attack: 1, goal: -1, field });
  assert.ok(at.look[0] > 35, 'towards the goal');
  assert.ok(Math.hypot(at.pos[0] - at.look[0], at.pos[2] - at.look[2]) < Math.hypot(tr.pos[0] - tr.look[0], tr.pos[2] - tr.look[2]), 'tighter than tracking');
  const bg = shotRig({ shot: 'replay', angle: 'behind_goal', ball: { x: -40, y: 0, z: 0 }, goal: 1, field });
  assert.ok(bg.pos[0] < -52.5, 'behind the left goal');
  const low = shotRig({ shot: 'replay', angle: 'low_side', ball: { x: -40, y: 0, z: 0 }, goal: 1, field });
  assert.ok(low.pos[1] < 2 && low.pos[2] > 34, 'low, at the touchline');
});

// A time shift as net/timeshift.js behaves for the director: a position that
// moves at `speed` frames per frame-time, and live at `last`.
function fakeShift(last) {
  return {
    active: false, pos: 0, speed: 1, last, first: 0, entered: [],
    enter(pos) { this.active = true; this.pos = pos; this.entered.push(pos); return true; },
    live() { this.active = false; this.speed = 1; },
    hasRange(from, to) { return from >= this.first && to <= this.last; },
    advance(ms) { if (this.active) { this.pos += ms / 50 * this.speed; if (this.pos >= this.last - 3) this.live(); } },
  };
}

test('cuts follow the picture, and a goal replays, then catches up with live', () => {
  const t = new DirectorTrack();
  for (const c of [cue(0, 'wide'), cue(60, 'tracking'), cue(500, 'attack'), cue(560, 'scorer', { subject: { side: 'right', unum: 9 } }),
    replayCue(620), cue(622, 'wide')]) t.add(c);
  const shift = fakeShift(0);
  let now = 0;
  const shots = [];
  const step = (pos) => {
    shift.last = Math.max(shift.last, pos + 3);
    const r = t.update(pos, shift, { now, streamSpeed: 1 });
    now += 50;
    shift.advance(50);
    const s = t.shot();
    const name = s.angle ? `replay:${s.angle}` : s.shot;
    if (!shots.length || shots[shots.length - 1] !== name) shots.push(name);
    return r;
  };
  let live = 0;
  for (; live < 600; live++) {
    step(live);
    assert.ok(!t.replaying, 'no replay before its cue');
  }
  assert.deepEqual(shots, ['wide', 'tracking', 'attack', 'scorer']);
  // Live passes the replay cue: the picture goes back to the goal.
  let r = null;
  for (; live < 640 && !t.replaying; live++) r = step(live);
  assert.ok(t.replaying);
  assert.ok(r.cut && !r.jumped, "a cut; the picture is silent while replaying (no events.jump)");
  assert.equal(shift.entered[0], 620 - 240, 'the first segment starts 12 s before the cue');
  // While replaying, live goes on (the playhead would) but the picture is the history's.
  let frames = 0;
  while (t.replaying && frames < 1000) {
    shift.last++;
    t.update(shift.pos, shift, { now, streamSpeed: 1 });
    now += 50;
    shift.advance(50);
    const s = t.shot();
    const name = s.angle ? `replay:${s.angle}` : s.shot;
    if (shots[shots.length - 1] !== name) shots.push(name);
    frames++;
  }
  // 120 frames at 1x, then 70 at 0.6x: 237 frames' time.
  assert.ok(frames > 220 && frames < 250, `the replay took ${frames} frames`);
  assert.equal(t.phase, 'catchup');
  assert.equal(shift.entered[2], 620, 'back to where live was left');
  assert.ok(shift.speed >= 3, 'catching up faster than live');
  assert.deepEqual(shots.slice(-3), ['replay:behind_goal', 'replay:low_side', 'wide'], 'then the shot after the replay');
  // Catching up ends at live.
  let n = 0;
  while (shift.active && n++ < 1000) { shift.last++; t.update(shift.pos, shift, { now, streamSpeed: 1 }); now += 50; shift.advance(50); }
  t.update(shift.last - 3, shift, { now });
  assert.equal(t.phase, 'live');
  assert.ok(n < 200, `caught up in ${n} frames`);
  assert.equal(t.counts.replays, 1);
  // The same replay cue is not played twice (a rewind over it).
  t.update(600, shift, { now });
  t.update(630, shift, { now });
  assert.equal(t.counts.replays, 1);
});

test('without the director on screen, or without the history, no replay', () => {
  const off = new DirectorTrack();
  off.add(replayCue(620));
  const shift = fakeShift(700);
  off.update(600, shift, { enabled: true });
  shift.first = 500;   // joined after the goal's build-up
  off.update(630, shift, { enabled: true });
  assert.equal(off.replaying, false);
  const manual = new DirectorTrack();
  manual.add(replayCue(620));
  const s2 = fakeShift(700);
  manual.update(600, s2, { enabled: false });
  manual.update(630, s2, { enabled: false });
  assert.equal(manual.replaying, false);
  // A manual camera in the middle of a replay ends it and returns to live.
  const mid = new DirectorTrack();
  mid.add(replayCue(620));
  const s3 = fakeShift(700);
  mid.update(600, s3, {});
  mid.update(630, s3, {});
  assert.equal(mid.replaying, true);
  mid.update(s3.pos, s3, { enabled: false });
  assert.equal(mid.replaying, false);
  assert.equal(s3.active, false);
});

test('a slow page still plays the replay on time (the clock paces it)', () => {
  const t = new DirectorTrack();
  t.add(replayCue(620));
  const shift = fakeShift(700);
  t.update(600, shift, { now: 0 });
  t.update(630, shift, { now: 0 });
  assert.equal(t.replaying, true);
  // One picture a second: the shift itself would move 250 ms a picture.
  let now = 0, pictures = 0;
  while (t.replaying && pictures < 100) {
    now += 1000;
    shift.pos += 5 * shift.speed;   // TimeShift.sample's 250 ms cap
    t.update(shift.pos, shift, { now });
    pictures++;
  }
  assert.ok(pictures >= 11 && pictures <= 14, `12 s of replay took ${pictures} one-second pictures`);
});
