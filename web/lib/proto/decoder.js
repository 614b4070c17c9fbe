// Matchcast pose-stream decoder for browsers and Node (ES module, no
// dependencies). It mirrors proto/frame_decoder.cpp bit for bit; the
// normative description is proto/SPEC.md. Both decoders pass the golden
// vectors in tests/proto/golden/.
//
// WebSocket framing: binary messages are pose frames (decode them with
// FrameDecoder); text messages are JSON control messages with a "type"
// (parseControl / parseHello).

export const PROTOCOL_MAJOR = 1;
export const PROTOCOL_MINOR = 0;
export const FRAME_MAGIC = 0x4d;
export const HEADER_SIZE = 26;
export const ANGLE_STEP_MDEG = 900;
export const POSITION_STEP_M = 0.01;
export const HEADING_STEPS = 400;
export const MAX_PLAYERS = 22;
export const MAX_DOF = 64;

const POS_MIN = -32768;
const POS_MAX = 32767;
const ESCAPE_RUN = 16;
const MAX_K = 24;
const HALVE_AT = 32;

/** Parses any text control message; throws Error when it is not a JSON object with a string "type". */
export function parseControl(text) {
  let msg;
  try {
    msg = JSON.parse(text);
  } catch (e) {
    throw new Error(`control message is not JSON: ${e.message}`);
  }
  if (msg === null || typeof msg !== 'object' || Array.isArray(msg) || typeof msg.type !== 'string') {
    throw new Error('control message has no "type"');
  }
  return msg;
}

/** Parses and checks a hello message; throws Error on an unknown major version or missing fields. */
export function parseHello(text) {
  const msg = typeof text === 'string' ? parseControl(text) : text;
  if (msg.type !== 'hello') throw new Error(`expected a hello message, got "${msg.type}"`);
  const major = msg.protocol && msg.protocol.major;
  if (major !== PROTOCOL_MAJOR) {
    throw new Error(`unsupported protocol major version ${major} (this client reads version ${PROTOCOL_MAJOR})`);
  }
  const sk = msg.skeleton;
  if (!sk || !Array.isArray(sk.joints)) throw new Error('bad hello: no skeleton');
  for (const [i, j] of sk.joints.entries()) {
    if (typeof j.dofs !== 'string' || !Array.isArray(j.limits)) throw new Error(`bad hello: joint ${i} has no dofs/limits`);
    if (!Number.isInteger(j.parent) || j.parent < -1 || j.parent >= i) throw new Error(`bad hello: joint ${i} has a bad parent`);
  }
  return msg;
}

/** Reads the 26-byte header without decoding the body. Throws on short input, bad magic or unknown major. */
export function peekHeader(buffer) {
  const bytes = toBytes(buffer);
  if (bytes.length < HEADER_SIZE) {
    throw new Error(`pose frame truncated: ${bytes.length} bytes, the header alone is ${HEADER_SIZE}`);
  }
  if (bytes[0] !== FRAME_MAGIC) throw new Error(`not a pose frame: bad magic byte ${bytes[0]}`);
  const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const h = {
    major: bytes[1],
    minor: bytes[2],
    keyframe: (bytes[3] & 1) !== 0,
    seq: dv.getUint32(4, true),
    time: dv.getInt32(8, true),
    stoppage: dv.getUint16(12, true),
    substep: bytes[14],
    playMode: bytes[15],
    scoreLeft: bytes[16],
    scoreRight: bytes[17],
    // Unix ms fits a double exactly (< 2^53).
    serverTimeMs: dv.getUint32(18, true) + dv.getUint32(22, true) * 4294967296,
  };
  if (h.major !== PROTOCOL_MAJOR) {
    throw new Error(`unsupported pose-frame protocol major version ${h.major} (this decoder reads version ${PROTOCOL_MAJOR})`);
  }
  return h;
}

function toBytes(buffer) {
  if (buffer instanceof Uint8Array) return buffer;
  if (buffer instanceof ArrayBuffer) return new Uint8Array(buffer);
  if (ArrayBuffer.isView(buffer)) return new Uint8Array(buffer.buffer, buffer.byteOffset, buffer.byteLength);
  throw new Error('pose frame must be an ArrayBuffer or a typed array');
}

// LSB-first bit reader; reads past the end return 0 and set `overrun`.
class BitReader {
  constructor(bytes) {
    this.bytes = bytes;
    this.totalBits = bytes.length * 8;
    this.pos = 0;
    this.overrun = false;
  }
  get(bits) {
    let value = 0;
    for (let i = 0; i < bits; i++) {
      if (this.pos >= this.totalBits) {
        this.overrun = true;
        return 0;
      }
      const bit = (this.bytes[this.pos >>> 3] >>> (this.pos & 7)) & 1;
      value += bit * 2 ** i;
      this.pos++;
    }
    return value;
  }
  varbits() {
    const len = this.get(5);
    if (len === 0) return 0;
    if (len === 1) return 1;
    return 2 ** (len - 1) + this.get(len - 1);
  }
}

// Adaptive Golomb-Rice context (proto/bit_io.hpp RiceContext).
class Rice {
  constructor() {
    this.reset();
  }
  reset() {
    this.sum = 4;
    this.count = 1;
  }
  k() {
    let k = 0;
    while (k < MAX_K && this.count * 2 ** k < this.sum) k++;
    return k;
  }
  read(r) {
    const k = this.k();
    let q = 0;
    while (q < ESCAPE_RUN && r.get(1) === 1) q++;
    const u = q === ESCAPE_RUN ? r.get(32) : q * 2 ** k + r.get(k);
    this.sum += u;
    if (++this.count >= HALVE_AT) {
      this.sum = Math.floor((this.sum + 1) / 2);
      this.count = Math.floor(this.count / 2);
    }
    return u % 2 === 1 ? -(u - 1) / 2 - 1 : u / 2;
  }
}

/** The quantization grid of each dof, from the hello's skeleton (proto/quantizer.cpp). */
export function buildGrids(skeleton) {
  const grids = [];
  for (const joint of skeleton.joints) {
    for (let d = 0; d < joint.dofs.length && grids.length < MAX_DOF; d++) {
      let lo = -180;
      let hi = 180;
      if (d < joint.limits.length) [lo, hi] = joint.limits[d];
      const loM = roundHalfAway(Math.fround(lo) * 1000);
      const hiM = Math.max(loM, roundHalfAway(Math.fround(hi) * 1000));
      const steps = Math.floor((hiM - loM + ANGLE_STEP_MDEG - 1) / ANGLE_STEP_MDEG) + 1;
      let bits = 0;
      while (bits < 31 && 2 ** bits <= steps - 1) bits++;
      grids.push({ loM, hiM, steps, bits });
    }
  }
  return grids;
}

/** FNV-1a over dof count and each grid's (lo, steps), as int32 little-endian. */
export function skeletonFingerprint(grids) {
  let h = 2166136261;
  const mix = (v) => {
    const u = v >>> 0;
    for (let i = 0; i < 4; i++) {
      h ^= (u >>> (8 * i)) & 0xff;
      h = Math.imul(h, 16777619) >>> 0;
    }
  };
  mix(grids.length);
  for (const g of grids) {
    mix(g.loM);
    mix(g.steps);
  }
  return h >>> 0;
}

// JS Math.round rounds -0.5 up; C++ std::lround rounds half away from zero.
// Limits are floats in JSON, so use the symmetric rule to match.
function roundHalfAway(x) {
  return x < 0 ? -Math.round(-x) : Math.round(x);
}

function signed16(u) {
  return u >= 32768 ? u - 65536 : u;
}
function clamp(v, lo, hi) {
  return v < lo ? lo : v > hi ? hi : v;
}
function wrapHeading(v) {
  const m = v % HEADING_STEPS;
  return m < 0 ? m + HEADING_STEPS : m;
}
function wrapSigned(v) {
  return wrapHeading(v + HEADING_STEPS / 2) - HEADING_STEPS / 2;
}

function emptyQuant(dofs) {
  const players = [];
  for (let i = 0; i < MAX_PLAYERS; i++) {
    players.push({ side: 0, unum: 0, state: 0, x: 0, y: 0, z: 0, heading: 0, angles: new Int32Array(dofs) });
  }
  return { ball: [0, 0, 0], players };
}

export class FrameDecoder {
  /** @param skeleton the "skeleton" object of the hello (joints with dofs and limits). */
  constructor(skeleton) {
    if (!skeleton || !Array.isArray(skeleton.joints)) throw new Error('FrameDecoder needs the hello skeleton');
    this.grids = buildGrids(skeleton);
    this.dofCount = this.grids.length;
    this.fingerprint = skeletonFingerprint(this.grids);
    this.ctx = { ballXY: new Rice(), ballZ: new Rice(), posXY: new Rice(), posZ: new Rice(), heading: new Rice() };
    this.angleCtx = this.grids.map(() => new Rice());
    this.prev = emptyQuant(this.dofCount);
    this.prev2 = emptyQuant(this.dofCount);
    this.history = 0;
    this.lastSeq = 0;
  }

  /** True once a keyframe was decoded and no gap or error happened since. */
  get synced() {
    return this.history > 0;
  }

  /**
   * Decodes one binary WebSocket message. Throws Error with a clear message
   * when the frame is truncated or corrupt, the version is unknown, the
   * keyframe is for another skeleton, or a delta arrives without its base;
   * the decoder then waits for the next keyframe.
   */
  decode(buffer) {
    const bytes = toBytes(buffer);
    const h = peekHeader(bytes);
    try {
      if (h.playMode >= 52) throw new Error(`corrupt pose frame: play mode ${h.playMode} is not defined`);
      if (!h.keyframe) {
        if (this.history === 0) throw new Error(`delta frame ${h.seq} without its base: waiting for a keyframe`);
        if (h.seq !== ((this.lastSeq + 1) >>> 0)) {
          throw new Error(`gap before delta frame ${h.seq} (last frame was ${this.lastSeq}): waiting for a keyframe`);
        }
      }
      const r = new BitReader(bytes.subarray(HEADER_SIZE));
      const q = h.keyframe ? this.#readKeyframe(r) : this.#readDelta(r);
      if (r.overrun) throw new Error(`${h.keyframe ? 'key' : 'delta '}frame ${h.seq} truncated`);
      if (h.minor === PROTOCOL_MINOR && r.totalBits - r.pos >= 8) {
        throw new Error(`corrupt pose frame ${h.seq}: ${Math.floor((r.totalBits - r.pos) / 8)} unexpected trailing bytes`);
      }
      if (h.keyframe) {
        for (const c of Object.values(this.ctx)) c.reset();
        for (const c of this.angleCtx) c.reset();
        this.prev = q;
        this.history = 1;
      } else {
        this.prev2 = this.prev;
        this.prev = q;
        this.history = Math.min(this.history + 1, 2);
      }
      this.lastSeq = h.seq;
      return this.#dequantize(h, q);
    } catch (e) {
      this.history = 0;
      throw e;
    }
  }

  #predict(a1, a0, lo, hi) {
    return clamp(this.history >= 2 ? 2 * a1 - a0 : a1, lo, hi);
  }
  #predictHeading(a1, a0) {
    return this.history >= 2 ? wrapHeading(a1 + wrapSigned(a1 - a0)) : a1;
  }

  #readKeyframe(r) {
    // Contexts restart at every keyframe (done after a successful decode; a
    // keyframe itself uses no Rice codes).
    const q = emptyQuant(this.dofCount);
    const fp = r.get(32);
    if (!r.overrun && fp !== this.fingerprint) {
      throw new Error(`keyframe was encoded for a different skeleton (fingerprint ${fp}, expected ${this.fingerprint})`);
    }
    for (let a = 0; a < 3; a++) q.ball[a] = signed16(r.get(16));
    for (const p of q.players) {
      p.side = r.get(2);
      p.unum = r.get(4);
      p.state = r.varbits();
      p.x = signed16(r.get(16));
      p.y = signed16(r.get(16));
      p.z = signed16(r.get(16));
      p.heading = r.get(9);
      if (p.heading >= HEADING_STEPS) throw new Error(`corrupt keyframe: heading index ${p.heading} out of range`);
      for (let d = 0; d < this.dofCount; d++) {
        const v = r.get(this.grids[d].bits);
        if (v >= this.grids[d].steps) throw new Error(`corrupt keyframe: angle index out of range for dof ${d}`);
        p.angles[d] = v;
      }
      if (r.overrun) break;
    }
    return q;
  }

  #readDelta(r) {
    const p1 = this.prev;
    const p0 = this.prev2;
    const q = emptyQuant(this.dofCount);
    const corrupt = (what) =>
      new Error(r.overrun ? 'delta frame truncated' : `corrupt delta frame: ${what} out of range`);
    const apply = (pred, res, lo, hi, what) => {
      const v = pred + res;
      if (v < lo || v > hi) throw corrupt(what);
      return v;
    };
    const ballMoved = r.get(1) === 1;
    for (let a = 0; a < 3; a++) {
      const res = !ballMoved ? 0 : a < 2 ? this.ctx.ballXY.read(r) : this.ctx.ballZ.read(r);
      q.ball[a] = apply(this.#predict(p1.ball[a], p0.ball[a], POS_MIN, POS_MAX), res, POS_MIN, POS_MAX, 'ball position');
    }
    for (let i = 0; i < MAX_PLAYERS; i++) {
      const p = q.players[i];
      const a1 = p1.players[i];
      const a0 = p0.players[i];
      p.side = a1.side;
      p.unum = a1.unum;
      p.state = a1.state;
      if (r.get(1) === 1) {
        p.side = r.get(2);
        p.unum = r.get(4);
        p.state = r.varbits();
      }
      let rx = 0;
      let ry = 0;
      let rz = 0;
      let rh = 0;
      if (r.get(1) === 1) {
        rx = this.ctx.posXY.read(r);
        ry = this.ctx.posXY.read(r);
        rz = this.ctx.posZ.read(r);
        rh = this.ctx.heading.read(r);
      }
      p.x = apply(this.#predict(a1.x, a0.x, POS_MIN, POS_MAX), rx, POS_MIN, POS_MAX, 'player position');
      p.y = apply(this.#predict(a1.y, a0.y, POS_MIN, POS_MAX), ry, POS_MIN, POS_MAX, 'player position');
      p.z = apply(this.#predict(a1.z, a0.z, POS_MIN, POS_MAX), rz, POS_MIN, POS_MAX, 'player position');
      if (rh < -HEADING_STEPS / 2 || rh >= HEADING_STEPS / 2) throw corrupt('heading change');
      p.heading = wrapHeading(this.#predictHeading(a1.heading, a0.heading) + rh);
      const pose = r.get(1) === 1;
      for (let d = 0; d < this.dofCount; d++) {
        const hi = this.grids[d].steps - 1;
        const res = pose ? this.angleCtx[d].read(r) : 0;
        p.angles[d] = apply(this.#predict(a1.angles[d], a0.angles[d], 0, hi), res, 0, hi, 'joint angle');
      }
      if (r.overrun) break;
    }
    return q;
  }

  #dequantize(h, q) {
    const players = q.players.map((p) => {
      const angles = new Float32Array(this.dofCount);
      for (let d = 0; d < this.dofCount; d++) {
        const g = this.grids[d];
        angles[d] = Math.min(g.loM + p.angles[d] * ANGLE_STEP_MDEG, g.hiM) / 1000;
      }
      let heading = (p.heading * ANGLE_STEP_MDEG) / 1000;
      if (heading > 180) heading -= 360;
      return {
        side: p.side === 1 ? 1 : p.side === 2 ? -1 : 0, // mc::Side: 1 left, -1 right
        unum: p.unum,
        state: p.state,
        x: p.x * POSITION_STEP_M,
        y: p.y * POSITION_STEP_M,
        z: p.z * POSITION_STEP_M,
        heading,
        angles,
      };
    });
    return {
      seq: h.seq,
      time: h.time,
      stoppage: h.stoppage,
      substep: h.substep,
      serverTimeMs: h.serverTimeMs,
      keyframe: h.keyframe,
      playMode: h.playMode,
      scoreLeft: h.scoreLeft,
      scoreRight: h.scoreRight,
      ball: { x: q.ball[0] * POSITION_STEP_M, y: q.ball[1] * POSITION_STEP_M, z: q.ball[2] * POSITION_STEP_M },
      players,
    };
  }
}
