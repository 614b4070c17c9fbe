// The head and neck at human speed (issue 20). The stream carries the
// agent's neck exactly, and rcssserver turns a neck up to 180° in one cycle;
// drawn as is, a head snaps round in one frame. Here the drawn neck and head
// angles follow the stream's with a short lag, and their combined turn never
// exceeds `maxDegPerS` (600°/s, a fast human head turn). They arrive where
// the stream says, so the head still shows where the agent looks; the
// stream itself stays exact: this is only how it is drawn.

export const MAX_HEAD_DEG_PER_S = 600;

// One step of the drawn angles `cur` towards `target` over dt seconds, in
// place. `groups` lists the angle indices that add up along one axis (the
// neck's and the head's yaw, say): their summed change is what is limited,
// and every index moves by the same fraction of its way, so neck and head
// arrive together. A first-order lag (tau seconds) eases the end of a turn.
// Returns the fraction of the way moved (1: there).
export function limitTurn(cur, target, groups, dt, { maxDegPerS = MAX_HEAD_DEG_PER_S, tau = 0.05 } = {}) {
  if (!(dt > 0)) return 0;
  const ease = 1 - Math.exp(-dt / tau);
  const budget = maxDegPerS * dt;
  let f = ease;
  for (const g of groups) {
    let sum = 0;
    for (const i of g) sum += target[i] - cur[i];
    const step = Math.abs(sum) * ease;
    if (step > budget) f = Math.min(f, budget / Math.abs(sum));
  }
  for (const g of groups) for (const i of g) cur[i] += (target[i] - cur[i]) * f;
  return f;
}

// Per player, the drawn angles: the stream's, with the neck and head limited.
export class HeadSmoother {
  // skel: normalizeSkeleton() result.
  constructor(skel, options = {}) {
    this.options = options;
    this.state = new Map();   // key -> { angles: Float32Array, x, y }
    // The angle indices of the neck and head joints, grouped by axis letter.
    const byAxis = { x: [], y: [], z: [] };
    for (const j of skel.joints) {
      if (!/neck|head/i.test(j.name)) continue;
      [...j.dofs].forEach((axis, k) => byAxis[axis]?.push(j.angleIndex + k));
    }
    this.groups = Object.values(byAxis).filter((g) => g.length);
    this.indices = this.groups.flat();
  }

  // The angles to draw for player `key` this picture: `p` is the frame's
  // player ({ x, y, angles }); dt seconds since the last picture. A first
  // sight, a long pause or a teleport (a cut in time) snaps to the stream.
  apply(key, p, dt) {
    let s = this.state.get(key);
    const n = p.angles.length;
    const jumped = !s || s.angles.length !== n || !(dt < 0.5) || Math.hypot(p.x - s.x, p.y - s.y) > 3;
    if (!s || s.angles.length !== n) {
      s = { angles: new Float32Array(n), x: 0, y: 0, target: new Float32Array(n) };
      this.state.set(key, s);
    }
    s.x = p.x;
    s.y = p.y;
    // Everything but the neck and head is drawn as the stream says.
    const head = s.target;
    for (const i of this.indices) head[i] = p.angles[i];
    const drawn = s.angles;
    const keep = this.indices.map((i) => drawn[i]);
    drawn.set(p.angles);
    if (jumped) return drawn;
    this.indices.forEach((i, k) => { drawn[i] = keep[k]; });
    limitTurn(drawn, head, this.groups, dt, this.options);
    return drawn;
  }
}
