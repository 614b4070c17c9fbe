// The close-up camera's line of sight (web/src/model/sightline.js): it
// keeps its bearing while no one stands between it and its subject, nor
// just beside it in its picture, and cuts to the clear bearing nearest to
// it when someone does.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const WEB = process.env.MATCHCAST_WEB_DIR ?? path.resolve(import.meta.dirname, '../../web');
const { CLOSEUP_BEARINGS_DEG, CLOSEUP_PATIENCE_S, CloseupAim, NEAR_CAMERA_M, blocks, clearBearing, closeupSpot } =
  await import(pathToFileURL(path.join(WEB, 'src/model/sightline.js')).href);

const subject = { x: 10, y: -5 };
// A player half-way along the line from a bearing's camera spot to the subject.
const inTheWay = (bearing) => {
  const cam = closeupSpot(subject, CLOSEUP_BEARINGS_DEG[bearing]);
  return { x: (cam.x + subject.x) / 2, y: (cam.y + subject.y) / 2 };
};

test('the camera stands 4.7 m from its subject, on the main stand side at bearing 0', () => {
  const cam = closeupSpot(subject, 0);
  assert.ok(Math.abs(Math.hypot(cam.x - subject.x, cam.y - subject.y) - Math.hypot(1.2, 4.6)) < 1e-9);
  assert.ok(cam.y > subject.y + 4);
  for (const deg of CLOSEUP_BEARINGS_DEG) {
    const c = closeupSpot(subject, deg);
    assert.ok(c.y > subject.y, `bearing ${deg}: still on the main stand side`);
  }
});

test('only a player between the camera and the subject blocks it', () => {
  const cam = closeupSpot(subject, 0);
  assert.equal(blocks(cam, subject, inTheWay(0)), true);
  assert.equal(blocks(cam, subject, { x: subject.x, y: subject.y - 1.5 }), false, 'behind the subject');
  assert.equal(blocks(cam, subject, { x: cam.x, y: cam.y + 1 }), false, 'behind the camera');
  const side = inTheWay(0);
  assert.equal(blocks(cam, subject, { x: side.x + 1.0, y: side.y }), false, 'a metre to the side');
  assert.equal(blocks(subject, subject, inTheWay(0)), false, 'no line of sight at all');
  assert.equal(blocks(cam, subject, { x: NaN, y: 0 }), false, 'no position');
});

// A point `ahead` m along the camera's line of sight and `aside` m to its
// right (as the camera looks), in field metres.
const fromCamera = (cam, ahead, aside) => {
  const vx = subject.x - cam.x, vy = subject.y - cam.y, len = Math.hypot(vx, vy);
  const ux = vx / len, uy = vy / len;
  return { x: cam.x + ux * ahead - uy * aside, y: cam.y + uy * ahead + ux * aside };
};

test('a player just beside the camera, in its picture, is in the way too', () => {
  const cam = closeupSpot(subject, 0);
  // 1.3 m ahead and 1 m aside, off the line of sight but in the picture:
  // the forearm across a corner of the frame.
  for (const aside of [1.0, -1.0]) assert.equal(blocks(cam, subject, fromCamera(cam, 1.3, aside)), true, `aside ${aside}`);
  // Beside the camera but out of the picture, or behind it: not.
  assert.equal(blocks(cam, subject, fromCamera(cam, 0.3, 1.5)), false, 'level with the camera');
  assert.equal(blocks(cam, subject, fromCamera(cam, -0.5, 0.6)), false, 'behind the camera');
  // At the picture's edge but further off than NEAR_CAMERA_M, and off the
  // line of sight: a player in the background, as any broadcast shows.
  const far = fromCamera(cam, (NEAR_CAMERA_M + 0.5) * Math.cos(0.4), (NEAR_CAMERA_M + 0.5) * Math.sin(0.4));
  assert.equal(blocks(cam, subject, far), false, 'further off');
  // The cut: to a bearing from which he is out of the picture.
  const beside = fromCamera(cam, 1.3, 1.0);
  const chosen = clearBearing(subject, [beside], 0);
  assert.notEqual(chosen, 0);
  assert.equal(blocks(closeupSpot(subject, CLOSEUP_BEARINGS_DEG[chosen]), subject, beside), false);
});

test('a clear bearing is kept; a blocked one gives way to the nearest clear one', () => {
  assert.equal(clearBearing(subject, []), 0);
  assert.equal(clearBearing(subject, [{ x: subject.x, y: subject.y - 2 }]), 0, 'someone behind him');
  const chosen = clearBearing(subject, [inTheWay(0)], 0);
  assert.notEqual(chosen, 0);
  assert.equal(Math.abs(CLOSEUP_BEARINGS_DEG[chosen]), 35, 'the nearest bearing that is clear');
  const cam = closeupSpot(subject, CLOSEUP_BEARINGS_DEG[chosen]);
  assert.equal(blocks(cam, subject, inTheWay(0)), false);
  // Not back to straight-on while the present bearing is clear.
  assert.equal(clearBearing(subject, [], 2), 2);
  // Both +-35 blocked as well: the next clear one out.
  const three = clearBearing(subject, [inTheWay(0), inTheWay(1), inTheWay(2)], 0);
  assert.equal(Math.abs(CLOSEUP_BEARINGS_DEG[three]), 70);
  // Everyone in the way: no cut helps.
  const all = CLOSEUP_BEARINGS_DEG.map((_, i) => inTheWay(i));
  assert.equal(clearBearing(subject, all, 1), 1);
  // A bad bearing index is read as straight-on.
  assert.equal(clearBearing(subject, [], 99), 0);
  assert.equal(clearBearing(subject, [], -1), 0);
});

test('the cut comes after the line of sight stays blocked for a while, and never while paused', () => {
  const blocker = [inTheWay(0)];
  const aim = new CloseupAim();
  const straight = closeupSpot(subject, 0);
  // Paused on one frame: however long, no cut.
  for (let i = 0; i < 100; i++) assert.deepEqual(aim.update(0.05, 500, subject, blocker), straight);
  // A moment in the way while the game moves: let pass.
  aim.update(0.05, 501, subject, blocker);
  assert.deepEqual(aim.update(0.05, 502, subject, []), straight);
  // Longer: the cut.
  let at = 502, spot = straight;
  for (let t = 0; t <= CLOSEUP_PATIENCE_S + 0.1; t += 0.05) spot = aim.update(0.05, ++at, subject, blocker);
  assert.notDeepEqual(spot, straight);
  assert.equal(blocks(spot, subject, blocker[0]), false, 'cut to a clear bearing');
  // Without stream positions (a caller that has none) time alone counts.
  const plain = new CloseupAim();
  for (let t = 0; t <= CLOSEUP_PATIENCE_S + 0.1; t += 0.05) spot = plain.update(0.05, undefined, subject, blocker);
  assert.notDeepEqual(spot, straight);
});
