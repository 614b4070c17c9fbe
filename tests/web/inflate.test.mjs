// The page's gunzip of a dropped log (web/src/local/inflate.js), in node:
// every byte before a cut comes out, whatever the reader's pace, and the
// cut shows as an error only after them; a whole file reads to its end.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { readFileSync } from 'node:fs';
import { gunzipSync, gzipSync, constants } from 'node:zlib';
import { pathToFileURL } from 'node:url';

const WEB = process.env.MATCHCAST_WEB_DIR ?? path.resolve(import.meta.dirname, '../../web');
const RCG = process.env.MATCHCAST_RCG ??
  path.resolve(import.meta.dirname, '../../data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz');
const { gunzipReader } = await import(pathToFileURL(path.join(WEB, 'src/local/inflate.js')).href);

// Reads `bytes` (gzip) through gunzipReader, pausing `pauseMs` after each
// chunk as the page's worker does while it animates; the first chunk is
// read before, as the worker does to tell gzip from plain.
async function inflate(bytes, pauseMs) {
  const raw = new Blob([bytes]).stream().getReader();
  const first = await raw.read();
  let rawBytes = 0;
  const r = gunzipReader(raw, first.value, (n) => { rawBytes += n; });
  const parts = [];
  let error = null;
  try {
    for (;;) {
      const { value, done } = await r.read();
      if (done) break;
      parts.push(value);
      if (pauseMs) await new Promise((res) => setTimeout(res, pauseMs));
    }
  } catch (err) {
    error = err;
  }
  return { out: Buffer.concat(parts), error, rawBytes };
}

const gz = readFileSync(RCG);

test('a cut log gives every byte before the cut, then the error', async () => {
  for (const [frac, pause] of [[0.4, 2], [0.77, 0], [0.05, 5]]) {
    const cut = gz.subarray(0, Math.floor(gz.length * frac));
    const want = gunzipSync(cut, { finishFlush: constants.Z_SYNC_FLUSH });
    const { out, error, rawBytes } = await inflate(cut, pause);
    assert.ok(error, `cut at ${frac}: the cut is reported`);
    assert.equal(out.length, want.length, `cut at ${frac}, pause ${pause} ms: bytes before the cut`);
    assert.ok(out.equals(want), `cut at ${frac}: the same bytes`);
    assert.equal(rawBytes, cut.length, 'every raw byte counted');
  }
});

test('a whole log reads to its end with no error', async () => {
  const { out, error } = await inflate(gz, 0);
  assert.equal(error, null);
  assert.ok(out.equals(gunzipSync(gz)));
});

test('garbage after a gzip header is an error, not a hang', async () => {
  const bad = Buffer.concat([gzipSync(Buffer.from('(show 1 ...)\n')).subarray(0, 10), Buffer.alloc(5000, 0xa5)]);
  const { error } = await inflate(bad, 0);
  assert.ok(error);
});
