// A footballer's body, generated in code (issue 20): web/assets/body.json
// describes it as rings around the skeleton's bones (trunk, arms, hands,
// legs, boots) and an ellipsoid head; this turns the description into a
// skinned triangle mesh in the skeleton's rest pose. viewer/body_mesh.cpp
// does exactly the same, vertex for vertex, for the native viewer
// (tests/web/body_model.test.mjs and tests/viewer/body_mesh_test.cpp check
// both against one summary).
//
// Conventions (proto/skeleton.hpp): body space Y up, the body faces +X, +Z
// is its right side; at rest every joint angle is 0, so a joint's frame is
// its rest position with the body's axes. Each vertex has up to two bones
// (its ring's joint, and a blend joint at the joints' seams) and a region
// (shirt, shorts, sock, boot, skin, hair) that the kit colours.
//
// Pure: no three.js, no DOM (node runs it).

// Rest positions of the joints (model space, the root at the origin).
export function restPositions(skel) {
  const out = [];
  skel.joints.forEach((j, i) => {
    const p = i === 0 ? [0, 0, 0] : out[j.parent].map((v, k) => v + j.offset[k]);
    out.push(p);
  });
  return out;
}

// mesh: { positions: Float32Array(3n), skinIndex: Uint16Array(4n),
//   skinWeight: Float32Array(4n), region: Uint8Array(n), index: Uint32Array,
//   vertexCount, regions: [names] }, or null when the skeleton lacks a joint
// the description names (another skeleton: the page draws boxes then).
export function buildBodyGeometry(spec, skel, lod = 0) {
  const jointIndex = new Map(skel.joints.map((j, i) => [j.name, i]));
  const rest = restPositions(skel);
  const regions = spec.regions;
  const N = spec.points[Math.min(lod, spec.points.length - 1)];
  const pos = [], idx = [], wIdx = [], wVal = [], reg = [];
  const vertex = (p, joint, blend, region) => {
    pos.push(p[0], p[1], p[2]);
    wIdx.push(joint, blend ? blend[0] : 0, 0, 0);
    wVal.push(blend ? 1 - blend[1] : 1, blend ? blend[1] : 0, 0, 0);
    reg.push(region);
    return pos.length / 3 - 1;
  };
  const at = (i) => [pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]];
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  // A triangle facing away from `inside` (a point inside the body).
  const tri = (a, b, c, inside) => {
    const n = cross(sub(at(b), at(a)), sub(at(c), at(a)));
    if (dot(n, sub(at(a), inside)) < 0) idx.push(a, c, b); else idx.push(a, b, c);
  };

  const chains = [];
  for (const c of spec.chains) {
    chains.push({ chain: c, mirror: false });
    if (c.mirror) chains.push({ chain: c, mirror: true });
  }
  for (const { chain, mirror } of chains) {
    const rename = (name) => (mirror && name.startsWith('r_') ? chain.mirror + name.slice(2) : name);
    const rings = [];
    for (const r of chain.rings) {
      const j = jointIndex.get(rename(r.j));
      const b = r.b ? jointIndex.get(rename(r.b[0])) : null;
      if (j === undefined || b === undefined) return null;
      const m = regions.indexOf(r.m);
      const c = r.c ?? [0, 0];
      const s = mirror ? -1 : 1;
      // The ring's centre and its points, in the joint's frame, then at rest.
      const local = chain.axis === 'x' ? [r.at, c[0], c[1] * s] : [c[0], r.at, c[1] * s];
      const centre = local.map((v, k) => v + rest[j][k]);
      const first = pos.length / 3;
      for (let k = 0; k < N; k++) {
        const th = (2 * Math.PI * k) / N;
        const u = r.r[0] * Math.cos(th), v = r.r[1] * Math.sin(th) * s;
        const off = chain.axis === 'x' ? [0, u, v] : [u, 0, v];
        vertex(centre.map((x, q) => x + off[q]), j, b === null ? null : [b, r.b[1]], m);
      }
      rings.push({ first, centre, j, b: b === null ? null : [b, r.b[1]], m });
    }
    for (let i = 0; i + 1 < rings.length; i++) {
      const A = rings[i], B = rings[i + 1];
      for (let k = 0; k < N; k++) {
        const a = A.first + k, b = A.first + (k + 1) % N, c = B.first + (k + 1) % N, d = B.first + k;
        tri(a, b, c, A.centre);
        tri(a, c, d, A.centre);
      }
    }
    // Caps: a centre point, a little beyond the end ring, and a fan.
    const cap = (R, away) => {
      const dir = sub(R.centre, away.centre);
      const len = Math.hypot(...dir) || 1;
      const tip = R.centre.map((v, q) => v + (dir[q] / len) * 0.01);
      const t = vertex(tip, R.j, R.b, R.m);
      for (let k = 0; k < N; k++) tri(t, R.first + k, R.first + (k + 1) % N, away.centre);
    };
    if (chain.caps?.[0] && rings.length > 1) cap(rings[0], rings[1]);
    if (chain.caps?.[1] && rings.length > 1) cap(rings[rings.length - 1], rings[rings.length - 2]);
  }

  // The head: an ellipsoid with hair on top and at the back, and a nose.
  const h = spec.head;
  const hj = jointIndex.get(h.j);
  if (hj === undefined) return null;
  const R = h.rings[Math.min(lod, h.rings.length - 1)];
  const hc = h.c.map((v, k) => v + rest[hj][k]);
  const skin = regions.indexOf(h.m), hair = regions.indexOf('hair');
  const headVertex = (p) => {
    const rel = sub(p, hc);
    if (h.nose) {
      const d = Math.hypot(...sub(rel, h.nose.at));
      if (d < h.nose.radius) p = [p[0] + h.nose.push * (1 - d / h.nose.radius), p[1], p[2]];
    }
    const isHair = rel[1] > h.hair.above || (rel[0] < h.hair.behind && rel[1] > h.hair.behind_above);
    return vertex(p, hj, null, isHair ? hair : skin);
  };
  const headFirst = pos.length / 3;
  for (let i = 1; i < R; i++) {
    const phi = (Math.PI * i) / R;
    for (let k = 0; k < N; k++) {
      const th = (2 * Math.PI * k) / N;
      headVertex([hc[0] + h.r[0] * Math.sin(phi) * Math.cos(th), hc[1] + h.r[1] * Math.cos(phi),
        hc[2] + h.r[2] * Math.sin(phi) * Math.sin(th)]);
    }
  }
  const top = headVertex([hc[0], hc[1] + h.r[1], hc[2]]);
  const bottom = headVertex([hc[0], hc[1] - h.r[1], hc[2]]);
  for (let i = 0; i + 1 < R - 1; i++) {
    for (let k = 0; k < N; k++) {
      const a = headFirst + i * N + k, b = headFirst + i * N + (k + 1) % N;
      const c = headFirst + (i + 1) * N + (k + 1) % N, d = headFirst + (i + 1) * N + k;
      tri(a, b, c, hc);
      tri(a, c, d, hc);
    }
  }
  const last = headFirst + (R - 2) * N;
  for (let k = 0; k < N; k++) {
    tri(top, headFirst + k, headFirst + (k + 1) % N, hc);
    tri(bottom, last + k, last + (k + 1) % N, hc);
  }

  return {
    positions: Float32Array.from(pos), skinIndex: Uint16Array.from(wIdx), skinWeight: Float32Array.from(wVal),
    region: Uint8Array.from(reg), index: Uint32Array.from(idx), vertexCount: pos.length / 3, regions,
  };
}

// What both generators must agree on: counts, bounds and a weighted sum of
// the positions (rounded: float32 vs float64 arithmetic).
export function meshSummary(mesh) {
  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  let sum = 0, weights = 0;
  for (let i = 0; i < mesh.vertexCount; i++) {
    for (let k = 0; k < 3; k++) {
      const v = mesh.positions[3 * i + k];
      min[k] = Math.min(min[k], v);
      max[k] = Math.max(max[k], v);
      sum += v * (k + 1);
    }
    weights += mesh.skinIndex[4 * i] * 3 + mesh.skinIndex[4 * i + 1] + mesh.region[i] * 7;
  }
  let tris = 0;
  for (let t = 0; t < mesh.index.length; t += 3) tris += mesh.index[t] + 2 * mesh.index[t + 1] + 3 * mesh.index[t + 2];
  const r = (v) => Math.round(v * 1000) / 1000;
  return { vertices: mesh.vertexCount, triangles: mesh.index.length / 3, min: min.map(r), max: max.map(r),
    positionSum: r(sum), boneRegionSum: weights, indexSum: tris };
}

// A player's skin and hair tones: fixed per player (side 1 / -1, unum), so
// every client and every replay shows him the same.
export function tonesOf(spec, side, unum) {
  const s = side === 1 || side === 'left' ? 0 : 1;
  return {
    skin: spec.skin_tones[(unum * 7 + s * 3) % spec.skin_tones.length],
    hair: spec.hair_tones[(unum * 5 + s * 2 + 1) % spec.hair_tones.length],
  };
}
