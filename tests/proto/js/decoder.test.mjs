// The JavaScript decoder against the same golden vectors as the C++ one
// (tests/proto/golden/frames_v1.json). Run: node --test tests/proto/js/
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

import { FrameDecoder, parseHello, parseControl, peekHeader } from '../../../web/lib/proto/decoder.js';

const golden = JSON.parse(
  readFileSync(fileURLToPath(new URL('../golden/frames_v1.json', import.meta.url)), 'utf8'),
);
const unhex = (h) => Uint8Array.from(h.match(/../g) ?? [], (b) => parseInt(b, 16));
const near = (a, b, what) => assert.ok(Math.abs(a - b) <= 1e-4, `${what}: ${a} != ${b}`);

test('hello parses and names the skeleton', () => {
  const hello = parseHello(JSON.stringify(golden.hello));
  assert.equal(hello.protocol.major, 1);
  assert.equal(hello.skeleton.dof_count, 36);
});

test('hello with an unknown major version is refused', () => {
  const bad = structuredClone(golden.hello);
  bad.protocol.major = 7;
  assert.throws(() => parseHello(JSON.stringify(bad)), /unsupported protocol major version 7/);
  assert.throws(() => parseHello('{oops'), /not JSON/);
  assert.throws(() => parseControl('[1,2]'), /no "type"/);
});

test('every golden frame decodes to the expected values', () => {
  const hello = parseHello(JSON.stringify(golden.hello));
  const dec = new FrameDecoder(hello.skeleton);
  for (const f of golden.frames) {
    const out = dec.decode(unhex(f.hex).buffer);
    const e = f.expected;
    for (const k of ['seq', 'time', 'stoppage', 'substep', 'serverTimeMs', 'keyframe', 'playMode', 'scoreLeft', 'scoreRight']) {
      assert.equal(out[k], e[k], `frame ${e.seq} ${k}`);
    }
    for (const k of ['x', 'y', 'z']) near(out.ball[k], e.ball[k], `frame ${e.seq} ball.${k}`);
    assert.equal(out.players.length, e.players.length);
    out.players.forEach((p, i) => {
      const ep = e.players[i];
      assert.equal(p.side, ep.side, `frame ${e.seq} player ${i} side`);
      assert.equal(p.unum, ep.unum);
      assert.equal(p.state, ep.state, `frame ${e.seq} player ${i} state`);
      for (const k of ['x', 'y', 'z', 'heading']) near(p[k], ep[k], `frame ${e.seq} player ${i} ${k}`);
      assert.equal(p.angles.length, ep.angles.length);
      p.angles.forEach((a, d) => near(a, ep.angles[d], `frame ${e.seq} player ${i} dof ${d}`));
    });
  }
});

test('bad frames are refused with the expected error', () => {
  const hello = parseHello(JSON.stringify(golden.hello));
  for (const b of golden.bad) {
    const dec = new FrameDecoder(hello.skeleton);
    for (let i = 0; i < b.prefix; i++) dec.decode(unhex(golden.frames[i].hex));
    assert.throws(() => dec.decode(unhex(b.hex)), (err) => err instanceof Error && err.message.includes(b.error_contains),
      b.name);
  }
});

test('a late joiner decodes from a later keyframe; a gap waits for the next one', () => {
  const hello = parseHello(JSON.stringify(golden.hello));
  const dec = new FrameDecoder(hello.skeleton);
  const keys = golden.frames.map((f, i) => (f.expected.keyframe ? i : -1)).filter((i) => i >= 0);
  assert.ok(keys.length >= 2);
  assert.throws(() => dec.decode(unhex(golden.frames[keys[0] + 1].hex)), /without its base/);
  const out = dec.decode(unhex(golden.frames[keys[1]].hex));
  assert.equal(out.keyframe, true);
  dec.decode(unhex(golden.frames[keys[1] + 1].hex));
  assert.throws(() => dec.decode(unhex(golden.frames[keys[1] + 3].hex)), /gap/);
  assert.equal(dec.synced, false);
});

test('peekHeader reads the header; every truncation of every frame throws, never crashes', () => {
  const h = peekHeader(unhex(golden.frames[1].hex));
  assert.equal(h.seq, golden.frames[1].expected.seq);
  assert.equal(h.keyframe, false);
  const hello = parseHello(JSON.stringify(golden.hello));
  for (let which = 0; which < 3; which++) {
    const full = unhex(golden.frames[which].hex);
    for (let len = 0; len < full.length; len++) {
      const dec = new FrameDecoder(hello.skeleton);
      for (let i = 0; i < which; i++) dec.decode(unhex(golden.frames[i].hex));
      assert.throws(() => dec.decode(full.slice(0, len)), Error, `frame ${which} cut at ${len}`);
    }
  }
});
