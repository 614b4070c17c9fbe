// The page's log module, measured (README.md, "The page without a server"):
//   node tests/wasm/wasm_bench.mjs [LOG] [--runs N]
// prints the module's size (raw and gzipped), the time from opening a log
// to its first frame in the module (compile + instantiate included), and
// the animation time of the whole game in the module against the native
// build (matchcast-log-frames: the server's reader and pipeline), as a
// ratio; the runs alternate, the best of each side counts.
import { spawnSync } from 'node:child_process';
import { readFileSync, statSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { gzipSync } from 'node:zlib';
import { MODULE_JS, MODULE_WASM, decodedLog, loadModule, moduleBuilt, runLog } from './wasm_module.mjs';

const REPO = process.env.MATCHCAST_REPO_ROOT ?? path.resolve(import.meta.dirname, '../..');
const args = process.argv.slice(2);
const runs = Number(args.includes('--runs') ? args[args.indexOf('--runs') + 1] : 3);
const log = args.find((a) => !a.startsWith('--') && a !== String(runs)) ??
  path.join(REPO, 'data', '20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz');
const tool = process.env.MATCHCAST_LOG_FRAMES ??
  [path.join(REPO, 'build', 'wasm', 'matchcast-log-frames')].find((p) => { try { return statSync(p).isFile(); } catch { return false; } });
if (!moduleBuilt()) { console.error('web/wasm/ not built: scripts/build-wasm.sh'); process.exit(1); }

const wasm = readFileSync(MODULE_WASM), js = readFileSync(MODULE_JS);
const kb = (n) => `${(n / 1024).toFixed(0)} KB`;
console.log(`module: matchcast-log.wasm ${kb(wasm.length)} (${kb(gzipSync(wasm, { level: 9 }).length)} gzipped), ` +
  `matchcast-log.js ${kb(js.length)} (${kb(gzipSync(js, { level: 9 }).length)} gzipped); ` +
  `total gzipped ${kb(gzipSync(wasm, { level: 9 }).length + gzipSync(js, { level: 9 }).length)} (goal 1024 KB)`);

// First frame: a fresh module each time (compile, instantiate, read, animate).
let firstBest = Infinity, compileBest = Infinity;
const bytes = decodedLog(log);
for (let i = 0; i < runs; i++) {
  const t0 = performance.now();
  const mod = await loadModule();
  const t1 = performance.now();
  const r = runLog(mod, bytes.subarray(0, 8 << 20), { matchId: 'bench' });
  compileBest = Math.min(compileBest, t1 - t0);
  firstBest = Math.min(firstBest, t1 - t0 + r.firstFrameMs);
}
console.log(`first frame: ${firstBest.toFixed(0)} ms after opening (module compiled and instantiated in ${compileBest.toFixed(0)} ms; ` +
  `the page adds reading and gunzipping the file and drawing)`);

// The whole game, module against native, alternating. Wall time is what a
// user waits; CPU time (this process's for the module, the child's user +
// system time for the native tool) stays meaningful on a busy machine.
const mod = await loadModule();
const best = { wasm: Infinity, native: Infinity, wasmCpu: Infinity, nativeCpu: Infinity };
let states = 0;
const out = path.join(os.tmpdir(), `matchcast-bench-${process.pid}.bin`);
for (let i = 0; i < runs; i++) {
  const c0 = process.cpuUsage();
  const r = runLog(mod, bytes, { matchId: 'bench' });
  const c = process.cpuUsage(c0);
  states = r.status.states;
  best.wasm = Math.min(best.wasm, r.totalMs);
  best.wasmCpu = Math.min(best.wasmCpu, (c.user + c.system) / 1000);
  if (tool) {
    // /usr/bin/time -f '%U %S' on stderr: the child's CPU seconds.
    const res = spawnSync('/usr/bin/time', ['-f', '%U %S', tool, log, out], { encoding: 'utf8' });
    const wall = /in (\d+) ms/.exec(res.stdout ?? '');
    if (wall) best.native = Math.min(best.native, Number(wall[1]));
    const cpu = /([\d.]+) ([\d.]+)\s*$/.exec(res.stderr ?? '');
    if (cpu) best.nativeCpu = Math.min(best.nativeCpu, (Number(cpu[1]) + Number(cpu[2])) * 1000);
  }
}
const f = (x) => (Number.isFinite(x) ? `${x.toFixed(0)} ms` : 'n/a');
console.log(`whole game (${states} states, ${path.basename(log)}), best of ${runs} each, alternated:`);
console.log(`  wall: module ${f(best.wasm)}, native ${f(best.native)}` +
  (tool ? `: ratio ${(best.wasm / best.native).toFixed(2)}` : ' (matchcast-log-frames not found: MATCHCAST_LOG_FRAMES=...)'));
console.log(`  cpu:  module ${f(best.wasmCpu)}, native ${f(best.nativeCpu)}` +
  (Number.isFinite(best.nativeCpu) ? `: ratio ${(best.wasmCpu / best.nativeCpu).toFixed(2)}` : ''));
console.log(`machine: ${os.cpus().length} cores, load ${os.loadavg().map((x) => x.toFixed(1)).join(' ')}`);
