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
