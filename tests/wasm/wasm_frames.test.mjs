// The page's WebAssembly log module makes the server pipeline's bytes: over
// the whole bundled game (and a short log of every other version), every
// frame and control message the module emits is byte-for-byte what the
// native pipeline (matchcast-log-frames: the server's reader and
// BroadcastPipeline) writes for the same log and options.
//
// Needs web/wasm/ (scripts/build-wasm.sh); without it the test is skipped
// (exit 77, ctest's SKIP_RETURN_CODE).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { decodedLog, loadModule, moduleBuilt, records, runLog } from './wasm_module.mjs';

const REPO = process.env.MATCHCAST_REPO_ROOT ?? path.resolve(import.meta.dirname, '../..');
const TOOL = process.env.MATCHCAST_LOG_FRAMES ?? path.join(REPO, 'build', 'wasm', 'matchcast-log-frames');
const BUNDLED = path.join(REPO, 'data', '20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz');
const GEN = path.join(REPO, 'tests', 'data', 'rcg', 'generated');

if (!moduleBuilt()) {
  console.log('SKIPPED: web/wasm/matchcast-log.{js,wasm} not built (scripts/build-wasm.sh)');
  process.exit(77);
}
const mod = await loadModule();
const tmp = mkdtempSync(path.join(os.tmpdir(), 'matchcast-wasm-'));
process.on('exit', () => rmSync(tmp, { recursive: true, force: true }));

// The native reference for `log` with the same options as the module run.
function reference(log, baseMs, matchId) {
  const out = path.join(tmp, 'ref.bin');
  execFileSync(TOOL, [log, out, '--base', String(baseMs), '--match-id', matchId]);
  return readFileSync(out);
}

function compare(got, want, what) {
  const a = records(got), b = records(want);
  assert.equal(a.length, b.length, `${what}: ${a.length} records from the module, ${b.length} from the server pipeline`);
  let frames = 0;
  for (let i = 0; i < a.length; i++) {
    assert.equal(a[i].kind, b[i].kind, `${what}: record ${i} kind`);
    assert.ok(a[i].bytes.equals(b[i].bytes), `${what}: record ${i} ('${a[i].kind}', frame ${frames}) differs`);
    if (a[i].kind === 'k' || a[i].kind === 'f') frames++;
  }
  assert.ok(got.equals(want));
  return frames;
}

test('the whole bundled game: every frame and message byte-identical to the server pipeline', () => {
  const base = 1764000000000;
  const run = runLog(mod, decodedLog(BUNDLED), { baseMs: base, matchId: 'bundled.rcg.gz', chunk: 65536 });
  assert.equal(run.rc, 2, JSON.stringify(run.status));
  assert.equal(run.status.states, 6689);
  const frames = compare(run.out, reference(BUNDLED, base, 'bundled.rcg.gz'), 'bundled game');
  assert.equal(frames, 13378);
  console.log(`bundled game: ${frames} frames, ${run.out.length} bytes identical; ` +
    `module ${run.totalMs.toFixed(0)} ms, first frame after ${run.firstFrameMs.toFixed(0)} ms`);
});

test('every other log version: byte-identical too', () => {
  for (const v of ['v1-20261122025913-Alpha_0-vs-Beta_0', 'v2-20261122025747-Alpha_1-vs-Beta_2',
    'v3-20261122025631-Alpha_0-vs-Beta_1', 'v4-20261122025515-Alpha_1-vs-Beta_0',
    'v5-20261122025405-Alpha_0-vs-Beta_0', 'json-20261122030023-Alpha_1-vs-Beta_1']) {
    const log = path.join(GEN, `gen19-${v}.rcg.gz`);
    const run = runLog(mod, decodedLog(log), { baseMs: 7, matchId: v, chunk: 4096, step: 37 });
    assert.equal(run.rc, 2, `${v}: ${JSON.stringify(run.status)}`);
    compare(run.out, reference(log, 7, v), v);
  }
});
