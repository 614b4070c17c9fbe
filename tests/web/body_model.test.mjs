// The bodies' pure logic in node: the head and neck at human speed
// (web/src/model/neck.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const WEB = process.env.MATCHCAST_WEB_DIR ?? path.resolve(import.meta.dirname, '../../web');
const load = (p) => import(pathToFileURL(path.join(WEB, p)).href);
const { limitTurn, HeadSmoother, MAX_HEAD_DEG_PER_S } = await load('src/model/neck.js');
const { normalizeSkeleton } = await load('src/model/skeleton.js');

// The server's skeleton's first joints (anim/human_skeleton.cpp): pelvis,
// torso, neck, head, an arm joint.
const skel = normalizeSkeleton({ joints: [
  { name: 'pelvis', parent: -1, offset: [0, 0, 0], dofs: 'yzx' },
  { name: 'torso', parent: 0, offset: [0, 0.08, 0], dofs: 'yzx' },
  { name: 'neck', parent: 1, offset: [0, 0.44, 0], dofs: 'yzx' },
  { name: 'head', parent: 2, offset: [0, 0.1, 0], dofs: 'yzx' },
  { name: 'r_upper_arm', parent: 1, offset: [0, 0.4, 0.19], dofs: 'zxy' },
] });
const NECK_YAW = 6, HEAD_YAW = 9;   // angle indices of the 'y' dofs of neck and head

test('a turn is limited to 600°/s in sum over neck and head, and arrives', () => {
  const cur = Float32Array.from({ length: 6 }, () => 0);
  const target = Float32Array.of(60, 60, 0, 0, 0, 0);   // 120° of yaw, split in two
  const groups = [[0, 1], [2, 4], [3, 5]];
  const dt = 1 / 60;
  let prev = 0, frames = 0;
  while (Math.abs(cur[0] + cur[1] - 120) > 0.5 && frames < 100) {
    limitTurn(cur, target, groups, dt);
    const sum = cur[0] + cur[1];
    assert.ok(sum - prev <= MAX_HEAD_DEG_PER_S * dt + 1e-4, `${(sum - prev) / dt} °/s`);
    assert.ok(Math.abs(cur[0] - cur[1]) < 1e-4, 'neck and head move together');
    prev = sum;
    frames++;
  }
  // 120° at 600°/s is 0.2 s; the ease adds a little at the end.
  assert.ok(frames >= 12 && frames < 30, `${frames} frames`);
  // The speed eases off at the end (no stop from full speed).
  const before = cur[0];
  limitTurn(cur, target, groups, dt);
  assert.ok(cur[0] - before < 1, 'slow at the end');
  // Without time, nothing moves.
  const still = Float32Array.of(0, 0);
  assert.equal(limitTurn(still, Float32Array.of(90, 90), [[0, 1]], 0), 0);
  assert.deepEqual([...still], [0, 0]);
});

test('the drawn head follows the stream at human speed; the rest of the body is drawn exactly', () => {
  const h = new HeadSmoother(skel);
  const n = skel.dofCount;
  const frame = (yaw, arm, x = 0) => ({ x, y: 0, angles: Float32Array.from({ length: n }, (_, i) =>
    (i === NECK_YAW || i === HEAD_YAW ? yaw : i === 12 ? arm : 0)) });
  let a = h.apply('1:9', frame(0, 10), 0);
  assert.equal(a[NECK_YAW], 0);
  // The agent snaps its neck by 120° (60 + 60) in one cycle.
  a = h.apply('1:9', frame(60, 20), 1 / 60);
  assert.ok(a[NECK_YAW] + a[HEAD_YAW] <= 10 + 1e-3, `drawn ${a[NECK_YAW] + a[HEAD_YAW]}° after one picture`);
  assert.equal(a[12], 20, 'an arm is drawn as the stream says');
  let t = 0;
  while (a[NECK_YAW] < 59.5 && t < 60) { a = h.apply('1:9', frame(60, 20), 1 / 60); t++; }
  assert.ok(t < 30, 'it gets there within half a second');
  assert.ok(Math.abs(a[NECK_YAW] - 60) < 0.5 && Math.abs(a[HEAD_YAW] - 60) < 0.5, 'where the agent looks');
  // A teleport (a kick-off move, a cut in time) snaps.
  a = h.apply('1:9', frame(-60, 0, 30), 1 / 60);
  assert.equal(a[NECK_YAW], -60);
  // Each player has his own.
  a = h.apply('-1:4', frame(45, 0), 1 / 60);
  assert.equal(a[NECK_YAW], 45, 'first sight: as the stream says');
});

const { buildBodyGeometry, meshSummary, restPositions, tonesOf } = await load('src/model/body_geometry.js');
import fs from 'node:fs';
const readJson = (rel) => JSON.parse(fs.readFileSync(path.resolve(import.meta.dirname, rel), 'utf8'));

test('the body is generated from its description, the same as the viewer makes it', () => {
  const spec = JSON.parse(fs.readFileSync(path.join(WEB, 'assets/body.json'), 'utf8'));
  const human = normalizeSkeleton(readJson('data/human_skeleton.json'));
  const golden = readJson('data/body_summary.json');   // viewer_BodyMesh.* checks the C++ generator against it
  for (const lod of [0, 1]) {
    const m = buildBodyGeometry(spec, human, lod);
    assert.ok(m, `level ${lod}`);
    assert.deepEqual(meshSummary(m), golden[lod], `level ${lod} as the viewer's`);
    // Every vertex's weights sum to 1, on joints of the skeleton.
    for (let i = 0; i < m.vertexCount; i++) {
      assert.ok(Math.abs(m.skinWeight[4 * i] + m.skinWeight[4 * i + 1] - 1) < 1e-6);
      assert.ok(m.skinIndex[4 * i] < human.joints.length && m.skinIndex[4 * i + 1] < human.joints.length);
    }
    assert.ok(m.index.every((v) => v < m.vertexCount), 'every index is a vertex');
  }
  const near = buildBodyGeometry(spec, human, 0), far = buildBodyGeometry(spec, human, 1);
  assert.ok(far.index.length < near.index.length / 2, 'the far level has under half the triangles');
  // Standing: soles on the grass (the pelvis 1.00 m up), the head at ~1.84 m.
  const s = meshSummary(near);
  assert.ok(Math.abs(s.min[1] + 1.0) < 0.01 && Math.abs(s.max[1] - 0.84) < 0.03, JSON.stringify(s));
  // Every region is used: kit, skin, hair, boots.
  assert.deepEqual([...new Set(near.region)].sort(), [0, 1, 2, 3, 4, 5]);
  // Another skeleton (the golden vectors' test humanoid): no body, the page draws boxes.
  const other = normalizeSkeleton({ joints: [{ name: 'root', parent: -1, dofs: 'y' }] });
  assert.equal(buildBodyGeometry(spec, other, 0), null);
  assert.deepEqual(restPositions(human)[2].map((v) => Math.round(v * 100) / 100), [0, 0.52, 0], 'the neck at rest');
  // Tones: fixed per player, and not all the same.
  assert.deepEqual(tonesOf(spec, 1, 9), tonesOf(spec, 1, 9));
  assert.ok(new Set(Array.from({ length: 11 }, (_, u) => tonesOf(spec, -1, u + 1).skin)).size >= 3);
});

const { tiredness, FatiguePose, HANDS_ON_KNEES_DROP } = await load('src/model/fatigue.js');

// Forward kinematics of the skeleton (proto/skeleton.hpp): joint positions
// in body space for `angles`, the pelvis `z` metres above the grass.
function jointPositions(skel, angles, z) {
  const rot = (axis, deg) => {
    const a = deg * Math.PI / 180, c = Math.cos(a), s = Math.sin(a);
    if (axis === 'x') return [[1, 0, 0], [0, c, -s], [0, s, c]];
    if (axis === 'y') return [[c, 0, s], [0, 1, 0], [-s, 0, c]];
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]];
  };
  const mul = (A, B) => A.map((r) => [0, 1, 2].map((j) => r[0] * B[0][j] + r[1] * B[1][j] + r[2] * B[2][j]));
  const app = (A, v) => A.map((r) => r[0] * v[0] + r[1] * v[1] + r[2] * v[2]);
  const R = [], P = [];
  skel.joints.forEach((j, i) => {
    let local = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
    [...j.dofs].forEach((axis, k) => { local = mul(local, rot(axis, angles[j.angleIndex + k])); });
    if (i === 0) { R.push(local); P.push([0, z, 0]); return; }
    const o = app(R[j.parent], j.offset);
    P.push(P[j.parent].map((v, k) => v + o[k]));
    R.push(mul(R[j.parent], local));
  });
  return { R, P, at: (name, v) => { const i = skel.joints.findIndex((q) => q.name === name); const o = app(R[i], v); return P[i].map((x, k) => x + o[k]); } };
}

test('a tired player leans, swings his arms less, and rests his hands on his knees at a stoppage', () => {
  const human = normalizeSkeleton(readJson('data/human_skeleton.json'));
  assert.equal(tiredness(8000, 8000), 0);
  assert.equal(tiredness(4400, 8000), 0, 'fresh enough above 55 %');
  assert.equal(tiredness(1600, 8000), 1, 'exhausted at 20 %');
  assert.ok(Math.abs(tiredness(3000, 8000) - 0.5) < 1e-9);
  assert.equal(tiredness(NaN), 0, 'a stream without stamina: nothing changes');

  const f = new FatiguePose(human);
  const n = human.dofCount;
  const idx = (name, axis) => { const j = human.joints.find((q) => q.name === name); return j.angleIndex + j.dofs.indexOf(axis); };
  const running = () => { const a = new Float32Array(n); a[idx('r_upper_arm', 'z')] = 40; a[idx('l_upper_arm', 'z')] = -30; return a; };
  // Running (moving 6 m/s), tired: the lean and the smaller swing.
  const p = { x: 0, y: 0, state: 1 };
  let a = running();
  f.apply('1:4', p, a, 0.8, 0, {});
  for (let t = 0; t < 10; t++) { p.x += 0.1; a = running(); f.apply('1:4', p, a, 0.8, 1 / 60, { stoppage: true, ball: { x: 30, y: 0 } }); }
  assert.ok(a[idx('torso', 'z')] < -10, `leaning forward: ${a[idx('torso', 'z')]}`);
  assert.ok(a[idx('r_upper_arm', 'z')] < 30 && a[idx('l_upper_arm', 'z')] > -20, 'arms swing less');
  // Fresh: exactly the stream's angles.
  const fresh = running();
  assert.equal(new FatiguePose(human).apply('1:5', { x: 0, y: 0, state: 1 }, fresh, 0, 1 / 60, { stoppage: true }), 0);
  assert.deepEqual([...fresh], [...running()]);
  // Standing at a stoppage, exhausted, far from the ball: hands on knees within ~0.5 s.
  const q = { x: 10, y: 5, state: 1 };
  let drop = 0, frames = 0;
  for (; frames < 60 && drop < HANDS_ON_KNEES_DROP - 1e-6; frames++) {
    a = new Float32Array(n);
    drop = f.apply('1:7', q, a, 1, 1 / 60, { stoppage: true, ball: { x: 40, y: 0 } });
  }
  assert.ok(frames >= 20 && frames <= 40, `eased in over ${frames} pictures`);
  const fk = jointPositions(human, a, 1.0 - drop);
  const knee = fk.at('r_shin', [0, 0, 0]);
  const hand = fk.at('r_hand', [0, -0.09, 0]);
  const dist = Math.hypot(...knee.map((v, k) => v - hand[k]));
  assert.ok(dist < 0.1, `the right hand ${dist.toFixed(2)} m from the knee`);
  const sole = fk.at('r_foot', [0, -0.08, 0]);
  assert.ok(Math.abs(sole[1]) < 0.02, `the sole on the grass: ${sole[1].toFixed(3)} m`);
  const head = fk.at('head', [0, 0.1, 0]);
  assert.ok(head[1] < 1.45, `bent over: head at ${head[1].toFixed(2)} m`);
  // Play on again: back up.
  for (let t = 0; t < 40; t++) { a = new Float32Array(n); drop = f.apply('1:7', q, a, 1, 1 / 60, { stoppage: false }); }
  assert.equal(drop, 0);
  // Near the ball (the taker) or a goalie: no.
  const g = new FatiguePose(human);
  for (let t = 0; t < 60; t++) drop = g.apply('1:8', { x: 0, y: 0, state: 1 }, new Float32Array(n), 1, 1 / 60, { stoppage: true, ball: { x: 1, y: 1 } });
  assert.equal(drop, 0);
  for (let t = 0; t < 60; t++) drop = g.apply('1:1', { x: -50, y: 0, state: 9 }, new Float32Array(n), 1, 1 / 60, { stoppage: true, ball: { x: 1, y: 1 } });
  assert.equal(drop, 0);
});

// Every drawn pose rests on the grass (web/src/model/ground.js, the same
// rule as anim::rest_on_grass): checked against three.js's own forward
// kinematics of the same joints, as scene/players.js builds them.
test('a pose dipping under the grass is raised by what lies deeper than 1 cm', async () => {
  const { lowestPoint, grassLift, GRASS_TOLERANCE_M } = await load('src/model/ground.js');
  const THREE = await import(pathToFileURL(path.join(WEB, 'node_modules/three/build/three.module.js')).href);
  const human = normalizeSkeleton(readJson('data/human_skeleton.json'));
  const AX = { x: new THREE.Vector3(1, 0, 0), y: new THREE.Vector3(0, 1, 0), z: new THREE.Vector3(0, 0, 1) };
  const threeLowest = (angles, rootHeight) => {
    const nodes = human.joints.map(() => new THREE.Object3D());
    human.joints.forEach((j, i) => {
      if (j.parent >= 0) { nodes[j.parent].add(nodes[i]); nodes[i].position.fromArray(j.offset); }
      else nodes[i].position.set(0, rootHeight, 0);
      const q = new THREE.Quaternion();
      for (let k = 0; k < j.dofs.length; k++)
        q.multiply(new THREE.Quaternion().setFromAxisAngle(AX[j.dofs[k]], angles[j.angleIndex + k] * Math.PI / 180));
      nodes[i].quaternion.copy(q);
    });
    nodes[0].updateMatrixWorld(true);
    let low = Infinity;
    human.joints.forEach((j, i) => {
      const { size, center, shape } = j.segment;
      if (shape === 'sphere') {
        low = Math.min(low, new THREE.Vector3().fromArray(center).applyMatrix4(nodes[i].matrixWorld).y - size[0]);
        return;
      }
      for (let c = 0; c < 8; c++) {
        const p = new THREE.Vector3(center[0] + (c & 1 ? 0.5 : -0.5) * size[0], center[1] + (c & 2 ? 0.5 : -0.5) * size[1],
                                    center[2] + (c & 4 ? 0.5 : -0.5) * size[2]);
        low = Math.min(low, p.applyMatrix4(nodes[i].matrixWorld).y);
      }
    });
    return low;
  };
  // Standing straight at the skeleton's own height: the soles on the grass.
  const stand = new Float32Array(human.dofCount);
  assert.ok(Math.abs(lowestPoint(human, stand, 1.0)) < 0.005, `${lowestPoint(human, stand, 1.0)}`);
  assert.equal(grassLift(human, stand, 1.0), 0);
  // Sunk 5 cm: raised by 4 (the tolerance is 1 cm).
  assert.ok(Math.abs(grassLift(human, stand, 0.95) - (0.05 - GRASS_TOLERANCE_M)) < 0.005);
  // Random poses within the joints' limits agree with three.js to 0.1 mm.
  let seed = 7;
  const rand = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  for (let n = 0; n < 50; n++) {
    const a = new Float32Array(human.dofCount);
    human.joints.forEach((j) => {
      for (let k = 0; k < j.dofs.length; k++) {
        const [lo, hi] = j.limits[k] ?? [-30, 30];
        a[j.angleIndex + k] = lo + (hi - lo) * rand();
      }
    });
    const h = 0.5 + 0.5 * rand();
    assert.ok(Math.abs(lowestPoint(human, a, h) - threeLowest(a, h)) < 1e-4, `pose ${n}`);
  }
});
