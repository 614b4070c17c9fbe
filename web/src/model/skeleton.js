// The skeleton definition as the page uses it: a parent-index array with
// rest offsets, per-joint rotation axes and one drawable segment each
// (proto/skeleton.hpp). normalizeSkeleton() accepts the hello's JSON in the
// shapes the wire may use and returns one canonical object, or throws with a
// message the page can show.
//
// Body space: Y up, the body faces +X, +Z is its right side.
// R_local = R_dofs[0](a0) * R_dofs[1](a1) * ... (intrinsic), and
// M_j = M_parent * T(offset) * R_local.

const vec3 = (v, what) => {
  if (!Array.isArray(v) || v.length !== 3 || !v.every(Number.isFinite))
    throw new Error(`skeleton: ${what} is not a 3-vector`);
  return v.map(Number);
};

// -> { name, joints: [{ name, parent, offset:[3], dofs:'zxy', limits,
//      segment: { shape: 'box'|'sphere', size:[3], center:[3] }, angleIndex }],
//      dofCount }
export function normalizeSkeleton(def) {
  if (!def || !Array.isArray(def.joints) || def.joints.length === 0)
    throw new Error('skeleton: no joints');
  let angleIndex = 0;
  const joints = def.joints.map((j, i) => {
    const parent = Number.isInteger(j.parent) ? j.parent : -1;
    if (parent >= i) throw new Error(`skeleton: joint ${i} comes before its parent`);
    if (i > 0 && parent < 0) throw new Error(`skeleton: joint ${i} has no parent`);
    const dofs = String(j.dofs ?? '').toLowerCase();
    if (!/^[xyz]*$/.test(dofs)) throw new Error(`skeleton: joint ${i} dofs "${dofs}"`);
    const seg = j.segment ?? {};
    const shape = (seg.shape === 1 || seg.shape === 'sphere') ? 'sphere' : 'box';
    const joint = {
      name: String(j.name ?? `joint${i}`),
      parent,
      offset: vec3(j.offset_ls ?? j.offset ?? [0, 0, 0], `joint ${i} offset`),
      dofs,
      limits: j.limits ?? [],
      segment: {
        shape,
        size: vec3(seg.size ?? [0, 0, 0], `joint ${i} segment size`),
        center: vec3(seg.center ?? [0, 0, 0], `joint ${i} segment center`),
      },
      angleIndex,
    };
    angleIndex += dofs.length;
    return joint;
  });
  return { name: String(def.name ?? 'skeleton'), joints, dofCount: angleIndex };
}

// Index of the first joint whose name matches the regular expression, or -1.
export function findJoint(skel, re) {
  return skel.joints.findIndex((j) => re.test(j.name));
}

// What a segment is dressed in, from its joint's name: the kit is drawn from
// the skeleton, so the page guesses body parts by the usual names and falls
// back to the shirt.
export function partOf(jointName) {
  const n = jointName.toLowerCase();
  if (/head|neck|skull/.test(n)) return 'skin';
  if (/hand|wrist|finger/.test(n)) return 'skin';
  if (/elbow|fore|lower_?arm|lowerarm/.test(n)) return 'skin';
  if (/toe|foot|ankle/.test(n)) return 'boot';
  if (/knee|shin|calf|lower_?leg|lowerleg/.test(n)) return 'sock';
  if (/hip|thigh|upper_?leg|upleg|pelvis|root/.test(n)) return 'shorts';
  return 'shirt';
}
