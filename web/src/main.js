// The page: wires the stream to the jitter buffer, and the buffer to the
// scene, the cameras and the HUD, once per displayed frame.
//
// Decoding happens as messages arrive, rendering at the display's rate: a
// slow GPU renders fewer pictures but every stream frame is still decoded,
// so the state stays current.
import { createStage } from './scene/stage.js';
import { createPitch, normalizeField } from './scene/pitch.js';
import { Players } from './scene/players.js';
import { Ball } from './scene/ball.js';
import { Overlays } from './scene/overlays.js';
import { makeKit } from './scene/kit.js';
import { Cameras } from './cameras.js';
import { Director } from './director.js';
import { Stereo } from './stereo.js';
import { Hud } from './hud.js';
import { KickSound } from './audio.js';
import { bindControls, markCamera, updateReplayBar } from './controls.js';
import { JitterBuffer } from './net/jitter.js';
import { TimeShift } from './net/timeshift.js';
import { ServerReplay, listRecordings } from './recordings.js';
import { ServerShift } from './net/server_shift.js';
import { Stream } from './net/stream.js';
import { Codec, loadDecoder, readHello } from './net/codec.js';
import { blendFrames } from './model/interp.js';
import { keepFeet } from './model/feet.js';
import { Announcer } from './announcer.js';
import { STATE } from './model/playmodes.js';
import { LocalLogs } from './local/local_logs.js';

const params = new URLSearchParams(location.search);
const canvas = document.getElementById('view');
const stage = createStage(canvas, { antialias: params.get('aa') !== '0', shadows: params.get('shadows') !== '0' });
const hud = new Hud();
const sound = new KickSound();
const events = new Announcer(hud, sound);
const buffer = new JitterBuffer({ delayFrames: Number(params.get('delay') ?? 3) });
let timeshift = new TimeShift();   // a LogPlayback (local/playback.js) once a log is opened

let field = normalizeField({});
let pitch = createPitch(field, stage.renderer);
stage.scene.add(pitch);
const ball = new Ball(stage.scene);
const cameras = new Cameras(stage.camera, canvas, field);
const director = new Director(() => timeshift);   // the server's director track drives the default camera
cameras.director = director;
const stereo = new Stereo(stage, { get width() { return field.width; } });   // side by side (V), WebXR seats
let players = null;       // built from the hello's skeleton
let overlays = null;
let match = null;         // readHello() result
let codec = null;
let helloKey = '';
let timeshiftKey = null;
let selected = null;
let view = null;          // the interpolated frame on screen
const toggles = { labels: true, offside: false, reach: false, reachmap: false, sound: true, stats: params.has('stats') };
const counters = { frames: 0, decoded: 0, skipped: 0, decodeErrors: 0, badMessages: 0, hellos: 0,
  rendered: 0 };
let connection = 'connecting';

// --- the match description --------------------------------------------------

function applyHello(msg) {
  let info;
  try {
    info = readHello(msg);
  } catch (e) {
    counters.badMessages++;
    hud.status(`The server's hello is not usable: ${e.message}`, true);
    return false;
  }
  counters.hellos++;
  const key = JSON.stringify([msg.skeleton, msg.field, msg.left, msg.right, msg.teams]);
  if (key !== helloKey) {
    helloKey = key;
    if (JSON.stringify(info.field) !== JSON.stringify(field)) {
      field = info.field;
      stage.scene.remove(pitch);
      pitch = createPitch(field, stage.renderer);
      stage.scene.add(pitch);
      cameras.field = field;
    }
    players?.dispose();
    players = new Players(stage.scene, info.skeleton, info.teams);
    players.showLabels = toggles.labels;
    if (overlays) stage.scene.remove(overlays.group);
    overlays = new Overlays(stage.scene, field, info.params);
    overlays.showOffside = toggles.offside;
    overlays.showReach = toggles.reach;
    overlays.showReachMap = toggles.reachmap;
    const kl = makeKit('left', info.teams.left), kr = makeKit('right', info.teams.right);
    hud.setTeams({ name: kl.name, css: `#${kl.shirtColor.getHexString()}` },
      { name: kr.name, css: `#${kr.shirtColor.getHexString()}` });
  }
  match = info;
  if (Number.isFinite(info.params.half_time) && Number.isFinite(info.params.simulator_step))
    hud.cyclesPerSecond = 1000 / info.params.simulator_step;
  buffer.frameMs = 1000 / info.frameRate;
  events.frameMs = buffer.frameMs;
  // A new hello is a new session: frames start again from a keyframe.
  buffer.reset();
  events.reset();
  return true;
}

function pushFrame(frame) {
  counters.decoded++;
  buffer.push(frame, performance.now());
}

// --- the stream -------------------------------------------------------------

// A recording (?recording=NAME) or a channel (?channel=NAME) of the relay.
const recording = params.get('recording');
function wsQuery() {
  if (recording) return `?recording=${encodeURIComponent(recording)}`;
  return params.has('channel') ? `?channel=${encodeURIComponent(params.get('channel'))}` : '';
}
let serverReplay = null;
let serverShift = null;   // the relay's time shift on the live game (net/server_shift.js)

function startStream() {
  const wsUrl = params.get('ws') ??
    `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws${wsQuery()}`;
  const stream = new Stream(wsUrl, {
    onStatus(state, info) {
      connection = state;
      if (state === 'connecting' && counters.hellos === 0) hud.status('Connecting to the match feed…');
      else if (state === 'lost') {
        const s = Math.max(1, Math.round(info.delay / 1000));
        hud.status(`Feed lost. Reconnecting in ${s} s… (${info.reason})`, true);
      } else if (state === 'silent') hud.status('The feed has gone quiet. Waiting for data…', true);
    },
    onText(msg) {
      if (msg.type === 'hello') {
        const mod = decoderModule;
        if (!mod) {
          hud.status(`The frame decoder could not be loaded: ${decoderError}`, true);
          return;
        }
        if (!applyHello(msg)) return;
        try {
          codec = new Codec(mod, msg);
          // A reconnect to the same match keeps the history; a new skeleton
          // (or a stream that starts again, see TimeShift.record) does not.
          if (timeshiftKey !== helloKey) timeshift.reset(() => new Codec(mod, msg));
          timeshiftKey = helloKey;
          timeshift.frameMs = buffer.frameMs;
        } catch (e) {
          codec = null;
          hud.status(`The frame decoder refused the hello: ${e.message}`, true);
          return;
        }
        stream.healthy();
        hud.status(null);
      } else if (msg.type === 'error') {
        hud.toast(`Server: ${msg.message ?? msg.error ?? 'error'}`);
      } else {
        onControl(msg);
      }
    },
    onBinary(buf) {
      counters.frames++;
      if (!codec) { counters.skipped++; return; }
      let frame;
      try {
        frame = codec.decode(buf);
      } catch (e) {
        counters.decodeErrors++;
        hud.toast(`Bad frame (${e.message}). Resyncing at the next keyframe.`);
        return;
      }
      if (!frame) { counters.skipped++; return; }
      if (connection !== 'open') hud.status(null);
      connection = 'open';
      pushFrame(frame);
      // During the relay's time shift the frames are the past: not kept.
      if (!serverShift?.active) {
        timeshift.record(buf, frame);
        serverShift?.noteLive(frame);
      }
    },
    onBadMessage(err) {
      counters.badMessages++;
      hud.toast(`Bad message from the server: ${err}`);
    },
  });
  stream.start();
  return stream;
}

// Control messages other than the hello (SPEC.md section 5.2): none is
// drawn yet; unknown types are ignored (forward compatibility).
function onControl(msg) {
  counters.controls = (counters.controls ?? 0) + 1;
  lastControl = msg.type;
  if (msg.type === 'director') { director.cue(msg); return; }
  if (events.control(msg)) return;
  if (serverShift?.control(msg)) { showReplay(); return; }
  if (msg.type === 'replay' && serverReplay) serverReplay.status(msg);
  else if (msg.type === 'reach_map') {
    if (overlays && players && overlays.setReachMap(msg, { 1: players.kits[1].shirtColor, [-1]: players.kits[-1].shirtColor }))
      counters.reachMaps = (counters.reachMaps ?? 0) + 1;
  }
  else if (msg.type === 'feed') {
    if (msg.status === 'lost') hud.status(`The match feed is lost${msg.detail ? ` (${msg.detail})` : ''}. Waiting for it…`, true);
    else if (msg.status === 'back') hud.status(null);
  } else if (msg.type === 'stamina') {
    stamina = { 1: msg.left, [-1]: msg.right };  // by unum - 1, -1 for an empty slot
  } else if (msg.type === 'teams') {
    for (const [side, t] of [[1, msg.left], [-1, msg.right]]) if (t?.name && hud.teams?.[side]) hud.teams[side].name = t.name;
    if (hud.teams) hud.setTeams(hud.teams[1], hud.teams[-1]);
  }
}
let lastControl = null;
let stamina = null;  // the last "stamina" message: { 1: left[11], -1: right[11] }
// A player's stamina from the last "stamina" message, NaN when there is none.
function staminaOf(side, unum) {
  const v = stamina?.[side]?.[unum - 1];
  return Number.isFinite(v) && v >= 0 ? v : NaN;
}

// The decoder module is loaded before the socket opens, so that no frame
// arrives before there is something to decode it.
let decoderModule = null, decoderError = '';
let stream = null;
if (!params.has('fixture')) {
  try {
    decoderModule = await loadDecoder();
  } catch (e) {
    decoderError = e.message;
  }
}
// A log opened in the page (drop, button, ?log=URL) replaces the live feed.
const local = new LocalLogs({
  hud, applyHello, control: onControl,
  makeCodec: (msg) => new Codec(decoderModule, msg),
  useTimeshift: (pb) => { timeshift = pb; },
  stopLive: () => { stream?.stop(); stream = null; serverReplay = null; connection = 'local'; },
});
if (params.has('fixture')) {
  const { startFixture } = await import('./dev/fixture.js');
  startFixture({ onHello: (h) => { applyHello(h); hud.status(null); }, onFrame: (f) => { counters.frames++; pushFrame(f); } });
  connection = 'open';
} else if (!(await local.takesOver(params))) {
  hud.status('Connecting to the match feed…');
  stream = startStream();
  if (!recording) serverShift = new ServerShift((m) => stream.send(m));
  if (recording) serverReplay = new ServerReplay(recording, (m) => stream.send(m));
  listRecordings(document.getElementById('rec-list'), recording);
}

// --- user actions -----------------------------------------------------------

function nearestToBall() {
  if (!view) return null;
  let best = null, bd = Infinity;
  for (const p of view.players) {
    if (p.state === 0) continue;
    const d = Math.hypot(p.x - view.ball.x, p.y - view.ball.y);
    if (d < bd) { bd = d; best = `${p.side}:${p.unum}`; }
  }
  return best;
}

function select(key) {
  selected = key;
  if (players) players.selected = key;
}

const app = {
  setCamera(id) {
    if ((id === 'player' || id === 'follow' || id === 'closeup') && !selected) select(nearestToBall());
    cameras.setMode(id);
    director.setEnabled(cameras.mode === 'director');
    markCamera(cameras.mode);
  },
  cameraMode: () => cameras.mode,
  toggle(name) {
    toggles[name] = !toggles[name];
    if (name === 'labels' && players) players.showLabels = toggles.labels;
    if (name === 'offside' && overlays) overlays.showOffside = toggles.offside;
    if (name === 'reach' && overlays) overlays.showReach = toggles.reach;
    if (name === 'reachmap' && overlays) overlays.showReachMap = toggles.reachmap;
    if (name === 'sound') sound.enabled = toggles.sound;
    if (name === 'stats') hud.showStats(toggles.stats);
    return toggles[name];
  },
  selectAt(ndc) {
    const key = players?.pick(ndc, stage.camera);
    if (key) select(key);
  },
  cyclePlayer(dir) {
    if (!view) return;
    const keys = view.players.filter((p) => p.state !== 0).map((p) => `${p.side}:${p.unum}`);
    if (!keys.length) return;
    const i = keys.indexOf(selected);
    select(keys[(i + dir + keys.length) % keys.length]);
  },
  deselect() { select(null); },
  // Time shift over what the page has received (net/timeshift.js).
  replay(cmd, arg) {
    director.userShift();
    if (serverReplay) {
      serverReplay.command(cmd, arg);
      if (cmd === 'seek' || cmd.endsWith('goal')) events.jump();
      return;
    }
    if (serverShift?.active) {   // the relay's recording: the bar drives it
      serverShift.command(cmd, arg);
      events.jump();
      showReplay();
      return;
    }
    // Joined late (5 s or more after kick-off): the kick-off (the bar's left
    // end) and the goals before the page's own history are the relay's.
    if (serverShift && serverShift.firstLive > 50) {
      const at = timeshift.active ? timeshift.pos : timeshift.last - 100;
      const toStart = cmd === 'seek' && arg <= 0.01;
      const toGoal = cmd === 'prev_goal' && !timeshift.goals.some((g) => g < at);
      if (toStart || toGoal) {
        timeshift.live();
        serverShift.enter(toStart ? 0 : serverShift.liveTime, toGoal ? 'prev_goal' : null);
        events.jump();
        showReplay();
        return;
      }
    }
    const here = () => (view ? view.seq : timeshift.last);
    switch (cmd) {
      case 'toggle':
        if (!timeshift.active) timeshift.enter(here(), true);
        else timeshift.paused = !timeshift.paused;
        break;
      case 'seek': timeshift.seek(arg); break;
      case 'speed':
        if (!timeshift.active && arg < 1) timeshift.enter(here(), false);
        timeshift.speed = timeshift.active ? arg : 1;
        break;
      case 'prev_goal': timeshift.jumpGoal(-1); break;
      case 'next_goal': timeshift.jumpGoal(1); break;
      case 'live': timeshift.live(); break;
      default: return;
    }
    events.jump();   // no kick or goal fires for the jump itself
    showReplay();
  },
};
bindControls(app, canvas);
function showReplay() {
  if (serverReplay) { updateReplayBar(serverReplay.bar()); return; }
  if (serverShift?.active) { updateReplayBar(serverShift.bar()); return; }
  if (timeshift.bar) { updateReplayBar(timeshift.bar(hud.cyclesPerSecond)); return; }
  updateReplayBar({ available: timeshift.entries.length > 40, active: timeshift.active, paused: timeshift.paused,
    fraction: timeshift.fraction(), behindMs: timeshift.behindMs(), speed: timeshift.speed });
}
markCamera(cameras.mode);
hud.showStats(toggles.stats);
for (const [k, v] of Object.entries(toggles)) document.querySelector(`[data-toggle="${k}"]`)?.classList.toggle('on', v);

// --- the render loop --------------------------------------------------------

let lastNow = performance.now();
let lastDt = 0;   // the seconds the last picture moved the cameras on (at most 0.1)
const fpsWindow = [];
let renderMs = 0, updateMs = 0;
let lastStats = 0, lastBytes = 0, kbps = 0, lastAdapt = performance.now() + 2000;

function frameLoop(now) {
  const dt = Math.min(0.1, (now - lastNow) / 1000);
  lastNow = now;
  lastDt = dt;
  stage.resize();
  // Live frames come from the jitter buffer; a time-shifted picture from the
  // kept history. The buffer is sampled either way so that it stays current.
  // The director first: a replay it starts or ends moves the time shift.
  if (director.update(timeshift.active ? timeshift.pos : buffer.playhead, { streamSpeed: buffer.speed, now }).jumped)
    events.jump();
  const live = players ? buffer.sample(now) : null;
  const shifted = timeshift.active;
  let s = shifted ? timeshift.sample(now) : live;
  if (shifted && !timeshift.active) { events.jump(); s = live; }   // caught up with live
  if (s) {
    view = blendFrames(s.a, s.b, s.t, view);
    // Planted feet stay on their line between the frames, lifting ones clear
    // the grass (proto/SPEC.md 4.7 step 2); players.update rests the bodies on it.
    if (players) keepFeet(players.skel, s.a, s.b, s.t, view);
    // A director's replay is silent (no kicks or banners of the past again).
    if (!director.track.replaying) events.step(s.passed, timeshift.active ? timeshift.pos : buffer.playhead,
      timeshift.active ? (timeshift.paused ? 0 : timeshift.speed * 1000 / buffer.frameMs) : buffer.rate);
    players.update(view.players, { stamina, staminaMax: match?.params?.stamina_max, playMode: view.playMode, ball: view.ball });
    ball.update(view.ball);
    const colors = { 1: players.kits[1].shirtColor, [-1]: players.kits[-1].shirtColor };
    overlays.update(view, colors);
    hud.update(view);
    const rig = selected ? players.get(selected) : null;
    hud.player(rig?.pose ? { side: rig.side, unum: rig.unum, goalie: (rig.pose.state & STATE.GOALIE) !== 0,
      stamina: staminaOf(rig.side, rig.unum), staminaMax: match?.params?.stamina_max } : null);
  }
  const hide = cameras.update(dt, { ball: view?.ball ?? { x: 0, y: 0, z: 0 }, players, selected,
    at: timeshift.active ? timeshift.pos : buffer.playhead });
  if (players && players.hiddenKey !== hide) players.hiddenKey = hide;
  const t0 = performance.now();
  stereo.render();
  renderMs += (performance.now() - t0 - renderMs) * 0.1;
  updateMs += (t0 - now - updateMs) * 0.1;
  counters.rendered++;

  fpsWindow.push(now);
  while (fpsWindow.length && fpsWindow[0] < now - 1000) fpsWindow.shift();
  if (now - lastAdapt > 1000 && !params.has('fixed-quality')) {
    lastAdapt = now;
    stage.adapt(fpsWindow.length);
  }
  if (now - lastStats > 500) {
    const bytes = stream?.bytes ?? 0;
    kbps = ((bytes - lastBytes) * 8) / 1000 / ((now - lastStats) / 1000);
    lastBytes = bytes;
    lastStats = now;
    showReplay();
    hud.stats({ fps: fpsWindow.length, kbps, delayMs: view?.serverTimeMs && connection !== 'local' ? Date.now() - view.serverTimeMs : NaN,
      dropped: buffer.dropped + buffer.late + counters.decodeErrors + counters.skipped });
  }
}
// The renderer's loop: the display's rate, or the headset's in WebXR.
stage.renderer.setAnimationLoop(frameLoop);

// --- a read-only hook for tests and curious users -----------------------------

window.matchcast = Object.freeze({
  stats: () => ({
    ...counters, ...events.counts, connection, connects: stream?.connects ?? 0, camera: cameras.mode,
    director: director.stats(), bodies: players?.lodCounts() ?? null, stereo: stereo.stats(),
    buffered: buffer.size, dropped: buffer.dropped, late: buffer.late, resyncs: buffer.resyncs,
    fps: fpsWindow.length, kbps, seq: view?.seq ?? null, time: view?.time ?? null,
    playMode: view?.playMode ?? null, selected, hello: !!match,
    teams: match ? [hud.teams[1].name, hud.teams[-1].name] : null,
    banner: hud.lastBanner ?? null, banners: hud.recentBanners ?? [], serverReplay: serverReplay?.state ?? null, lastControl,
    serverShift: serverShift?.stats() ?? null,
    local: local.stats(),
    timeshift: { active: timeshift.active, paused: timeshift.paused, pos: timeshift.pos, first: timeshift.first,
      last: timeshift.last, goals: [...timeshift.goals], bytes: timeshift.bytes, speed: timeshift.speed }, sounds: sound.played, renderMs, updateMs, scale: stage.scale,
    // What the last picture cost the GPU (three.js counts per render): the
    // budget that decides 60 frames/s on a real GPU, which headless
    // software rendering cannot show.
    draw: { calls: stage.renderer.info.render.calls, triangles: stage.renderer.info.render.triangles },
  }),
  playerPositions: () => (view ? view.players.map((p) => ({ side: p.side, unum: p.unum, state: p.state,
    x: p.x, y: p.y, z: p.z, heading: p.heading })) : []),
  ball: () => (view ? { ...view.ball } : null),
  cameraPosition: () => stage.camera.position.toArray(),
  // The camera with the time the last picture moved it on: its own clock,
  // which a stalled browser holds to 0.1 s a picture.
  cameraStep: () => ({ p: stage.camera.position.toArray(), dt: lastDt }),
  setCamera: (id) => app.setCamera(id),
  select: (key) => select(key),
  toggle: (name) => app.toggle(name),
  // Holds the picture still at a stream position (seq; a fraction draws
  // the clients' blend in between), as the replay bar's pause would: the
  // close-up contact sheet draws one frame at a time (issue 23). Anything
  // but a finite number is refused (false), never a NaN playhead.
  pauseAt: (seq) => typeof seq === 'number' && Number.isFinite(seq) && timeshift.enter(seq, true),
  // Where a player's chest is on the screen (CSS px), for click tests.
  screenOf: (key) => {
    const rig = players?.get(key);
    if (!rig?.pose || !rig.root.visible) return null;
    const v = rig.root.position.clone();
    v.y += 0.3;
    v.project(stage.camera);
    if (v.z > 1) return null;
    const r = canvas.getBoundingClientRect();
    return { x: r.left + (v.x + 1) / 2 * r.width, y: r.top + (1 - v.y) / 2 * r.height };
  },
});
