// The bridge between the wire and the page: reads the hello (JSON) into the
// page's match description, and turns binary pose frames, decoded by the
// proto engineer's decoder (web/lib/proto/decoder.js, spec in proto/SPEC.md),
// into the page's canonical frame shape (model/interp.js).
import { normalizeSkeleton } from '../model/skeleton.js';
import { normalizeField } from '../scene/pitch.js';

// The decoder module is loaded once; the page still runs (and says why it
// cannot draw frames) if it is missing.
let decoderModule = null;
export async function loadDecoder() {
  if (decoderModule) return decoderModule;
  decoderModule = await import('../../lib/proto/decoder.js');
  return decoderModule;
}

const num = (v, d = 0) => (Number.isFinite(Number(v)) ? Number(v) : d);

// hello JSON -> { skeleton, field, teams: {left, right}, frameRate, params, raw }
export function readHello(msg) {
  const skeleton = normalizeSkeleton(msg.skeleton);
  const field = normalizeField(msg.field);
  if (msg.field) {
    // The hello's names for the geometry the pitch builder calls otherwise.
    const f = msg.field;
    if (Number.isFinite(f.center_circle_radius)) field.centerCircleR = f.center_circle_radius;
    if (Number.isFinite(f.penalty_spot_distance)) field.penaltySpotDist = f.penalty_spot_distance;
    if (Number.isFinite(f.corner_arc_radius)) field.cornerArcR = f.corner_arc_radius;
  }
  const team = (t) => (t && typeof t === 'object' ? t : {});
  const teams = msg.teams ?? {};
  return {
    skeleton,
    field,
    teams: { left: team(msg.left ?? teams.left), right: team(msg.right ?? teams.right) },
    frameRate: num(msg.frame_rate ?? msg.frameRate, 20) || 20,
    params: msg.server_params ?? msg.serverParams ?? {},
    raw: msg,
  };
}

// Side as 1 (left) / -1 (right) from the forms a decoder may use.
function side(v) {
  if (v === 1 || v === 'l' || v === 'left' || v === 'L') return 1;
  if (v === -1 || v === 255 || v === 'r' || v === 'right' || v === 'R') return -1;
  return 0;
}

// A decoded frame (snake_case or camelCase) -> the page's canonical frame.
export function canonicalFrame(d) {
  const ball = d.ball ?? {};
  return {
    seq: num(d.seq),
    time: num(d.time),
    stoppage: num(d.stoppage),
    substep: num(d.substep),
    keyframe: !!(d.keyframe ?? d.key),
    serverTimeMs: num(d.server_time_ms ?? d.serverTimeMs),
    playMode: d.play_mode ?? d.playMode ?? 0,
    scoreLeft: num(d.score_left ?? d.scoreLeft),
    scoreRight: num(d.score_right ?? d.scoreRight),
    ball: { x: num(ball.x), y: num(ball.y), z: num(ball.z) },
    // Empty slots (side 0) are not players.
    players: (d.players ?? []).filter((p) => side(p.side) !== 0 && p.unum > 0).map((p) => ({
      side: side(p.side),
      unum: num(p.unum),
      state: num(p.state),
      x: num(p.x), y: num(p.y), z: num(p.z),
      heading: num(p.heading),
      angles: p.angles instanceof Float32Array ? p.angles : Float32Array.from(p.angles ?? []),
      stamina: p.stamina !== undefined ? num(p.stamina, NaN) : NaN,
    })),
    extras: d.extras ?? null,
  };
}

// One decoder per hello. decode() returns a canonical frame, or null while
// the decoder waits for a keyframe; it throws with a message on bad bytes.
export class Codec {
  constructor(mod, helloMsg) {
    this.mod = mod;
    if (typeof mod.parseHello === 'function') mod.parseHello(helloMsg);  // throws on a bad hello
    const Dec = mod.FrameDecoder ?? mod.Decoder ?? mod.default;
    if (typeof Dec === 'function') {
      this.decoder = new Dec(helloMsg.skeleton, helloMsg);
      this.decodeFn = (buf) => this.decoder.decode(buf);
    } else if (typeof mod.decodeFrame === 'function') {
      this.decodeFn = (buf) => mod.decodeFrame(buf, helloMsg.skeleton);
    } else {
      throw new Error('decoder.js exports no decoder');
    }
  }

  decode(buf) {
    const bytes = buf instanceof Uint8Array ? buf : new Uint8Array(buf);
    const out = this.decodeFn(bytes);
    if (out === null || out === undefined) return null;
    if (out.ok === false || out.error) throw new Error(out.error ?? 'decode failed');
    return canonicalFrame(out.frame ?? out);
  }
}
