// Feet between two frames (proto/SPEC.md 4.7, step 2; anim/leg_blend.cpp is
// the same step in C++, for the native viewer and the quality figures).
//
// The page draws at the display's rate and blends two 20 Hz frames' joint
// angles (interp.js). A foot on the grass in both frames then leaves its
// line between them, and a foot that leaves or lands is dragged low over the
// grass: a sliding foot, in a close-up. After the blend, leg by leg:
//   - a foot on the grass in both frames keeps its ankle, across the grass,
//     on the straight line between its places in the two frames;
//   - a foot on the grass in one frame only is raised: its sole's height
//     eases out of the grass (1 - (1 - t)^2 of the way) or into it (t^2)
//     instead of following t, and across the grass it starts (leaving) or
//     ends (landing) slowly: t -/+ ACROSS_EASE t (1 - t) of its way.
// Either is done by swinging the whole leg about its hip (the thigh's three
// angles; knee and ankle keep theirs) by at most 1 degree: enough for what
// the blend gets wrong, too little to jerk a leg.
// Then the legs are kept apart: a leg swinging past the other passes through
// it in the blend even when both frames hold them apart. A leg in the air
// turns at the hip, away from the other hip (feet: from the other foot),
// until the boxes' centre lines are half the wider box's width and 1 cm
// apart, within a room that grows from nothing at either frame (keepApart).
//
// Forward kinematics as skeleton.js says: M_j = M_parent * T(offset) *
// R_local, joint 0 at (0, z, 0) plus its offset; body space X forward, Y up,
// Z right; field (x, y) from body (bx, bz) by the heading h:
// x + bx cos h - bz sin h, y + bx sin h + bz cos h. Rotations are 3 x 3,
// row-major. No allocation after the first call for a skeleton.

import { axisRotation } from './ground.js';

export const CONTACT_M = 0.03;       // a sole this low is on the grass
export const SAME_STANCE_M = 0.3;    // both frames on it and this close: one stance
export const MAX_SWING_DEG = 1;      // the largest swing of a leg about its hip
export const ACROSS_EASE = 0.5;      // a leaving / landing foot crosses t -/+ this * t(1 - t) of its way
export const ACROSS_WAY_M = 0.15;    // that way taken this far at most
export const APART_M = 0.01;         // legs' centre lines apart beyond half the wider box
export const MAX_APART_DEG = 8;      // the largest turn of a leg out of the other's way
export const APART_SPEED_DEG = 54;   // turns out only below this thigh turn per frame
export const APART_TRAVEL_M = 0.47;  // its ankle's travel about the root and the turn's move together
export const APART_LEVER_M = 0.85;   // the turn's move taken this far from the hip
export const APART_ROUNDS = 4;       // times the legs are posed and turned apart

const DEG = Math.PI / 180;
const legsOf = new WeakMap();        // skeleton -> [leg, leg] | null

// -1 left, +1 right, 0 neither ("r_thigh", "RightUpLeg", "thigh.L").
function sideOf(n) {
  if (n.startsWith('l_') || n.startsWith('left') || n.endsWith('_l') || n.endsWith('.l')) return -1;
  if (n.startsWith('r_') || n.startsWith('right') || n.endsWith('_r') || n.endsWith('.r')) return 1;
  return 0;
}

const hasAny = (s, words) => words.some((w) => s.includes(w));

function threeAxes(dofs) {
  return dofs.length === 3 && new Set(dofs).size === 3;
}

// The two legs (thigh -> shin -> foot off the root, the thigh with three
// dofs about three different axes), found by name as anim/leg_blend.cpp
// finds them, or null.
export function findLegs(skel) {
  if (legsOf.has(skel)) return legsOf.get(skel);
  const legs = [];
  const joints = skel.joints;
  for (let i = 0; i < joints.length; i++) {
    const n = joints[i].name.toLowerCase();
    if (sideOf(n) === 0 || !hasAny(n, ['thigh', 'upleg', 'hip']) || joints[i].parent !== 0) continue;
    if (!threeAxes(joints[i].dofs)) continue;
    let shin = -1, foot = -1;
    for (let k = i + 1; k < joints.length; k++) {
      const m = joints[k].name.toLowerCase();
      if (shin < 0 && joints[k].parent === i && hasAny(m, ['shin', 'knee', 'calf', 'leg'])) shin = k;
      else if (shin >= 0 && joints[k].parent === shin && hasAny(m, ['foot', 'ankle'])) foot = k;
    }
    if (shin >= 0 && foot >= 0 && legs.length < 2) legs.push({ thigh: i, shin, foot });
  }
  const found = legs.length === 2 ? legs : null;
  legsOf.set(skel, found);
  return found;
}

// out = a * b (3 x 3).
function mul(a, b, out) {
  for (let r = 0; r < 3; r++) {
    for (let c = 0; c < 3; c++) {
      out[3 * r + c] = a[3 * r] * b[c] + a[3 * r + 1] * b[3 + c] + a[3 * r + 2] * b[6 + c];
    }
  }
  return out;
}

// out = a^T * b.
function mulT(a, b, out) {
  for (let r = 0; r < 3; r++) {
    for (let c = 0; c < 3; c++) {
      out[3 * r + c] = a[r] * b[c] + a[3 + r] * b[3 + c] + a[6 + r] * b[6 + c];
    }
  }
  return out;
}

// out = m * v.
function apply(m, v, out) {
  const x = v[0], y = v[1], z = v[2];
  out[0] = m[0] * x + m[1] * y + m[2] * z;
  out[1] = m[3] * x + m[4] * y + m[5] * z;
  out[2] = m[6] * x + m[7] * y + m[8] * z;
  return out;
}

const axisTmp = new Float64Array(9), prodTmp = new Float64Array(9);

// A joint's local rotation: R_dofs[0](a0) * R_dofs[1](a1) * ...
function localRotation(joint, angles, out) {
  out.fill(0); out[0] = out[4] = out[8] = 1;
  for (let k = 0; k < joint.dofs.length; k++) {
    mul(out, axisRotation(joint.dofs[k], angles[joint.angleIndex + k] || 0, axisTmp), prodTmp);
    out.set(prodTmp);
  }
  return out;
}

// The angles (deg) of a three-axis joint whose rotation is `r`: the
// Tait-Bryan decomposition for its order, the middle angle within +-90.
const AXIS = { x: 0, y: 1, z: 2 };

export function jointAngles(dofs, r, out) {
  const i = AXIS[dofs[0]], j = AXIS[dofs[1]], k = AXIS[dofs[2]];
  const sign = (j - i + 3) % 3 === 1 ? 1 : -1;   // +1 for xyz, yzx, zxy
  const at = (row, col) => r[3 * row + col];
  out[1] = Math.asin(Math.max(-1, Math.min(1, sign * at(i, k)))) / DEG;
  out[0] = Math.atan2(-sign * at(j, k), at(k, k)) / DEG;
  out[2] = Math.atan2(-sign * at(i, j), at(i, i)) / DEG;
  return out;
}

// One chain's rotations and positions (body space).
const chain = () => ({
  rRoot: new Float64Array(9), rThigh: new Float64Array(9), rShin: new Float64Array(9), rFoot: new Float64Array(9),
  pRoot: [0, 0, 0], pThigh: [0, 0, 0], pShin: [0, 0, 0], pFoot: [0, 0, 0],
});
// Scratch: a chain, and what the steps work with.
const S = Object.assign(chain(), {
  local: new Float64Array(9), tmp: new Float64Array(9), swing: new Float64Array(9), turned: new Float64Array(9),
  v: [0, 0, 0], deg: [0, 0, 0],
});
const bothLegs = [chain(), chain()];

// Poses one leg of `p` (angles, root height z): fills `C`'s rotations and
// positions of root, thigh, shin and foot (S's by default).
function poseLeg(skel, leg, p, C = S) {
  const J = skel.joints;
  const root = J[0];
  localRotation(root, p.angles, C.rRoot);
  C.pRoot[0] = root.offset[0]; C.pRoot[1] = root.offset[1] + p.z; C.pRoot[2] = root.offset[2];
  link(J[leg.thigh], p.angles, C.rRoot, C.pRoot, C.rThigh, C.pThigh);
  link(J[leg.shin], p.angles, C.rThigh, C.pThigh, C.rShin, C.pShin);
  link(J[leg.foot], p.angles, C.rShin, C.pShin, C.rFoot, C.pFoot);
}

// A child joint's rotation `r` and position `pos` from its parent's.
function link(joint, angles, rp, pp, r, pos) {
  apply(rp, joint.offset, S.v);
  pos[0] = pp[0] + S.v[0]; pos[1] = pp[1] + S.v[1]; pos[2] = pp[2] + S.v[2];
  mul(rp, localRotation(joint, angles, S.local), r);
}

// The foot box's lowest corner above the grass (after poseLeg into `C`).
function soleHeight(skel, leg, C = S) {
  const seg = skel.joints[leg.foot].segment;
  let low = C.pFoot[1];
  if (seg.shape !== 'box') return low;
  const r = C.rFoot;
  for (let c = 0; c < 8; c++) {
    const x = seg.center[0] + ((c & 1) ? 0.5 : -0.5) * seg.size[0];
    const y = seg.center[1] + ((c & 2) ? 0.5 : -0.5) * seg.size[1];
    const z = seg.center[2] + ((c & 4) ? 0.5 : -0.5) * seg.size[2];
    low = Math.min(low, C.pFoot[1] + r[3] * x + r[4] * y + r[5] * z);
  }
  return low;
}

// Where a pose puts a foot: its ankle in field space [x, height, y] and its sole.
function place(skel, leg, p, out) {
  poseLeg(skel, leg, p);
  const c = Math.cos(p.heading * DEG), s = Math.sin(p.heading * DEG);
  out.ankle[0] = p.x + S.pFoot[0] * c - S.pFoot[2] * s;
  out.ankle[1] = S.pFoot[1];
  out.ankle[2] = p.y + S.pFoot[0] * s + S.pFoot[2] * c;
  out.sole = soleHeight(skel, leg);
  return out;
}

const placeA = { ankle: [0, 0, 0], sole: 0 }, placeB = { ankle: [0, 0, 0], sole: 0 };
const hip = [0, 0, 0], ankle = [0, 0, 0], target = [0, 0, 0];

// One player: `o` is the blend of `pa` and `pb` at `t` (SPEC 4.7 step 1);
// its thighs' angles are changed in place.
export function keepFeetOfPlayer(skel, pa, pb, t, o) {
  const legs = findLegs(skel);
  if (!legs || !(t > 0 && t < 1)) return;
  for (let i = 0; i < 2; i++) {
    const leg = legs[i];
    const fa = place(skel, leg, pa, placeA), fb = place(skel, leg, pb, placeB);
    const ca = fa.sole < CONTACT_M, cb = fb.sole < CONTACT_M;
    inAir[i] = !ca && !cb;
    // How freely keepApart may turn it: a foot in the air in both frames
    // fully; one leaving the grass by t, one landing by 1 - t (still on
    // its way through the blend, however low the blend draws it); one on
    // the grass in both not at all (or by its drawn sole's height).
    free[i] = inAir[i] ? 1 : ca && !cb ? t : !ca && cb ? 1 - t : 0;
    // The ankle's travel about the root over the frame, and the thigh's own
    // turn (deg): the room for keepApart (rad) grows from nothing at either
    // frame at the rate the thigh's turn leaves below APART_SPEED_DEG and
    // the rate the ankle's travel leaves below APART_TRAVEL_M (a fast foot
    // carried sideways reads as a pop), up to MAX_APART_DEG; `along`, for
    // the feet's turn that may carry the ankle along its travel, counts
    // the move added to the travel, not in quadrature.
    const travel = Math.hypot(fb.ankle[0] - pb.x - (fa.ankle[0] - pa.x), fb.ankle[1] - pb.z - (fa.ankle[1] - pa.z),
      fb.ankle[2] - pb.y - (fa.ankle[2] - pa.y));
    const speed = thighTurnDeg(skel.joints[leg.thigh], pa, pb);
    const sideways = Math.sqrt(Math.max(0, APART_TRAVEL_M * APART_TRAVEL_M - travel * travel));
    const ramp = Math.min(t, 1 - t);
    room[i] = Math.min(MAX_APART_DEG * DEG, Math.max(0, APART_SPEED_DEG - speed) * DEG * ramp,
      sideways / APART_LEVER_M * ramp);
    along[i] = Math.min(room[i], Math.max(0, APART_TRAVEL_M - travel) / APART_LEVER_M * ramp);
    if (inAir[i]) continue;   // in the air in both: the blend's arc
    poseLeg(skel, leg, o);
    hip[0] = S.pThigh[0]; hip[1] = S.pThigh[1]; hip[2] = S.pThigh[2];
    ankle[0] = S.pFoot[0]; ankle[1] = S.pFoot[1]; ankle[2] = S.pFoot[2];
    target[0] = ankle[0]; target[1] = ankle[1]; target[2] = ankle[2];
    if (ca && cb) {
      const dx = fb.ankle[0] - fa.ankle[0], dh = fb.ankle[1] - fa.ankle[1], dy = fb.ankle[2] - fa.ankle[2];
      if (Math.hypot(dx, dh, dy) >= SAME_STANCE_M) continue;
      // Across the grass, on the line between its two places (field -> body).
      const fx = fa.ankle[0] + dx * t - o.x, fy = fa.ankle[2] + dy * t - o.y;
      const c = Math.cos(o.heading * DEG), s = Math.sin(o.heading * DEG);
      target[0] = fx * c + fy * s;
      target[2] = -fx * s + fy * c;
    } else {
      const e = ca ? 1 - (1 - t) * (1 - t) : t * t;
      target[1] += (fb.sole - fa.sole) * (e - t);   // >= 0 leaving or landing
      // Across the grass it starts (leaving) or ends (landing) slowly; the
      // ease adds to the ankle's travel, so it stays below APART_TRAVEL_M.
      const dx = fb.ankle[0] - fa.ankle[0], dy = fb.ankle[2] - fa.ankle[2];
      const c = Math.cos(o.heading * DEG), s = Math.sin(o.heading * DEG);
      const wx = dx * c + dy * s, wz = -dx * s + dy * c;
      const way = Math.hypot(wx, wz);
      if (way > 1e-4) {
        const taken = Math.min(way, ACROSS_WAY_M);
        const k = Math.min(ACROSS_EASE, Math.max(0, APART_TRAVEL_M - travel) / taken);
        const shift = (ca ? -k : k) * t * (1 - t) * taken / way;
        target[0] += wx * shift;
        target[2] += wz * shift;
      }
    }
    // The swing: the rotation taking hip->ankle's direction to hip->target's.
    const ux = ankle[0] - hip[0], uy = ankle[1] - hip[1], uz = ankle[2] - hip[2];
    const vx = target[0] - hip[0], vy = target[1] - hip[1], vz = target[2] - hip[2];
    const lu = Math.hypot(ux, uy, uz), lv = Math.hypot(vx, vy, vz);
    if (lu < 1e-4 || lv < 1e-4) continue;
    let ax = (uy * vz - uz * vy) / (lu * lv), ay = (uz * vx - ux * vz) / (lu * lv), az = (ux * vy - uy * vx) / (lu * lv);
    const sn = Math.hypot(ax, ay, az);
    if (sn < 1e-6) continue;
    const angle = Math.min(Math.atan2(sn, (ux * vx + uy * vy + uz * vz) / (lu * lv)), MAX_SWING_DEG * DEG);
    ax /= sn; ay /= sn; az /= sn;
    turnThigh(skel.joints[leg.thigh], S, ax, ay, az, angle, o);
  }
  keepApart(skel, legs, o);
}

const inAir = [false, false], free = [0, 0], room = [0, 0], along = [0, 0];
const rotA = new Float64Array(9), rotB = new Float64Array(9);

// The rotation (deg) between a thigh's local rotations in two poses.
function thighTurnDeg(joint, pa, pb) {
  localRotation(joint, pa.angles, rotA);
  localRotation(joint, pb.angles, rotB);
  let tr = 0;
  for (let k = 0; k < 9; k++) tr += rotA[k] * rotB[k];
  return Math.acos(Math.max(-1, Math.min(1, 0.5 * (tr - 1)))) / DEG;
}

// Turns a thigh by `angle` (rad) about the unit axis (ax, ay, az) through its
// hip (body space); `C` holds the leg as posed on `o`.
function turnThigh(joint, C, ax, ay, az, angle, o) {
  const c = Math.cos(angle), s = Math.sin(angle), k = 1 - c;
  const R = S.swing;
  R[0] = c + ax * ax * k;      R[1] = ax * ay * k - az * s; R[2] = ax * az * k + ay * s;
  R[3] = ay * ax * k + az * s; R[4] = c + ay * ay * k;      R[5] = ay * az * k - ax * s;
  R[6] = az * ax * k - ay * s; R[7] = az * ay * k + ax * s; R[8] = c + az * az * k;
  // The thigh's new local rotation: root^T * rotation * (root * local).
  mulT(C.rRoot, mul(R, C.rThigh, S.tmp), S.turned);
  jointAngles(joint.dofs, S.turned, S.deg);
  for (let d = 0; d < 3; d++) {
    const cur = o.angles[joint.angleIndex + d];
    // The same turn, not one the other way round the circle.
    let next = cur + (((S.deg[d] - cur) % 360 + 540) % 360 - 180);
    // A hello's limit that is not two numbers is no limit; one given upside
    // down is read as the quantizer reads it (its top no lower than its bottom).
    const lim = joint.limits[d];
    if (Array.isArray(lim) && Number.isFinite(lim[0]) && Number.isFinite(lim[1])) {
      next = Math.min(Math.max(next, lim[0]), Math.max(lim[0], lim[1]));
    }
    o.angles[joint.angleIndex + d] = next;
  }
}

// A segment's box centre line (its longest axis, end to end) posed by
// rotation `r` at `pos`, into from/to; returns half its larger other side,
// or -1 when the segment is not a box.
const half = [0, 0, 0], end = [0, 0, 0];
function centreLine(seg, r, pos, from, to) {
  if (!seg || seg.shape !== 'box') return -1;
  for (let k = 0; k < 3; k++) half[k] = 0.5 * seg.size[k];
  const axis = half[0] >= half[1] && half[0] >= half[2] ? 0 : half[1] >= half[2] ? 1 : 2;
  for (let e = 0; e < 2; e++) {
    const out = e === 0 ? from : to;
    for (let k = 0; k < 3; k++) end[k] = seg.center[k];
    end[axis] += (e === 0 ? -1 : 1) * half[axis];
    apply(r, end, out);
    out[0] += pos[0]; out[1] += pos[1]; out[2] += pos[2];
  }
  return Math.max(half[(axis + 1) % 3], half[(axis + 2) % 3]);
}

// Closest points of segments p1q1 and p2q2 (Ericson, Real-Time Collision
// Detection, 5.1.9), as anim/segment_distance.hpp: into c1, c2; returns the distance.
const d1 = [0, 0, 0], d2 = [0, 0, 0], r12 = [0, 0, 0];
const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
const clamp01 = (v) => Math.min(Math.max(v, 0), 1);
export function closestPoints(p1, q1, p2, q2, c1, c2) {
  for (let k = 0; k < 3; k++) { d1[k] = q1[k] - p1[k]; d2[k] = q2[k] - p2[k]; r12[k] = p1[k] - p2[k]; }
  const r = r12;
  const a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  let s = 0, t = 0;
  if (a <= 1e-9 && e > 1e-9) {
    t = clamp01(f / e);
  } else if (a > 1e-9) {
    const c = dot(d1, r);
    if (e <= 1e-9) {
      s = clamp01(-c / a);
    } else {
      const b = dot(d1, d2), denom = a * e - b * b;
      s = denom > 1e-9 ? clamp01((b * f - c * e) / denom) : 0;
      t = (b * s + f) / e;
      if (t < 0) { t = 0; s = clamp01(-c / a); } else if (t > 1) { t = 1; s = clamp01((b - c) / a); }
    }
  }
  for (let k = 0; k < 3; k++) { c1[k] = p1[k] + d1[k] * s; c2[k] = p2[k] + d2[k] * t; }
  return Math.hypot(c1[0] - c2[0], c1[1] - c2[1], c1[2] - c2[2]);
}

const lineFrom = [[0, 0, 0], [0, 0, 0]], lineTo = [[0, 0, 0], [0, 0, 0]];
const near = [[0, 0, 0], [0, 0, 0]], nearest = [[0, 0, 0], [0, 0, 0]];
const middle = [[0, 0, 0], [0, 0, 0]], onOther = [[0, 0, 0], [0, 0, 0]], scratch = [0, 0, 0];
const share = [0, 0];
const PAIRS = [['thigh', 'rThigh', 'pThigh'], ['shin', 'rShin', 'pShin'], ['foot', 'rFoot', 'pFoot']];

// The step's second part: the legs' boxes kept APART_M beyond half the
// wider box's width, thighs, shins and feet. APART_ROUNDS times: each leg
// turns at the hip by its share of the shortfall of the pair furthest
// inside (1 in the air in both frames; else the larger of its `free` share
// and its drawn sole's height from CONTACT_M to twice that), within what
// is left of its room: thighs and shins away from the other hip, each foot's
// middle away from the nearest point of the other foot's centre line
// (within `along`).
function keepApart(skel, legs, o) {
  const J = skel.joints;
  for (let round = 0; round < APART_ROUNDS; round++) {
    for (let i = 0; i < 2; i++) {
      poseLeg(skel, legs[i], o, bothLegs[i]);
      const sole = soleHeight(skel, legs[i], bothLegs[i]);
      share[i] = Math.max(free[i], Math.min(Math.max((sole - CONTACT_M) / CONTACT_M, 0), 1));
    }
    const shares = share[0] + share[1];
    if (shares <= 0) return;
    let shortfall = 0, feet = false;
    for (let pair = 0; pair < 3; pair++) {
      const part = PAIRS[pair][0], rot = PAIRS[pair][1], pos = PAIRS[pair][2];
      const w0 = centreLine(J[legs[0][part]].segment, bothLegs[0][rot], bothLegs[0][pos], lineFrom[0], lineTo[0]);
      const w1 = centreLine(J[legs[1][part]].segment, bothLegs[1][rot], bothLegs[1][pos], lineFrom[1], lineTo[1]);
      if (w0 < 0 || w1 < 0) continue;
      const need = APART_M + Math.max(w0, w1) - closestPoints(lineFrom[0], lineTo[0], lineFrom[1], lineTo[1], near[0], near[1]);
      if (need > shortfall) {
        shortfall = need;
        feet = pair === 2;
        for (let k = 0; k < 3; k++) { nearest[0][k] = near[0][k]; nearest[1][k] = near[1][k]; }
      }
    }
    if (shortfall <= 0) return;
    // Each foot's middle parts from the other's centre line (feet pass
    // front to back as well as side to side; the nearest points would jump
    // from end to end as they pass); thighs and shins move out. The feet
    // are the last pair, so lineFrom/lineTo still hold their centre lines.
    let betweenFeet = feet;
    if (feet) {
      for (let i = 0; i < 2; i++)
        for (let k = 0; k < 3; k++) middle[i][k] = 0.5 * (lineFrom[i][k] + lineTo[i][k]);
      for (let i = 0; i < 2; i++)
        if (closestPoints(middle[i], middle[i], lineFrom[1 - i], lineTo[1 - i], scratch, onOther[i]) < 1e-3)
          betweenFeet = false;
    }
    for (let i = 0; i < 2; i++) {
      if (share[i] <= 0) continue;
      const hp = bothLegs[i].pThigh;
      const from = betweenFeet ? onOther[i] : bothLegs[1 - i].pThigh, to = betweenFeet ? middle[i] : hp;
      const lx = nearest[i][0] - hp[0], ly = nearest[i][1] - hp[1], lz = nearest[i][2] - hp[2];
      let cx = to[0] - from[0], cy = to[1] - from[1], cz = to[2] - from[2];
      const width = Math.hypot(cx, cy, cz);
      if (width < 1e-4) continue;
      cx /= width; cy /= width; cz /= width;
      // The axis lever x away; its length is the travel away per radian.
      let ax = ly * cz - lz * cy, ay = lz * cx - lx * cz, az = lx * cy - ly * cx;
      const reach = Math.hypot(ax, ay, az);
      if (reach < 1e-3) continue;
      const angle = Math.min(shortfall * share[i] / shares / reach, betweenFeet ? along[i] : room[i]);
      if (!(angle > 0)) continue;
      room[i] -= angle;
      along[i] -= angle;
      ax /= reach; ay /= reach; az /= reach;
      turnThigh(J[legs[i].thigh], bothLegs[i], ax, ay, az, angle, o);
    }
  }
}

// Every player of the blended frame `out` (interp.js's blendFrames of `a`
// and `b` at `t`) but those whose slot changes or who jump 5 m (a move at
// kick-off is not animated).
export function keepFeet(skel, a, b, t, out) {
  if (!skel || !(t > 0 && t < 1) || !findLegs(skel)) return out;
  const n = Math.min(a.players.length, b.players.length, out.players.length);
  for (let i = 0; i < n; i++) {
    const pa = a.players[i], pb = b.players[i];
    if (!pa || !pb || pb.side !== pa.side || pb.unum !== pa.unum) continue;
    if (Math.hypot(pb.x - pa.x, pb.y - pa.y) >= 5) continue;
    if (pa.angles.length !== out.players[i].angles.length || pb.angles.length !== pa.angles.length) continue;
    keepFeetOfPlayer(skel, pa, pb, t, out.players[i]);
  }
  return out;
}
