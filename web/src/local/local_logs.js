// Opening a log in the page, with no server: a file dropped on the page,
// chosen with the "Open log" button, or given as ?log=URL. A Web Worker
// (log_worker.js) runs the WebAssembly pipeline over it; its frames fill a
// LogPlayback (the replay bar's history) as they are made, so the game
// plays from the first keyframe while the rest is animated. The worker and
// the module load only when a log is opened: a live spectator never
// downloads them.
//
// On a static host (no Matchcast server answers /healthz) the page opens
// no WebSocket and says so; served by a relay it goes live as before.
import { peekHeader } from '../../lib/proto/messages.js';
import { LogPlayback } from './playback.js';

const STYLE = `
#log-open input { display: none; }
#log-drop { position: fixed; inset: 0; display: none; align-items: center; justify-content: center;
  background: rgba(10, 20, 30, .55); color: #fff; font-size: 24px; z-index: 20; pointer-events: none;
  border: 4px dashed rgba(255,255,255,.6); }
#log-drop.show { display: flex; }
#log-note { position: fixed; top: 56px; left: 10px; padding: 6px 10px; font-size: 12px;
  max-width: min(460px, 80vw); }
#log-note.warn { color: #ffd6a0; }
@media (max-width: 640px) { #log-note { top: 96px; } }
/* The chosen player's card sits where the note is: below it while it shows. */
body:has(#log-note:not([hidden])) #player-card { top: 112px; }
@media (max-width: 640px) { body:has(#log-note:not([hidden])) #player-card { top: 150px; } }
`;

const mb = (n) => `${(n / 1e6).toFixed(1)} MB`;

// host: { hud, applyHello(msg) -> bool, makeCodec(msg), control(msg),
//         useTimeshift(playback), stopLive(), showReplay() }
export class LocalLogs {
  constructor(host) {
    this.host = host;
    this.worker = null;
    this.playback = null;
    this.state = null;       // for window.matchcast.stats().local
    this.opened = 0;
    this._ui();
  }

  // ?log=URL opens that log; otherwise a page with no relay behind it says
  // so and waits for a file. True when the page must not go live.
  async takesOver(params) {
    const url = params.get('log');
    if (url) {
      // Relative to the page (the worker would resolve it against its own script).
      let abs = url;
      try { abs = new URL(url, location.href).href; } catch { /* the worker says it cannot fetch it */ }
      this.open({ url: abs, name: decodeURIComponent(url.split('/').pop() || url) });
      return true;
    }
    if (params.has('ws')) return false;   // an explicit relay elsewhere
    let relay = false;
    try {
      const res = await fetch('./healthz', { cache: 'no-store' });
      relay = res.ok && (await res.text()).trim() === 'ok';
    } catch { /* no answer: a static host, or offline */ }
    if (relay) return false;
    this.host.hud.status('No live game here: this copy of the page is served without a Matchcast server. ' +
      'Drop a .rcg or .rcg.gz game log onto the page, or choose one with “Open log”, to watch it in 3D. ' +
      'The log stays on this computer.');
    this.state = { phase: 'static' };
    return true;
  }

  // Opens { file } or { url, name }: ends the live feed or the previous log.
  open({ file, url, name }) {
    this.worker?.terminate();
    this.host.stopLive();
    this.opened = performance.now();
    name = name ?? file?.name ?? 'log';
    this.name = name;
    this.state = { phase: 'opening', name, frames: 0, controls: 0,
      readyMs: null, firstDataMs: null, endMs: null, status: null, error: null, warning: null };
    this.host.hud.status(`Opening ${name}…`);
    this._note(`${name}: loading the log reader…`);
    this.hello = null;
    const pb = new LogPlayback();
    pb.onMessage = (m) => this.host.control(m);
    this.playback = pb;
    this.host.useTimeshift(pb);
    document.getElementById('rp-live')?.setAttribute('hidden', '');

    const worker = new Worker(new URL('./log_worker.js', import.meta.url), { type: 'module' });
    this.worker = worker;
    worker.onerror = (e) => {
      e.preventDefault?.();
      this._fail(`The log reader could not start (${e.message || 'the WebAssembly module is missing: run scripts/build-wasm.sh'}).`);
    };
    worker.onmessage = ({ data }) => {
      if (worker !== this.worker) return;
      if (data.type === 'ready') this.state.readyMs = data.ms;
      else if (data.type === 'data') this._records(new Uint8Array(data.buf));
      else if (data.type === 'progress') this._progress(data.status);
      else if (data.type === 'end') this._end(data.status);
      else if (data.type === 'error') this._error(data.message, data.status);
    };
    worker.postMessage({ type: 'open', file, url, name, options: { baseMs: Date.now() } });
  }

  // Records from the worker: hello, frames, control messages, in wire order.
  _records(bytes) {
    const st = this.state;
    if (st.firstDataMs === null) st.firstDataMs = performance.now() - this.opened;
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const text = new TextDecoder();
    for (let i = 0; i + 5 <= bytes.length;) {
      const kind = String.fromCharCode(bytes[i]);
      const n = dv.getUint32(i + 1, true);
      const body = bytes.subarray(i + 5, i + 5 + n);
      i += 5 + n;
      if (kind === 'k' || kind === 'f') {
        if (!this.hello) continue;
        const h = peekHeader(body);
        this.playback.record(body, { seq: h.seq, keyframe: h.keyframe, playMode: h.playMode, time: h.time });
        st.frames++;
      } else if (kind === 'h') {
        this._hello(JSON.parse(text.decode(body)));
      } else if (kind === 'c') {
        const msg = JSON.parse(text.decode(body));
        st.controls++;
        // Moments (stamina, reach maps) wait for the playhead; events are
        // timed by the announcer's track; the rest applies at once.
        if (msg.type === 'stamina' || msg.type === 'reach_map') this.playback.addTimed(msg.seq, msg);
        else this.host.control(msg);
      }
    }
  }

  // What happened so far, for window.matchcast.stats().local (tests).
  stats() {
    if (!this.state) return null;
    const pb = this.playback;
    const since = (t) => (t !== null && t !== undefined && t >= this.opened ? t - this.opened : null);
    // Ready: the first keyframe is in the playback; sampled: it went to the
    // renderer; shown: that picture is drawn.
    return { ...this.state, firstReadyMs: since(pb?.ready), firstSampledMs: since(pb?.firstSampled),
      firstShownMs: since(pb?.firstShown),
      complete: pb?.complete ?? false, kept: pb?.entries.length ?? 0 };
  }

  _hello(msg) {
    if (!this.host.applyHello(msg)) { this._fail('The log reader made a hello this page cannot use.'); return; }
    this.hello = msg;
    const pb = this.playback;
    pb.reset(() => this.host.makeCodec(msg));
    pb.frameMs = 1000 / (msg.frame_rate ?? 20);
    this.state.phase = 'playing';
    this.host.hud.status(null);
  }

  _progress(s) {
    this.state.status = s;
    const pct = Number.isFinite(s.total) && s.total > 0 ? ` ${Math.min(99, Math.round(100 * s.raw / s.total))} %` : '';
    this._note(`${this.name} (${s.format}): animating…${pct}, cycle ${s.time}`);
  }

  _end(s) {
    const st = this.state;
    st.status = s;
    st.endMs = performance.now() - this.opened;
    st.phase = 'done';
    this.playback.complete = true;
    const facts = `${this.name} (${s.format}, ${mb(s.bytes)}): ${s.states} states, ${s.frames} frames, ` +
      `animated in ${(st.endMs / 1000).toFixed(1)} s`;
    const warn = [];
    if (s.ended_early) warn.push(`The log is cut off: ${s.ended_early}. It plays up to cycle ${s.time}.`);
    if (s.capped) warn.push(`Only the first ${s.capped} states were read (a game has about 6,000).`);
    if (s.skipped) warn.push(`${s.skipped} damaged record${s.skipped > 1 ? 's were' : ' was'} skipped (${s.errors?.[0] ?? ''}).`);
    st.warning = warn.join(' ') || null;
    this._note(warn.length ? `${facts}. ${st.warning}` : facts, warn.length > 0);
    this.worker?.terminate();
    this.worker = null;
  }

  _error(message, s) {
    this.state.status = s;
    if (s && s.frames > 0) {
      // Frames went out before the problem: they play; say where it stops.
      this._end(s);
      this.state.phase = 'done';
      this.state.error = message;
      this._note(`${this.name}: ${message}. It plays up to cycle ${s.time}.`, true);
      return;
    }
    this._fail(message.match(/[.!?]$/) ? message : `${this.name}: ${message}.`);
  }

  _fail(message) {
    this.state.phase = 'failed';
    this.state.error = message;
    this.worker?.terminate();
    this.worker = null;
    this.host.hud.status(`${message} Drop another file, or choose one with “Open log”.`, true);
    this._note(message, true);
  }

  _note(text, warn = false) {
    this.note.textContent = text;
    this.note.hidden = !text;
    this.note.classList.toggle('warn', warn);
  }

  // The "Open log" button, the drop zone and the note line.
  _ui() {
    const style = document.createElement('style');
    style.textContent = STYLE;
    document.head.appendChild(style);

    this.note = document.createElement('div');
    this.note.id = 'log-note';
    this.note.className = 'panel';
    this.note.hidden = true;
    this.note.setAttribute('role', 'status');
    document.body.appendChild(this.note);

    const label = document.createElement('label');
    label.id = 'log-open';
    label.className = 'button';
    label.title = 'Open a game log (.rcg, .rcg.gz) from this computer';
    label.innerHTML = '<button type="button">Open log</button><input type="file" accept=".rcg,.gz,.json,application/gzip">';
    const input = label.querySelector('input');
    label.querySelector('button').addEventListener('click', () => input.click());
    input.addEventListener('change', () => {
      if (input.files?.[0]) this.open({ file: input.files[0] });
      input.value = '';
    });
    (document.getElementById('toggle-bar') ?? document.body).appendChild(label);

    const drop = document.createElement('div');
    drop.id = 'log-drop';
    drop.textContent = 'Drop a .rcg or .rcg.gz game log to watch it';
    document.body.appendChild(drop);
    let depth = 0;
    const hasFiles = (e) => [...(e.dataTransfer?.types ?? [])].includes('Files');
    window.addEventListener('dragenter', (e) => { if (hasFiles(e)) { depth++; drop.classList.add('show'); } });
    window.addEventListener('dragleave', () => { if (--depth <= 0) { depth = 0; drop.classList.remove('show'); } });
    window.addEventListener('dragover', (e) => { if (hasFiles(e)) e.preventDefault(); });
    window.addEventListener('drop', (e) => {
      depth = 0;
      drop.classList.remove('show');
      if (!hasFiles(e)) return;
      e.preventDefault();   // never let the browser navigate to the file
      const f = e.dataTransfer.files?.[0];
      if (f) this.open({ file: f });
    });
  }
}
