// Matchcast pose-stream decoder for browsers and Node (ES module, no
// dependencies). It mirrors proto/frame_decoder.cpp bit for bit; the
// normative description is proto/SPEC.md. Both decoders pass the golden
// vectors in tests/proto/golden/.
//
// WebSocket framing: binary messages are pose frames (decode them with
// FrameDecoder); text messages are JSON control messages with a "type"
// (parseControl / parseHello).

import {
  ANGLE_STEP_MDEG,
  HEADER_SIZE,
  HEADING_STEPS,
  MAX_DOF,
  MAX_PLAYERS,
  POSITION_STEP_M,
  PROTOCOL_MINOR,
  peekHeader,
  toBytes,
} from './messages.js';
import { RangeDecoder, SignedModel, PROB_INIT, activityClass, zeroCtx } from './range_decoder.js';

// The whole public API is importable from this file.
export * from './messages.js';

const POS_MIN = -32768;
const POS_MAX = 32767;

// JS Math.round rounds -0.5 up; C++ std::lround rounds half away from zero.
function roundHalfAway(x) {
  return x < 0 ? -Math.round(-x) : Math.round(x);
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
      // Index of 0 deg (clamped): what the first keyframe player is predicted by.
      const restIndex = clamp(roundHalfAway((0 - loM) / ANGLE_STEP_MDEG), 0, steps - 1);
      grids.push({ loM, hiM, steps, restIndex });
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

// One context set per frame kind (proto/codec_model.hpp ModelSet).
function newModelSet(dofs) {
  const angle = [];
  for (let d = 0; d < dofs; d++) angle.push(new SignedModel());
  return {
    ballXY: new SignedModel(),
    ballZ: new SignedModel(),
    posXY: new SignedModel(),
    posZ: new SignedModel(),
    heading: new SignedModel(),
    angle,
    meta: new Uint16Array(1).fill(PROB_INIT),
  };
}

const PARTNER_COEF2 = [-4, -3, -2, -1, 1, 2, 3, 4];
const ROOT_KEYS = ['x', 'y', 'z'];

// round(c2 * r / 2), halves away from zero (proto/codec_model.hpp PartnerTable::term).
function partnerTerm(c2, r) {
  const t = c2 * r;
  return t >= 0 ? Math.floor((t + 1) / 2) : -Math.floor((-t + 1) / 2);
}

// Hold-vs-linear running costs per kind of value (proto/codec_model.hpp PredictorCosts).
// Separate costs for substep 0 and 1 frames.
class PredictorCosts {
  constructor(dofs) {
    this.n = 4 + dofs;
    this.hold = new Uint32Array(2 * this.n);
    this.linear = new Uint32Array(2 * this.n);
    this.base = 0; // n * substep of the frame being decoded
  }
  setSubstep(substep) {
    this.base = (substep & 1) * this.n;
  }
  useLinear(value) {
    return this.linear[this.base + value] <= this.hold[this.base + value];
  }
  learn(value, errHold, errLinear) {
    const i = this.base + value;
    const upd = (arr, e) => {
      const c = arr[i];
      arr[i] = c - (c >>> 7) + Math.min(Math.abs(e), 1023);
    };
    upd(this.hold, errHold);
    upd(this.linear, errLinear);
  }
}

// The last residual of each value per player (proto/codec_model.hpp LastResiduals).
function newLastResiduals(dofs) {
  const root = [];
  const angle = [];
  for (let i = 0; i < MAX_PLAYERS; i++) {
    root.push(new Int32Array(4));
    angle.push(new Int32Array(dofs));
  }
  return { ball: new Int32Array(3), root, angle };
}

export class FrameDecoder {
  /** @param skeleton the "skeleton" object of the hello (joints with dofs and limits). */
  constructor(skeleton) {
    if (!skeleton || !Array.isArray(skeleton.joints)) throw new Error('FrameDecoder needs the hello skeleton');
    this.grids = buildGrids(skeleton);
    this.dofCount = this.grids.length;
    this.fingerprint = skeletonFingerprint(this.grids);
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
      const rc = new RangeDecoder(bytes.subarray(HEADER_SIZE));
      let q;
      if (h.keyframe) {
        this.key = newModelSet(this.dofCount);
        this.delta = newModelSet(this.dofCount);
        this.last = newLastResiduals(this.dofCount);
        this.costs = new PredictorCosts(this.dofCount);
        this.partner = new Int8Array(this.dofCount).fill(-1);
        this.coef2 = new Int8Array(this.dofCount);
        this.rawResidual = [];
        for (let i = 0; i < MAX_PLAYERS; i++) this.rawResidual.push(new Int32Array(this.dofCount));
        this.history = 0;
        const fp = rc.direct(32);
        if (!rc.overrun && fp !== this.fingerprint) {
          throw new Error(`keyframe was encoded for a different skeleton (fingerprint ${fp}, expected ${this.fingerprint})`);
        }
        q = this.#readKeyframe(rc);
      } else {
        this.costs.setSubstep(h.substep);
        q = this.#readDelta(rc);
      }
      if (rc.overrun) throw new Error(`${h.keyframe ? 'keyframe' : 'delta frame'} ${h.seq} truncated`);
      const bodyLength = bytes.length - HEADER_SIZE;
      if (h.minor === PROTOCOL_MINOR && rc.pos !== bodyLength) {
        throw new Error(`corrupt pose frame ${h.seq}: ${bodyLength - rc.pos} unexpected trailing bytes`);
      }
      this.prev2 = this.prev;
      this.prev = q;
      this.history = Math.min(this.history + 1, 2);
      this.lastSeq = h.seq;
      return this.#dequantize(h, q);
    } catch (e) {
      this.history = 0;
      throw e;
    }
  }

  #predict(a1, a0, lo, hi, linear = true) {
    return clamp(this.history >= 2 && linear ? 2 * a1 - a0 : a1, lo, hi);
  }
  #predictHeading(a1, a0, linear = true) {
    return this.history >= 2 && linear ? wrapHeading(a1 + wrapSigned(a1 - a0)) : a1;
  }
  #learn(value, v, a1, a0, lo, hi) {
    if (this.history < 2) return;
    this.costs.learn(value, v - a1, v - this.#predict(a1, a0, lo, hi));
  }
  #learnHeading(v, a1, a0) {
    if (this.history < 2) return;
    this.costs.learn(3, wrapSigned(v - a1), wrapSigned(v - this.#predictHeading(a1, a0)));
  }

  // Prediction + decoded residual, range-checked; returns the value and
  // leaves the residual in this.res (no per-value allocation).
  #value(rc, model, pred, lo, hi, zctx, act) {
    const res = model.decode(rc, zctx, act);
    const v = pred + res;
    if (v < lo || v > hi) {
      throw new Error(rc.overrun ? 'pose frame truncated' : 'corrupt pose frame: value out of range');
    }
    this.res = res;
    return v;
  }
  #heading(rc, model, pred, zctx, act) {
    const res = model.decode(rc, zctx, act);
    if (res < -HEADING_STEPS / 2 || res >= HEADING_STEPS / 2) {
      throw new Error(rc.overrun ? 'pose frame truncated' : 'corrupt pose frame: heading out of range');
    }
    this.res = res;
    return wrapHeading(pred + res);
  }

  // proto/codec_model.hpp walk_keyframe.
  #readKeyframe(rc) {
    const s = this.key;
    const q = emptyQuant(this.dofCount);
    // The partner table: per dof a direct bit, then partner (6) and coefficient index (3).
    for (let d = 0; d < this.dofCount; d++) {
      if (rc.direct(1) === 0) continue;
      const partner = rc.direct(6);
      const coef = rc.direct(3);
      if (partner >= d) throw new Error(rc.overrun ? 'pose frame truncated' : 'corrupt pose frame: partner dof out of range');
      this.partner[d] = partner;
      this.coef2[d] = PARTNER_COEF2[coef];
    }
    for (let a = 0; a < 3; a++) q.ball[a] = this.#value(rc, a < 2 ? s.ballXY : s.ballZ, 0, POS_MIN, POS_MAX, 0, 0);
    for (let i = 0; i < MAX_PLAYERS; i++) {
      const p = q.players[i];
      const before = i > 0 ? q.players[i - 1] : null;
      p.side = rc.direct(2);
      p.unum = rc.direct(4);
      p.state = rc.varbits();
      p.x = this.#value(rc, s.posXY, 0, POS_MIN, POS_MAX, 0, 0);
      p.y = this.#value(rc, s.posXY, 0, POS_MIN, POS_MAX, 0, 0);
      p.z = this.#value(rc, s.posZ, before ? before.z : 0, POS_MIN, POS_MAX, 0, 0);
      p.heading = this.#heading(rc, s.heading, 0, 0, 0);
      let prevNonzero = false;
      for (let d = 0; d < this.dofCount; d++) {
        const g = this.grids[d];
        const pred = before ? before.angles[d] : g.restIndex;
        p.angles[d] = this.#value(rc, s.angle[d], pred, 0, g.steps - 1, zeroCtx(0, prevNonzero), 0);
        prevNonzero = this.res !== 0;
      }
    }
    return q;
  }

  // proto/codec_model.hpp walk_delta.
  #readDelta(rc) {
    const s = this.delta;
    const last = this.last;
    const p1 = this.prev;
    const p0 = this.prev2;
    const q = emptyQuant(this.dofCount);
    let prevNonzero = false;
    for (let a = 0; a < 3; a++) {
      const act = activityClass(last.ball[a]);
      const pred = this.#predict(p1.ball[a], p0.ball[a], POS_MIN, POS_MAX);
      q.ball[a] = this.#value(rc, a < 2 ? s.ballXY : s.ballZ, pred, POS_MIN, POS_MAX, zeroCtx(act, prevNonzero), act);
      last.ball[a] = this.res;
      prevNonzero = this.res !== 0;
    }
    for (let i = 0; i < MAX_PLAYERS; i++) {
      const p = q.players[i];
      const a1 = p1.players[i];
      const a0 = p0.players[i];
      if (rc.bit(s.meta, 0) === 1) {
        p.side = rc.direct(2);
        p.unum = rc.direct(4);
        p.state = rc.varbits();
      } else {
        p.side = a1.side;
        p.unum = a1.unum;
        p.state = a1.state;
      }
      const rootLast = last.root[i];
      prevNonzero = false;
      for (let c = 0; c < 3; c++) {
        const k = ROOT_KEYS[c];
        const act = activityClass(rootLast[c]);
        const pred = this.#predict(a1[k], a0[k], POS_MIN, POS_MAX, this.costs.useLinear(c));
        const v = this.#value(rc, c < 2 ? s.posXY : s.posZ, pred, POS_MIN, POS_MAX, zeroCtx(act, prevNonzero), act);
        p[k] = v;
        this.#learn(c, v, a1[k], a0[k], POS_MIN, POS_MAX);
        rootLast[c] = this.res;
        prevNonzero = this.res !== 0;
      }
      const hAct = activityClass(rootLast[3]);
      const hv = this.#heading(rc, s.heading, this.#predictHeading(a1.heading, a0.heading, this.costs.useLinear(3)),
        zeroCtx(hAct, prevNonzero), hAct);
      p.heading = hv;
      this.#learnHeading(hv, a1.heading, a0.heading);
      rootLast[3] = this.res;
      const angleLast = last.angle[i];
      const raw = this.rawResidual[i];
      prevNonzero = false;
      for (let d = 0; d < this.dofCount; d++) {
        const hi = this.grids[d].steps - 1;
        const act = activityClass(angleLast[d]);
        const pred = this.#predict(a1.angles[d], a0.angles[d], 0, hi, this.costs.useLinear(4 + d));
        const partner = this.partner[d];
        const adj = partner >= 0 ? partnerTerm(this.coef2[d], raw[partner]) : 0;
        const v = this.#value(rc, s.angle[d], pred + adj, 0, hi, zeroCtx(act, prevNonzero), act);
        p.angles[d] = v;
        raw[d] = v - pred;
        this.#learn(4 + d, v, a1.angles[d], a0.angles[d], 0, hi);
        angleLast[d] = this.res;
        prevNonzero = this.res !== 0;
      }
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
      let heading = (p.heading * 360) / HEADING_STEPS;
      if (heading > 180) heading -= 360;
      return {
        side: p.side === 1 ? 1 : p.side === 2 ? -1 : 0, // mc::Side: 1 left, -1 right, 0 neutral
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
