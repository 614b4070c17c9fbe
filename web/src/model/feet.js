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
//     instead of following t.
// Either is done by swinging the whole leg about its hip (the thigh's three
// angles; knee and ankle keep theirs) by at most 1 degree: enough for what
// the blend gets wrong, too little to jerk a leg.
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

// Scratch: one chain's rotations and positions.
const S = {
  rRoot: new Float64Array(9), rThigh: new Float64Array(9), rShin: new Float64Array(9), rFoot: new Float64Array(9),
  local: new Float64Array(9), tmp: new Float64Array(9), swing: new Float64Array(9), turned: new Float64Array(9),
  pRoot: [0, 0, 0], pThigh: [0, 0, 0], pShin: [0, 0, 0], pFoot: [0, 0, 0], v: [0, 0, 0],
  deg: [0, 0, 0],
};

// Poses one leg of `p` (angles, root height z): fills S's rotations and
// positions (body space) of root, thigh, shin and foot.
function poseLeg(skel, leg, p) {
  const J = skel.joints;
  const root = J[0];
  localRotation(root, p.angles, S.rRoot);
  S.pRoot[0] = root.offset[0]; S.pRoot[1] = root.offset[1] + p.z; S.pRoot[2] = root.offset[2];
  link(J[leg.thigh], p.angles, S.rRoot, S.pRoot, S.rThigh, S.pThigh);
  link(J[leg.shin], p.angles, S.rThigh, S.pThigh, S.rShin, S.pShin);
  link(J[leg.foot], p.angles, S.rShin, S.pShin, S.rFoot, S.pFoot);
}

// A child joint's rotation `r` and position `pos` from its parent's.
function link(joint, angles, rp, pp, r, pos) {
  apply(rp, joint.offset, S.v);
  pos[0] = pp[0] + S.v[0]; pos[1] = pp[1] + S.v[1]; pos[2] = pp[2] + S.v[2];
  mul(rp, localRotation(joint, angles, S.local), r);
}

// The foot box's lowest corner above the grass (after poseLeg).
function soleHeight(skel, leg) {
  const seg = skel.joints[leg.foot].segment;
  let low = S.pFoot[1];
  if (seg.shape !== 'box') return low;
  const r = S.rFoot;
  for (let c = 0; c < 8; c++) {
    const x = seg.center[0] + ((c & 1) ? 0.5 : -0.5) * seg.size[0];
    const y = seg.center[1] + ((c & 2) ? 0.5 : -0.5) * seg.size[1];
    const z = seg.center[2] + ((c & 4) ? 0.5 : -0.5) * seg.size[2];
    low = Math.min(low, S.pFoot[1] + r[3] * x + r[4] * y + r[5] * z);
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
  const J = skel.joints;
  for (const leg of legs) {
    const fa = place(skel, leg, pa, placeA), fb = place(skel, leg, pb, placeB);
    const ca = fa.sole < CONTACT_M, cb = fb.sole < CONTACT_M;
    if (!ca && !cb) continue;   // in the air in both: the blend's arc
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
    const c = Math.cos(angle), s = Math.sin(angle), k = 1 - c;
    const R = S.swing;
    R[0] = c + ax * ax * k;      R[1] = ax * ay * k - az * s; R[2] = ax * az * k + ay * s;
    R[3] = ay * ax * k + az * s; R[4] = c + ay * ay * k;      R[5] = ay * az * k - ax * s;
    R[6] = az * ax * k - ay * s; R[7] = az * ay * k + ax * s; R[8] = c + az * az * k;
    // The thigh's new local rotation: root^T * swing * (root * local).
    mulT(S.rRoot, mul(R, S.rThigh, S.tmp), S.turned);
    const joint = J[leg.thigh];
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
