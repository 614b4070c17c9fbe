// Interpolation between two frames of the page's canonical shape:
//   { seq, time, stoppage, playMode, scoreLeft, scoreRight,
//     ball: {x, y, z}, players: [{ side, unum, state, x, y, z, heading,
//     angles, stamina? }] }   (field metres, field degrees)
// Positions and joint angles are blended linearly, the heading the short way
// round. Discrete data (play mode, score, state bits) comes from `a` until
// the playhead reaches `b`.

const lerp = (p, q, t) => p + (q - p) * t;

// Field degrees, the short way round.
export function lerpAngle(p, q, t) {
  let d = ((q - p) % 360 + 540) % 360 - 180;
  return p + d * t;
}

// Writes the blend of a and b into `out` (reused between calls, so a render
// tick allocates nothing once warmed up) and returns it.
export function blendFrames(a, b, t, out) {
  out ??= { ball: { x: 0, y: 0, z: 0 }, players: [] };
  const d = t >= 1 ? b : a;
  out.seq = lerp(a.seq, b.seq, t);
  out.time = d.time;
  out.stoppage = d.stoppage;
  out.playMode = d.playMode;
  out.scoreLeft = d.scoreLeft;
  out.scoreRight = d.scoreRight;
  out.serverTimeMs = lerp(a.serverTimeMs ?? 0, b.serverTimeMs ?? 0, t);
  out.extras = d.extras;
  out.ball.x = lerp(a.ball.x, b.ball.x, t);
  out.ball.y = lerp(a.ball.y, b.ball.y, t);
  out.ball.z = lerp(a.ball.z, b.ball.z, t);
  const n = a.players.length;
  out.players.length = n;
  for (let i = 0; i < n; i++) {
    const pa = a.players[i];
    // Same slot in b (slots are fixed: left 1..11, right 1..11).
    let pb = b.players[i];
    if (!pb || pb.side !== pa.side || pb.unum !== pa.unum) pb = pa;
    const o = (out.players[i] ??= { angles: new Float32Array(0) });
    o.side = pa.side;
    o.unum = pa.unum;
    o.state = (t >= 1 ? pb : pa).state;
    o.stamina = lerp(pa.stamina ?? NaN, pb.stamina ?? NaN, t);
    // A teleport (a move command at kick-off) is not animated across the pitch.
    const jump = Math.hypot(pb.x - pa.x, pb.y - pa.y) > 5;
    const tt = jump ? (t < 0.5 ? 0 : 1) : t;
    o.x = lerp(pa.x, pb.x, tt);
    o.y = lerp(pa.y, pb.y, tt);
    o.z = lerp(pa.z, pb.z, tt);
    o.heading = lerpAngle(pa.heading, pb.heading, tt);
    const m = pa.angles.length;
    if (o.angles.length !== m) o.angles = new Float32Array(m);
    const qa = pa.angles, qb = pb.angles.length === m ? pb.angles : qa;
    for (let k = 0; k < m; k++) o.angles[k] = lerp(qa[k], qb[k], tt);
  }
  return out;
}
