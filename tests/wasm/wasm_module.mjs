// Runs the page's WebAssembly log module (web/wasm/matchcast-log.js, built
// by scripts/build-wasm.sh) in node, the way web/src/local/log_worker.js
// does in the browser: decoded bytes in chunks while it wants them, steps of
// a few states, output records collected. For the byte-identity test and the
// benchmark.
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { gunzipSync } from 'node:zlib';

export const WEB = process.env.MATCHCAST_WEB_DIR ?? path.resolve(import.meta.dirname, '../../web');
export const MODULE_JS = path.join(WEB, 'wasm', 'matchcast-log.js');
export const MODULE_WASM = path.join(WEB, 'wasm', 'matchcast-log.wasm');
export const moduleBuilt = () => existsSync(MODULE_JS) && existsSync(MODULE_WASM);

export async function loadModule() {
  const { default: createLogModule } = await import(pathToFileURL(MODULE_JS).href);
  // ENVIRONMENT=web,worker: in node the binary is handed over, not fetched.
  return createLogModule({ wasmBinary: readFileSync(MODULE_WASM) });
}

// A log's decoded bytes (gzip inflated, as the page's DecompressionStream does).
export function decodedLog(file) {
  const raw = readFileSync(file);
  return raw[0] === 0x1f && raw[1] === 0x8b ? gunzipSync(raw) : raw;
}

function cString(mod, s) {
  const b = new TextEncoder().encode(`${s}\0`);
  const p = mod._malloc(b.length);
  mod.HEAPU8.set(b, p);
  return p;
}

// Runs one session over `bytes`; resolves { out: Buffer, status, firstFrameMs, totalMs }.
export function runLog(mod, bytes, { chunk = 1 << 20, firstStep = 10, step = 200, baseMs = 0, matchId = 'log',
  keyframeInterval = 20, lookahead = 2, detail = 3 } = {}) {
  const t0 = performance.now();
  const idp = cString(mod, matchId);
  const s = mod._mc_open(keyframeInterval, lookahead, detail, baseMs, idp);
  mod._free(idp);
  const parts = [];
  let at = 0, ended = false, steps = 0, r = 0, firstFrameMs = null;
  for (;;) {
    while (!ended && mod._mc_wants(s) > 0) {
      if (at >= bytes.length) {
        const p = cString(mod, '');
        mod._mc_end(s, p);
        mod._free(p);
        ended = true;
        break;
      }
      const n = Math.min(chunk, bytes.length - at);
      const p = mod._mc_buffer(n);
      mod.HEAPU8.set(bytes.subarray(at, at + n), p);
      mod._mc_input(s, n);
      at += n;
    }
    r = mod._mc_step(s, steps++ === 0 ? firstStep : step);
    const n = mod._mc_output_size(s);
    if (n > 0) {
      const o = mod._mc_output(s);
      const out = Buffer.from(mod.HEAPU8.slice(o, o + n));
      mod._mc_output_clear(s);
      if (firstFrameMs === null && records(out).some((x) => x.kind === 'k')) firstFrameMs = performance.now() - t0;
      parts.push(out);
    }
    if (r >= 2) break;
  }
  const status = JSON.parse(mod.UTF8ToString(mod._mc_status(s)));
  mod._mc_close(s);
  return { out: Buffer.concat(parts), status, firstFrameMs, totalMs: performance.now() - t0, rc: r };
}

// Output records: [{ kind, bytes }].
export function records(buf) {
  const out = [];
  for (let i = 0; i + 5 <= buf.length;) {
    const n = buf.readUInt32LE(i + 1);
    out.push({ kind: String.fromCharCode(buf[i]), bytes: buf.subarray(i + 5, i + 5 + n) });
    i += 5 + n;
  }
  return out;
}
