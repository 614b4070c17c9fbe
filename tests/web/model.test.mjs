// The page's pure logic, in node: the jitter buffer (ordering, gaps, resync,
// playhead behind the newest frame), frame interpolation, and the events
// the picture fires (kick, goal, card, foul).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const WEB = process.env.MATCHCAST_WEB_DIR ?? path.resolve(import.meta.dirname, '../../web');
const load = (p) => import(pathToFileURL(path.join(WEB, p)).href);
const { JitterBuffer } = await load('src/net/jitter.js');
const { blendFrames, lerpAngle } = await load('src/model/interp.js');
const { EventDetector } = await load('src/model/events.js');
const { Announcer } = await load('src/announcer.js');
const { normalizeSkeleton } = await load('src/model/skeleton.js');

const frame = (seq, extra = {}) => ({
  seq, time: seq >> 1, stoppage: 0, playMode: 3, scoreLeft: 0, scoreRight: 0,
  ball: { x: seq, y: 0, z: 0 },
  players: [{ side: 1, unum: 1, state: 1, x: seq * 0.1, y: 0, z: 1, heading: 0, angles: Float32Array.of(seq) }],
  ...extra,
});

test('the playhead runs a few frames behind the newest and interpolates', () => {
  const jb = new JitterBuffer({ frameMs: 50, delayFrames: 3 });
  let now = 0;
  for (let s = 100; s < 110; s++) { jb.push(frame(s), now); now += 50; }
  now -= 50;
  let r = jb.sample(now);
  assert.ok(Math.abs(jb.playhead - 106) < 1e-9, `playhead ${jb.playhead}`);
  // Steady arrivals: the playhead advances at the stream's rate.
  for (let s = 110; s < 130; s++) {
    now += 50; jb.push(frame(s), now);
    r = jb.sample(now + 25);
  }
  assert.ok(r.b.seq === r.a.seq + 1 && r.t >= 0 && r.t <= 1);
  assert.ok(jb.lagMs() > 50 && jb.lagMs() < 250, `lag ${jb.lagMs()}`);
});

test('seq gaps count as dropped; a big jump resyncs', () => {
  const jb = new JitterBuffer();
  jb.push(frame(1), 0);
  jb.push(frame(4), 50);
  assert.equal(jb.dropped, 2);
  jb.push(frame(5000), 100);
  assert.equal(jb.size, 1);
  assert.equal(jb.resyncs, 1);
  assert.equal(jb.push(frame(5000), 120), false, 'duplicates are ignored');
});

test('a frame that arrives late but ahead of the playhead is inserted in order', () => {
  const jb = new JitterBuffer();
  jb.push(frame(10), 0);
  jb.push(frame(12), 50);
  jb.push(frame(11), 60);
  assert.deepEqual(jb.frames.map((f) => f.seq), [10, 11, 12]);
  assert.equal(jb.dropped, 0);
});

test('a stalled renderer never loses stream frames and catches up by resync', () => {
  const jb = new JitterBuffer({ capacity: 1000 });
  for (let s = 0; s < 10; s++) jb.push(frame(s), s * 50);
  jb.sample(450);
  for (let s = 10; s < 400; s++) jb.push(frame(s), s * 50);
  assert.ok(jb.size >= 390, 'every new frame kept while the renderer sleeps');
  const r = jb.sample(400 * 50);
  assert.ok(r.a.seq >= 395, `jumped to the present (${r.a.seq})`);
});

test('interpolation blends positions and angles and turns the short way', () => {
  const out = blendFrames(frame(10), frame(20), 0.5);
  assert.equal(out.ball.x, 15);
  assert.ok(Math.abs(out.players[0].angles[0] - 15) < 1e-6);
  assert.equal(lerpAngle(170, -170, 0.5), 180);
  assert.equal(lerpAngle(-10, 10, 0.5), 0);
});

test('events fire once on their edge', () => {
  const ev = new EventDetector();
  assert.deepEqual(ev.step(frame(1)), []);
  const kick = frame(2);
  kick.players[0].state = 3;
  assert.deepEqual(ev.step(kick).map((e) => e.type), ['kick']);
  const still = frame(3);
  still.players[0].state = 3;
  assert.deepEqual(ev.step(still), []);
  assert.deepEqual(ev.step(frame(4, { playMode: 14, scoreLeft: 1 })).map((e) => e.type), ['goal']);
  assert.deepEqual(ev.step(frame(5, { playMode: 24 })).map((e) => e.type), ['foul']);
  const card = frame(6, { playMode: 24 });
  card.players[0].state = 1 | 0x40000;
  assert.deepEqual(ev.step(card).map((e) => e.color), ['yellow']);
});

test('a foul gives the free kick to the team the mode does not name', () => {
  // rcssserver's infringement modes name the team that committed it:
  // foul_charge_r is followed by free_kick_l (issue 20's foul banner).
  const ev = new EventDetector();
  ev.step(frame(1));
  const cases = [[24, 'r', 'l'], [25, 'l', 'r'], [32, 'r', 'l'], [33, 'l', 'r'], [17, null, null]];
  let seq = 2;
  for (const [mode, side, offender] of cases) {
    const out = ev.step(frame(seq++, { playMode: mode }));
    ev.step(frame(seq++));  // back to play on
    if (side === null) { assert.deepEqual(out, [], `mode ${mode}`); continue; }
    assert.deepEqual(out.map((e) => [e.type, e.side, e.offender]), [['foul', side, offender]], `mode ${mode}`);
  }
  // The banner names that team.
  const banners = [];
  const hud = { teams: { 1: { name: 'HELIOS_A' }, [-1]: { name: 'HELIOS_B' } }, banner: (text) => banners.push(text) };
  const announcer = new Announcer(hud, { kick() {} });
  announcer.step([frame(100), frame(101, { playMode: 25 }), frame(102), frame(103, { playMode: 32 })], null, 20);
  assert.deepEqual(banners, ['Foul: free kick HELIOS_A', 'Foul: free kick HELIOS_B']);
});

test('the skeleton is read from the hello and bad ones are refused', () => {
  const sk = normalizeSkeleton({ joints: [
    { name: 'pelvis', parent: -1, offset: [0, 0, 0], dofs: 'zxy', segment: { shape: 'box', size: [1, 1, 1], center: [0, 0, 0] } },
    { name: 'head', parent: 0, offset: [0, 1, 0], dofs: 'y', segment: { shape: 'sphere', size: [0.1, 0, 0], center: [0, 0, 0] } }] });
  assert.equal(sk.dofCount, 4);
  assert.equal(sk.joints[1].angleIndex, 3);
  assert.throws(() => normalizeSkeleton({ joints: [{ parent: 1 }] }));
  assert.throws(() => normalizeSkeleton({}));
});

test('the playhead follows a stream that runs faster than real time', () => {
  const jb = new JitterBuffer({ frameMs: 50, delayFrames: 3 });
  let now = 0, seq = 0;
  // 4x: a frame every 12.5 ms, the renderer at 60 Hz.
  for (let ms = 0; ms < 3000; ms += 1) {
    if (ms % 12.5 < 1) jb.push(frame(seq++), ms);
    if (ms % 16 === 0) jb.sample(ms);
    now = ms;
  }
  assert.ok(Math.abs(jb.speed - 4) < 0.3, `speed ${jb.speed}`);
  assert.ok(jb.newest.seq - jb.playhead < 30, `playhead keeps up (${jb.newest.seq - jb.playhead} behind)`);
  assert.ok(jb.resyncs <= 1, `no repeated resyncs (${jb.resyncs})`);
  assert.ok(now > 0);
});

test('time shift: pause, seek back, jump to a goal, catch up with live', async () => {
  const { TimeShift } = await load('src/net/timeshift.js');
  // A fake codec: "bytes" are the frames themselves; deltas need their base.
  const makeCodec = () => {
    let last = null;
    return { decode(b) {
      if (!b.keyframe && (last === null || b.seq !== last + 1)) { last = null; throw new Error('without its base'); }
      last = b.seq;
      return b;
    } };
  };
  const ts = new TimeShift({ frameMs: 50 });
  ts.reset(makeCodec);
  for (let s = 100; s < 700; s++) {
    const f = { ...frame(s, { playMode: s >= 400 && s < 420 ? 14 : 3 }), keyframe: s % 20 === 0 };
    f.byteLength = 100;
    ts.record(f, f);
  }
  assert.deepEqual(ts.goals, [400]);
  assert.equal(ts.first, 100);
  assert.ok(ts.enter(690, true));
  let r = ts.sample(0);
  assert.equal(r.a.seq, 690, 'paused where it was entered');
  r = ts.sample(1000);
  assert.equal(r.a.seq, 690, 'still paused');
  ts.seek(0.5);
  r = ts.sample(1000);
  assert.ok(Math.abs(r.a.seq - 400) <= 1, 'half-way through the history');
  assert.ok(ts.jumpGoal(-1) === false || ts.pos < 400, 'no goal before');
  ts.paused = false;
  ts.seek(0);
  assert.ok(ts.jumpGoal(1));
  assert.equal(ts.pos, 300, '5 s before the goal');
  for (let now = 2000; now <= 2500; now += 100) r = ts.sample(now);
  assert.ok(Math.abs(r.a.seq - 310) <= 1, `plays on at 1x (${r.a.seq})`);
  ts.speed = 4;
  for (let now = 2500; ts.active && now < 60000; now += 16) ts.sample(now);
  assert.equal(ts.active, false, 'caught up with live');
});

test('stream events play once, at their contact time, and not across jumps', async () => {
  const { EventTrack } = await load('src/model/eventtrack.js');
  const tr = new EventTrack({ frameMs: 50 });
  tr.add({ type: 'goal', seq: 30 });
  tr.add({ type: 'kick', seq: 20, contact_time_ms: 1025 });   // 20.5 frames
  assert.deepEqual(tr.due(10), []);
  assert.deepEqual(tr.due(20.4), []);
  assert.deepEqual(tr.due(21).map((e) => e.ev.type), ['kick']);
  assert.deepEqual(tr.due(21.5), []);
  assert.deepEqual(tr.due(35).map((e) => e.ev.type), ['goal']);
  tr.due(0);                                   // a seek back: replays play them again
  assert.deepEqual(tr.due(21).map((e) => e.ev.type), ['kick']);
  tr.jump();
  assert.deepEqual(tr.due(30), [], 'right after a jump nothing plays');
  assert.deepEqual(tr.due(100), [], 'a big step forward plays nothing');
  assert.ok(tr.seen.has('kick'));
});
