// The page's feet between frames (web/src/model/feet.js; proto/SPEC.md 4.7
// step 2) against the golden vectors that anim/leg_blend.cpp also passes
// (tests/proto/golden/feet_v1.json, LegBlend.GoldenVectorsForTheClients).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const WEB = process.env.MATCHCAST_WEB_DIR ?? path.resolve(import.meta.dirname, '../../web');
const ROOT = process.env.MATCHCAST_REPO_ROOT ?? path.resolve(import.meta.dirname, '../..');
const load = (p) => import(pathToFileURL(path.join(WEB, p)).href);
const { keepFeetOfPlayer, keepFeet, findLegs, jointAngles } = await load('src/model/feet.js');
const { normalizeSkeleton } = await load('src/model/skeleton.js');
const { blendFrames } = await load('src/model/interp.js');

const golden = JSON.parse(fs.readFileSync(path.join(ROOT, 'tests/proto/golden/feet_v1.json'), 'utf8'));
const skel = normalizeSkeleton(golden.skeleton);
const pose = (p) => ({ side: 1, unum: 7, state: 1, x: p.x, y: p.y, z: p.z, heading: p.heading, angles: Float32Array.from(p.angles) });

test('every golden case comes out as the C++ step makes it', () => {
  assert.ok(findLegs(skel), 'the hello skeleton has two legs');
  let moved = 0, apart = 0;
  for (const [i, c] of golden.cases.entries()) {
    const o = pose(c.drawn);
    keepFeetOfPlayer(skel, pose(c.a), pose(c.b), c.t, o);
    let changed = false;
    for (let k = 0; k < c.out.length; k++) {
      // 0.002 deg: the page computes in doubles, the C++ step in floats;
      // four rounds of turning the legs apart carry that difference to
      // 0.0012 deg on case 75 (a foot landing past the other).
      assert.ok(Math.abs(o.angles[k] - c.out[k]) < 0.002, `case ${i} dof ${k}: ${o.angles[k]} vs ${c.out[k]}`);
      changed ||= Math.abs(o.angles[k] - c.drawn.angles[k]) > 1e-3;
    }
    moved += changed;
    if (i >= 48) apart += changed;
  }
  assert.ok(moved > 12, `the cases move legs (${moved})`);
  assert.ok(apart >= 8, `cases 48-79 turn a leg out of the other's way (${apart})`);
});

test('frames, teleports and a skeleton without legs are left alone', () => {
  const c = golden.cases.find((k) => k.out.some((v, i) => Math.abs(v - k.drawn.angles[i]) > 0.01));
  const frame = (p) => ({ ball: { x: 0, y: 0, z: 0 }, players: [pose(p)] });
  const a = frame(c.a), b = frame(c.b);
  for (const t of [0, 1]) {
    const out = blendFrames(a, b, t);
    const before = Array.from(out.players[0].angles);
    keepFeet(skel, a, b, t, out);
    assert.deepEqual(Array.from(out.players[0].angles), before);
  }
  // A move at kick-off: 6 m between the frames.
  const far = frame({ ...c.b, x: c.a.x + 6 });
  const out = blendFrames(a, far, 0.5);
  const before = Array.from(out.players[0].angles);
  keepFeet(skel, a, far, 0.5, out);
  assert.deepEqual(Array.from(out.players[0].angles), before);
  // A drawn frame between them is changed: what the step is for.
  const mid = blendFrames(a, b, c.t);
  const plain = Array.from(mid.players[0].angles);
  keepFeet(skel, a, b, c.t, mid);
  assert.notDeepEqual(Array.from(mid.players[0].angles), plain);
  // No legs: nothing happens.
  const armless = normalizeSkeleton({ joints: [{ name: 'root', parent: -1, offset: [0, 0, 0], dofs: 'y' }] });
  assert.equal(findLegs(armless), null);
});

test("a hello's garbage or upside-down thigh limits give finite angles", () => {
  const c = golden.cases.find((k) => k.out.some((v, i) => Math.abs(v - k.drawn.angles[i]) > 0.01));
  const def = structuredClone(golden.skeleton);
  const thigh = def.joints.findIndex((j) => j.name === 'r_thigh');
  def.joints[thigh].limits = [[10, -10], ['x', 1], null];
  const bad = normalizeSkeleton(def);
  const o = pose(c.drawn);
  keepFeetOfPlayer(bad, pose(c.a), pose(c.b), c.t, o);
  const at = bad.joints[thigh].angleIndex;
  assert.ok(Array.from(o.angles).every(Number.isFinite), 'every angle finite');
  assert.equal(o.angles[at], 10, 'an upside-down limit holds at its bottom');
});

test('joint angles undo a rotation in every order', () => {
  const DEG = Math.PI / 180;
  const rot = (axis, d) => {
    const c = Math.cos(d * DEG), s = Math.sin(d * DEG);
    if (axis === 'x') return [1, 0, 0, 0, c, -s, 0, s, c];
    if (axis === 'y') return [c, 0, s, 0, 1, 0, -s, 0, c];
    return [c, -s, 0, s, c, 0, 0, 0, 1];
  };
  const mul = (a, b) => Array.from({ length: 9 }, (_, i) => a[3 * Math.floor(i / 3)] * b[i % 3] +
    a[3 * Math.floor(i / 3) + 1] * b[3 + i % 3] + a[3 * Math.floor(i / 3) + 2] * b[6 + i % 3]);
  for (const order of ['xyz', 'yzx', 'zxy', 'xzy', 'zyx', 'yxz']) {
    for (const ang of [[10, 20, 30], [-120, 80, 170], [45, -60, -5]]) {
      const r = mul(mul(rot(order[0], ang[0]), rot(order[1], ang[1])), rot(order[2], ang[2]));
      const back = jointAngles(order, r, [0, 0, 0]);
      for (let k = 0; k < 3; k++) assert.ok(Math.abs(back[k] - ang[k]) < 1e-6, `${order} ${ang} -> ${back}`);
    }
  }
});
