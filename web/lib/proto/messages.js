// Matchcast control messages and frame headers for browsers and Node (ES
// module, no dependencies): constants of protocol 1, JSON control messages
// (hello, events, metadata) and the 26-byte pose-frame header. See
// proto/SPEC.md; the frame body is decoded by decoder.js.

export const PROTOCOL_MAJOR = 1;
export const PROTOCOL_MINOR = 0;
export const FRAME_MAGIC = 0x4d;
export const HEADER_SIZE = 26;
export const ANGLE_STEP_MDEG = 990;
export const POSITION_STEP_M = 0.01;
export const HEADING_STEPS = 364;
export const MAX_PLAYERS = 22;
export const MAX_DOF = 64;

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

export function toBytes(buffer) {
  if (buffer instanceof Uint8Array) return buffer;
  if (buffer instanceof ArrayBuffer) return new Uint8Array(buffer);
  if (ArrayBuffer.isView(buffer)) return new Uint8Array(buffer.buffer, buffer.byteOffset, buffer.byteLength);
  throw new Error('pose frame must be an ArrayBuffer or a typed array');
}
