// Every pose the page draws rests on the grass (proto/SPEC.md, "Drawing
// between frames"; anim::rest_on_grass in C++, which the native viewer and
// the quality tool use). Blending two 20 Hz frames' joint angles can take a
// sole a few centimetres under the grass between them (the frames
// themselves are at most 2 cm under): the body is raised by what lies
// deeper than the tolerance.
//
// Forward kinematics of the skeleton (skeleton.js): M_j = M_parent *
// T(offset) * R_local, joint 0 at the pose's root height (its rest offset is
// not added, as in scene/players.js). Only heights matter here, so each
// joint keeps its rotation (3 x 3, row-major) and its position's height.
// No allocation after the first call for a skeleton.

export const GRASS_TOLERANCE_M = 0.01;

const DEG = Math.PI / 180;
const scratch = new WeakMap();  // skeleton -> { rot: Float64Array(9 n), y: Float64Array(n) }

// out = a * b (3 x 3, row-major).
function mul3(a, ao, b, bo, out, oo) {
  for (let r = 0; r < 3; r++) {
    for (let c = 0; c < 3; c++) {
      out[oo + 3 * r + c] = a[ao + 3 * r] * b[bo + c] + a[ao + 3 * r + 1] * b[bo + 3 + c] + a[ao + 3 * r + 2] * b[bo + 6 + c];
    }
  }
}

// R_axis(deg), row-major, right-handed (as THREE.Quaternion.setFromAxisAngle).
export function axisRotation(axis, deg, out) {
  const c = Math.cos(deg * DEG), s = Math.sin(deg * DEG);
  out.fill(0);
  if (axis === 'x') { out[0] = 1; out[4] = c; out[5] = -s; out[7] = s; out[8] = c; }
  else if (axis === 'y') { out[0] = c; out[2] = s; out[4] = 1; out[6] = -s; out[8] = c; }
  else { out[0] = c; out[1] = -s; out[3] = s; out[4] = c; out[8] = 1; }
  return out;
}

const axisTmp = new Float64Array(9), localTmp = new Float64Array(9), prodTmp = new Float64Array(9);

// Lowest height (m, 0 the grass) of any joint's segment for `angles` (one
// per dof, skeleton order) with joint 0 at height `rootHeight`.
export function lowestPoint(skel, angles, rootHeight) {
  const n = skel.joints.length;
  let s = scratch.get(skel);
  if (!s || s.y.length !== n) {
    s = { rot: new Float64Array(9 * n), y: new Float64Array(n) };
    scratch.set(skel, s);
  }
  const { rot, y } = s;
  let lowest = Infinity;
  for (let j = 0; j < n; j++) {
    const joint = skel.joints[j];
    // R_local = R_dofs[0](a0) * R_dofs[1](a1) * ...
    localTmp.fill(0); localTmp[0] = localTmp[4] = localTmp[8] = 1;
    for (let k = 0; k < joint.dofs.length; k++) {
      const a = angles[joint.angleIndex + k] || 0;
      if (!a) continue;
      mul3(localTmp, 0, axisRotation(joint.dofs[k], a, axisTmp), 0, prodTmp, 0);
      localTmp.set(prodTmp);
    }
    const o = 9 * j;
    if (joint.parent < 0) {
      rot.set(localTmp, o);
      y[j] = rootHeight;
    } else {
      const po = 9 * joint.parent;
      const off = joint.offset;
      // The offset turns with the parent; only its height is kept.
      y[j] = y[joint.parent] + rot[po + 3] * off[0] + rot[po + 4] * off[1] + rot[po + 5] * off[2];
      mul3(rot, po, localTmp, 0, rot, o);
    }
    // The segment's lowest point: its centre's height less each half extent
    // times |its height weight| (a sphere: less its radius).
    const seg = joint.segment;
    const cy = y[j] + rot[o + 3] * seg.center[0] + rot[o + 4] * seg.center[1] + rot[o + 5] * seg.center[2];
    const low = seg.shape === 'sphere'
      ? cy - seg.size[0]
      : cy - 0.5 * (Math.abs(rot[o + 3]) * seg.size[0] + Math.abs(rot[o + 4]) * seg.size[1] + Math.abs(rot[o + 5]) * seg.size[2]);
    if (low < lowest) lowest = low;
  }
  return lowest;
}

// How far to raise a pose (m) so that nothing lies deeper than `tolerance`
// under the grass; 0 for a pose already on or above it.
export function grassLift(skel, angles, rootHeight, tolerance = GRASS_TOLERANCE_M) {
  const low = lowestPoint(skel, angles, rootHeight);
  return Number.isFinite(low) ? Math.max(0, -low - tolerance) : 0;
}
