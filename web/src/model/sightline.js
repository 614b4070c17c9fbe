// The close-up camera keeps its subject in sight. It stands beside him on
// the main stand's side at chest height; another player between the two
// filled the picture with his back (seen in a close-up of #10 behind #11),
// and one just beside the camera a corner of it with his arm.
// The camera then cuts to the nearest of a few bearings about the subject
// from which no one stands in the way, as a broadcast cuts to another
// camera. Pure functions of positions (field x, y in metres): no three.js.

// Bearings (deg) tried about the subject, from the straight-on view first.
export const CLOSEUP_BEARINGS_DEG = [0, -35, 35, -70, 70];
// The camera's offset from its subject at bearing 0 (field m): a little
// behind him towards -x, 4.6 m towards the main stand (+y).
const OFFSET = { x: -1.2, y: 4.6 };
// A body in the way: its centre this near the line of sight (m; a torso's
// half width and an arm).
export const BODY_RADIUS_M = 0.45;

// The camera's field position for a subject at (x, y) and a bearing.
export function closeupSpot(subject, bearingDeg) {
  const b = (bearingDeg * Math.PI) / 180, c = Math.cos(b), s = Math.sin(b);
  return { x: subject.x + OFFSET.x * c - OFFSET.y * s, y: subject.y + OFFSET.x * s + OFFSET.y * c };
}

// A body this near the camera (m) fills part of the close-up wherever in
// the picture it stands: a player just beside the camera put his forearm
// down a side of the frame (seen in a close-up of #10, 2026-11-30); the
// subject himself stands 4.75 m off.
export const NEAR_CAMERA_M = 2.5;
// Half the close-up's picture, across (deg): 38 deg of vertical field of
// view on a 16:9 screen is 63 across; a little more for the body's edge.
export const PICTURE_HALF_DEG = 33;

// Whether `other` stands in the way: between the camera and the subject,
// or within NEAR_CAMERA_M of the camera and in its picture.
export function blocks(cam, subject, other, radius = BODY_RADIUS_M) {
  const vx = subject.x - cam.x, vy = subject.y - cam.y;
  const len2 = vx * vx + vy * vy;
  if (!(len2 > 1e-6)) return false;
  const ox = other.x - cam.x, oy = other.y - cam.y;
  const t = (ox * vx + oy * vy) / len2;
  if (!(t > 0)) return false;  // behind the camera (or no position)
  const near = Math.hypot(ox, oy);
  if (near < NEAR_CAMERA_M) {
    // The angle off the line of sight, less the body's own half width as
    // seen from the camera.
    const off = Math.acos(Math.min(1, (ox * vx + oy * vy) / (near * Math.sqrt(len2))));
    const half = Math.asin(Math.min(1, radius / near));
    if ((off - half) * (180 / Math.PI) < PICTURE_HALF_DEG) return true;
  }
  if (!(t < 1)) return false;  // beyond the subject
  const px = cam.x + vx * t - other.x, py = cam.y + vy * t - other.y;
  return px * px + py * py < radius * radius;
}

function blockedAt(subject, others, index) {
  const cam = closeupSpot(subject, CLOSEUP_BEARINGS_DEG[index]);
  return others.some((o) => blocks(cam, subject, o));
}

// The bearing index to film from: `current` while no one blocks it, else
// the clear one nearest to it (by angle), else `current` (everyone in the
// way: no cut helps).
export function clearBearing(subject, others, current = 0) {
  const cur = Number.isInteger(current) && current >= 0 && current < CLOSEUP_BEARINGS_DEG.length ? current : 0;
  if (!blockedAt(subject, others, cur)) return cur;
  let best = cur, bestTurn = Infinity;
  CLOSEUP_BEARINGS_DEG.forEach((deg, i) => {
    const turn = Math.abs(deg - CLOSEUP_BEARINGS_DEG[cur]);
    if (i !== cur && turn < bestTurn && !blockedAt(subject, others, i)) { best = i; bestTurn = turn; }
  });
  return best;
}

// A player who crosses the line of sight for less than this (s of game
// time) is let pass rather than cut away from.
export const CLOSEUP_PATIENCE_S = 0.3;

// The close-up's bearing over time: a cut once the line of sight has been
// blocked for CLOSEUP_PATIENCE_S while the game moves. `at` is the stream
// position drawn: while it stays the same (paused, a viewer studying a
// frame, the page's contact sheet stepping frame by frame) nothing counts.
export class CloseupAim {
  constructor() {
    this.bearing = 0;        // index into CLOSEUP_BEARINGS_DEG
    this.blocked = 0;        // s the line of sight has been blocked
    this.at = undefined;     // the stream position last drawn
  }

  // Returns the camera's field position for `subject` among `others`.
  update(dt, at, subject, others) {
    const moving = at === undefined || at !== this.at;
    this.at = at;
    const clear = clearBearing(subject, others, this.bearing);
    this.blocked = clear === this.bearing ? 0 : this.blocked + (moving && dt > 0 ? dt : 0);
    if (this.blocked > CLOSEUP_PATIENCE_S) {
      this.bearing = clear;
      this.blocked = 0;
    }
    return closeupSpot(subject, CLOSEUP_BEARINGS_DEG[this.bearing]);
  }
}
