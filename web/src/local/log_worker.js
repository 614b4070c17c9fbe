// The Web Worker that turns a log into the broadcast, off the page's main
// thread: it streams the file (or URL), gunzips it with the browser's
// DecompressionStream (inflate.js: nothing before a cut is lost), and feeds
// the bytes to the WebAssembly module (wasm/log_module.cpp: the server's
// ingest readers, anim/ and the proto encoder), a few megabytes ahead of
// the reader. What the module makes goes to the page as it is made, so the
// game plays while the rest is animated.
//
// Protocol (web/README.md, "Opening a log"):
//   page -> worker  { type: 'open', file | url, name, options: { keyframeInterval, lookahead, detail, baseMs } }
//   worker -> page  { type: 'ready', ms }               the module is compiled
//                   { type: 'data', buf }               records: u8 kind ('h' hello, 'k' keyframe,
//                                                       'f' frame, 'c' control), u32 LE length, bytes
//                   { type: 'progress', status }        the module's status (states, frames, bytes, time)
//                   { type: 'end', status }             the whole log went out
//                   { type: 'error', message, status }  it cannot go on; what went out stays valid
// The page ends a log by terminating the worker.
import createLogModule from '../../wasm/matchcast-log.js';
import { gunzipReader } from './inflate.js';

// A game log is 5 to 40 MB (1 to 4 MB gzipped); these bound the work and
// the memory a wrong file can take.
const MAX_FILE_BYTES = 512 * 1024 * 1024;
const MAX_DECODED_BYTES = 1024 * 1024 * 1024;
const CHUNK = 1 << 20;          // bytes copied into the module at a time
const FIRST_STEP_STATES = 10;   // a small first step: the first picture soon
const STEP_STATES = 200;

const mb = (n) => `${(n / 1e6).toFixed(n < 1e7 ? 1 : 0)} MB`;
const size = (n) => (n >= 1e9 ? `${(n / 1e9).toFixed(1)} GB` : mb(n));

class Refusal extends Error {}

self.onmessage = (e) => {
  if (e.data?.type !== 'open') return;
  run(e.data).catch((err) => {
    const message = err instanceof Refusal ? err.message : `Reading the log failed: ${err?.message ?? err}`;
    self.postMessage({ type: 'error', message, status: null });
  });
};

// The bytes of a File or URL as a stream, and the file's size if known.
async function openInput({ file, url }) {
  if (file) {
    if (file.size > MAX_FILE_BYTES) {
      throw new Refusal(`${file.name} is ${size(file.size)}: far more than a game log (a whole game is ` +
        `about 25 MB, 3 MB gzipped). Matchcast reads files up to ${size(MAX_FILE_BYTES)}.`);
    }
    return { stream: file.stream(), total: file.size };
  }
  let res;
  try {
    res = await fetch(url);
  } catch (err) {
    throw new Refusal(`The log at ${url} could not be fetched (${err.message}).`);
  }
  if (!res.ok || !res.body) throw new Refusal(`The log at ${url} could not be fetched: HTTP ${res.status}.`);
  const total = Number(res.headers.get('content-length')) || NaN;
  if (total > MAX_FILE_BYTES) throw new Refusal(`The log at ${url} is ${size(total)}: far more than a game log.`);
  return { stream: res.body, total };
}

// A reader of the log's bytes, gunzipped if they are gzip (the first chunk
// tells), counting the raw bytes that go by.
async function decodedReader(stream, counter) {
  const reader = stream.getReader();
  const first = await reader.read();
  const head = first.done ? new Uint8Array(0) : first.value;
  const gzip = head.length >= 2 && head[0] === 0x1f && head[1] === 0x8b;
  if (gzip) return { reader: gunzipReader(reader, head, (n) => { counter.raw += n; }), gzip };
  let pending = head.length ? head : null;
  counter.raw += head.length;
  const plain = {
    async read() {
      if (pending) { const value = pending; pending = null; return { value, done: false }; }
      if (first.done) return { value: undefined, done: true };
      const r = await reader.read();
      if (!r.done) counter.raw += r.value.length;
      return r;
    },
    cancel: (reason) => reader.cancel(reason),
  };
  return { reader: plain, gzip };
}

async function run({ file, url, name, options = {} }) {
  const t0 = performance.now();
  const modReady = createLogModule({
    locateFile: (p) => new URL(`../../wasm/${p}`, import.meta.url).href,
  });
  const input = await openInput({ file, url });
  const counter = { raw: 0 };
  const { reader, gzip } = await decodedReader(input.stream, counter);
  const mod = await modReady;
  self.postMessage({ type: 'ready', ms: performance.now() - t0 });

  const text = new TextEncoder().encode(`${name ?? ''}\0`);
  const namePtr = mod._malloc(text.length);
  mod.HEAPU8.set(text, namePtr);
  const s = mod._mc_open(options.keyframeInterval ?? 20, options.lookahead ?? 2, options.detail ?? 3,
    options.baseMs ?? 0, namePtr);
  mod._free(namePtr);
  const status = () => JSON.parse(mod.UTF8ToString(mod._mc_status(s)));
  const end = (why) => {
    const t = new TextEncoder().encode(`${why}\0`);
    const p = mod._malloc(t.length);
    mod.HEAPU8.set(t, p);
    mod._mc_end(s, p);
    mod._free(p);
  };

  let decoded = 0, ended = false, steps = 0, lastProgress = 0;
  for (;;) {
    while (!ended && mod._mc_wants(s) > 0) {
      let chunk;
      try {
        chunk = await reader.read();
      } catch (err) {
        // A cut or corrupt gzip stream: play what came before it.
        end(`the file's ${gzip ? 'gzip data ends' : 'data ends'} early, after ${mb(decoded)} of log` +
          ` (${String(err?.message ?? 'read error').replace(/^Failed to execute '[^']*' on '[^']*': /, '').replace(/\.$/, '')})`);
        ended = true;
        break;
      }
      if (chunk.done) { end(''); ended = true; break; }
      const v = chunk.value;
      for (let at = 0; at < v.length; at += CHUNK) {
        const n = Math.min(CHUNK, v.length - at);
        const p = mod._mc_buffer(n);
        mod.HEAPU8.set(v.subarray(at, at + n), p);
        mod._mc_input(s, n);
      }
      decoded += v.length;
      if (decoded > MAX_DECODED_BYTES) {
        reader.cancel().catch(() => {});
        end(`stopped after ${size(MAX_DECODED_BYTES)} of decoded data: far more than a game log`);
        ended = true;
      }
    }
    const r = mod._mc_step(s, steps++ === 0 ? FIRST_STEP_STATES : STEP_STATES);
    const n = mod._mc_output_size(s);
    if (n > 0) {
      const at = mod._mc_output(s);
      const buf = mod.HEAPU8.slice(at, at + n).buffer;
      mod._mc_output_clear(s);
      self.postMessage({ type: 'data', buf }, [buf]);
    }
    const now = performance.now();
    if (r >= 2 || now - lastProgress > 100) {
      lastProgress = now;
      const st = { ...status(), raw: counter.raw, total: input.total, gzip, ms: now - t0 };
      if (r === 2) { self.postMessage({ type: 'end', status: st }); break; }
      if (r === 3) { self.postMessage({ type: 'error', message: st.error, status: st }); break; }
      self.postMessage({ type: 'progress', status: st });
    }
  }
  reader.cancel().catch(() => {});
  mod._mc_close(s);
}
