// Binary adaptive range decoder and the signed-value model of the pose
// stream: the JavaScript twin of proto/range_coder.cpp and
// proto/residual_coder.cpp (normative text: proto/SPEC.md section 4.2-4.3).
// All state stays below 2^32 and is kept in plain numbers, so every
// operation is exact in doubles; no dependencies.

const PROB_BITS = 11;
export const PROB_INIT = 1 << (PROB_BITS - 1);
const PROB_SHIFT = 4;
const TOP = 2 ** 24;
const ACTIVITY_CLASSES = 4;
const ZERO_CONTEXTS = 8;
const BUCKET_CONTEXTS = 24;

// LZMA-style decoder. Reading past the end yields zero bytes and sets
// `overrun` (the input was truncated); it never reads outside `bytes`.
export class RangeDecoder {
  constructor(bytes) {
    this.bytes = bytes;
    this.pos = 0;
    this.overrun = false;
    this.range = 0xffffffff;
    this.code = 0;
    for (let i = 0; i < 4; i++) this.code = this.code * 256 + this.next();
  }
  next() {
    if (this.pos >= this.bytes.length) {
      this.overrun = true;
      return 0;
    }
    return this.bytes[this.pos++];
  }
  normalize() {
    while (this.range < TOP) {
      this.range *= 256;
      this.code = ((this.code * 256) % 4294967296) + this.next();
    }
  }
  /** One adaptive bit; `probs[i]` is P(0) in 1/2048ths and is updated. */
  bit(probs, i) {
    const p = probs[i];
    const bound = (this.range >>> PROB_BITS) * p;
    let bit;
    if (this.code < bound) {
      this.range = bound;
      probs[i] = p + (((1 << PROB_BITS) - p) >>> PROB_SHIFT);
      bit = 0;
    } else {
      this.range -= bound;
      this.code -= bound;
      probs[i] = p - (p >>> PROB_SHIFT);
      bit = 1;
    }
    this.normalize();
    return bit;
  }
  /** `bits` equiprobable bits, most significant first. */
  direct(bits) {
    let value = 0;
    for (let i = 0; i < bits; i++) {
      this.range = Math.floor(this.range / 2);
      let bit = 0;
      if (this.code >= this.range) {
        this.code -= this.range;
        bit = 1;
      }
      value = value * 2 + bit;
      this.normalize();
    }
    return value;
  }
  /** 5 bits of bit length L, then the L-1 bits below the leading one. */
  varbits() {
    const len = this.direct(5);
    if (len === 0) return 0;
    if (len === 1) return 1;
    return 2 ** (len - 1) + this.direct(len - 1);
  }
}

// Adaptive contexts of one kind of signed value.
export class SignedModel {
  constructor() {
    this.zero = new Uint16Array(ZERO_CONTEXTS).fill(PROB_INIT);
    this.sign = new Uint16Array(ACTIVITY_CLASSES).fill(PROB_INIT);
    this.bucket = new Uint16Array(ACTIVITY_CLASSES * BUCKET_CONTEXTS).fill(PROB_INIT);
    this.mant = new Uint16Array(ACTIVITY_CLASSES * BUCKET_CONTEXTS).fill(PROB_INIT);
  }
  /** zero? sign, unary bucket floor(log2|v|), mantissa (first bit adaptive, rest direct). */
  decode(rc, zeroCtx, act) {
    if (rc.bit(this.zero, zeroCtx) === 0) return 0;
    const negative = rc.bit(this.sign, act) === 1;
    const base = act * BUCKET_CONTEXTS;
    let b = 0;
    while (b < 31 && rc.bit(this.bucket, base + Math.min(b, BUCKET_CONTEXTS - 1)) === 1) b++;
    let mag = 2 ** b;
    if (b >= 1) {
      if (rc.bit(this.mant, base + Math.min(b, BUCKET_CONTEXTS - 1)) === 1) mag += 2 ** (b - 1);
      if (b >= 2) mag += rc.direct(b - 1);
    }
    return negative ? -mag : mag;
  }
}

/** Activity class of a magnitude: 0 -> 0, 1 -> 1, 2..4 -> 2, 5+ -> 3. */
export function activityClass(v) {
  const m = Math.abs(v);
  return m === 0 ? 0 : m === 1 ? 1 : m <= 4 ? 2 : 3;
}
export function zeroCtx(act, prevNonzero) {
  return act * 2 + (prevNonzero ? 1 : 0);
}
