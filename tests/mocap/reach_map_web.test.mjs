// The page's side of the reach map (web/src/scene/overlays.js): the
// run-length decoder refuses malformed cells, and a message paints the
// texture with the team colours, field +y at the texture's bottom row.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const WEB = process.env.MATCHCAST_WEB_DIR ?? path.resolve(import.meta.dirname, '../../web');
const load = (p) => import(pathToFileURL(path.join(WEB, p)).href);
const { Overlays } = await load('src/scene/overlays.js');
const THREE = await load('node_modules/three/build/three.module.js');

test('run-length cells decode exactly or not at all', () => {
  const D = Overlays.decodeCells;
  assert.equal(D('l2r2', 4), 'llrr');
  assert.equal(D('c1n3', 4), 'cnnn');
  for (const bad of ['l2r1', 'l2r3', 'x4', 'l0l4', 'l4r', '', 'l2 r2', 'l99999999']) assert.equal(D(bad, 4), null, bad);
});

test('a reach_map message paints the grid in team colours', () => {
  const o = new Overlays(new THREE.Scene(), { length: 105, width: 68 }, {});
  const colors = { 1: new THREE.Color(1, 0, 0), [-1]: new THREE.Color(0, 0, 1) };
  assert.ok(o.setReachMap({ grid: { w: 2, h: 2, cell: 2, x0: -2, y0: -2 }, cells: 'l1r1c1n1' }, colors));
  const d = o.reachMap.data;
  const px = (row, col) => Array.from(d.slice((row * 2 + col) * 4, (row * 2 + col) * 4 + 4));
  assert.deepEqual(px(1, 0), [255, 0, 0, 90]);     // cell (0,0), field y min: top texture row
  assert.deepEqual(px(1, 1), [0, 0, 255, 90]);     // right team
  assert.deepEqual(px(0, 0), [255, 255, 255, 70]); // contested
  assert.equal(px(0, 1)[3], 0);                    // nobody: transparent
  assert.equal(o.reachMap.mesh.position.x, 0);
  assert.equal(o.reachMap.mesh.position.z, 0);
  assert.equal(o.setReachMap({ grid: { w: 2, h: 2, cell: 2, x0: -2, y0: -2 }, cells: 'l5' }, colors), false);
  assert.equal(o.setReachMap({ grid: { w: 0, h: 2, cell: 2, x0: 0, y0: 0 }, cells: '' }, colors), false);
  o.showReachMap = false;
  o.update({ players: [], ball: { x: 0, y: 0 } }, colors);
  assert.equal(o.reachMap.mesh.visible, false);
});
