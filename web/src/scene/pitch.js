// The pitch: grass with mown stripes, the markings, the goals with nets, and
// a simple stand of ground around it. Geometry comes from the hello's field
// description; the defaults are rcssserver's hard-coded values
// (rcss-protocol.md section 1).
import * as THREE from 'three';

export const DEFAULT_FIELD = Object.freeze({
  length: 105, width: 68, margin: 5, centerCircleR: 9.15,
  penaltyAreaLength: 16.5, penaltyAreaWidth: 40.32, goalAreaLength: 5.5,
  goalAreaWidth: 18.32, goalDepth: 2.44, goalWidth: 14.02, goalHeight: 2.44,
  penaltySpotDist: 11, cornerArcR: 1,
});

// Accepts snake_case or camelCase keys from the hello, fills the rest.
export function normalizeField(f = {}) {
  const out = { ...DEFAULT_FIELD };
  for (const [k, v] of Object.entries(f ?? {})) {
    const camel = k.replace(/_([a-z])/g, (_, c) => c.toUpperCase());
    if (camel in out && Number.isFinite(Number(v))) out[camel] = Number(v);
  }
  return out;
}

const LINE_W = 0.12;   // m, painted line width
const Y_LINE = 0.012;  // lines sit just above the grass

// The markings as one canvas texture over the whole surface (crisp at any
// distance with anisotropic filtering, no z-fighting between lines).
function markingsTexture(F, renderer) {
  const W = F.length + 2 * F.margin, H = F.width + 2 * F.margin;
  const ppm = 20;  // pixels per metre
  const c = document.createElement('canvas');
  c.width = Math.round(W * ppm); c.height = Math.round(H * ppm);
  const g = c.getContext('2d');
  // Grass stripes across the length.
  const n = 18, sw = F.length / n;
  g.fillStyle = '#3f8a34'; g.fillRect(0, 0, c.width, c.height);
  for (let i = 0; i < n; i++) {
    g.fillStyle = i % 2 ? '#428f37' : '#4b9a3d';
    g.fillRect((F.margin + i * sw) * ppm, 0, sw * ppm + 1, c.height);
  }
  // Field metres -> canvas pixels.
  g.setTransform(ppm, 0, 0, ppm, (W / 2) * ppm, (H / 2) * ppm);
  g.strokeStyle = 'rgba(255,255,255,0.92)';
  g.fillStyle = 'rgba(255,255,255,0.92)';
  g.lineWidth = LINE_W;
  const L = F.length / 2, Wd = F.width / 2;
  g.strokeRect(-L, -Wd, F.length, F.width);
  g.beginPath(); g.moveTo(0, -Wd); g.lineTo(0, Wd); g.stroke();
  g.beginPath(); g.arc(0, 0, F.centerCircleR, 0, 2 * Math.PI); g.stroke();
  const spot = (x, y) => { g.beginPath(); g.arc(x, y, 0.22, 0, 2 * Math.PI); g.fill(); };
  spot(0, 0);
  for (const s of [-1, 1]) {
    const gx = s * L;
    g.strokeRect(Math.min(gx, gx - s * F.penaltyAreaLength), -F.penaltyAreaWidth / 2,
      F.penaltyAreaLength, F.penaltyAreaWidth);
    g.strokeRect(Math.min(gx, gx - s * F.goalAreaLength), -F.goalAreaWidth / 2,
      F.goalAreaLength, F.goalAreaWidth);
    const px = gx - s * F.penaltySpotDist;
    spot(px, 0);
    // Penalty arc: the part of the 9.15 m circle outside the area.
    const d = F.penaltyAreaLength - F.penaltySpotDist;
    const a = Math.acos(Math.min(1, d / F.centerCircleR));
    g.beginPath();
    if (s < 0) g.arc(px, 0, F.centerCircleR, -a, a);
    else g.arc(px, 0, F.centerCircleR, Math.PI - a, Math.PI + a);
    g.stroke();
    for (const t of [-1, 1]) {
      // Quarter circle into the field from the corner (gx, -t*Wd).
      const mid = Math.atan2(t, -s);
      g.beginPath();
      g.arc(gx, -t * Wd, F.cornerArcR, mid - Math.PI / 4, mid + Math.PI / 4);
      g.stroke();
    }
  }
  const tex = new THREE.CanvasTexture(c);
  tex.colorSpace = THREE.SRGBColorSpace;
  tex.anisotropy = renderer.capabilities.getMaxAnisotropy();
  tex.generateMipmaps = true;
  return tex;
}

// A goal at side s (-1 left, +1 right): posts, crossbar, and a net.
function makeGoal(F, s) {
  const group = new THREE.Group();
  const white = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.35 });
  const r = 0.06, hw = F.goalWidth / 2, h = F.goalHeight, d = F.goalDepth;
  const post = new THREE.CylinderGeometry(r, r, h, 12);
  for (const t of [-1, 1]) {
    const m = new THREE.Mesh(post, white);
    m.position.set(0, h / 2, t * (hw + r));
    m.castShadow = true;
    group.add(m);
  }
  const bar = new THREE.Mesh(new THREE.CylinderGeometry(r, r, F.goalWidth + 4 * r, 12), white);
  bar.rotation.x = Math.PI / 2;
  bar.position.set(0, h, 0);
  bar.castShadow = true;
  group.add(bar);

  // The net: a mesh pattern texture on the back, the roof and the sides.
  const c = document.createElement('canvas');
  c.width = c.height = 64;
  const g = c.getContext('2d');
  g.strokeStyle = 'rgba(255,255,255,0.85)';
  g.lineWidth = 3;
  g.strokeRect(0, 0, 64, 64);
  const tex = new THREE.CanvasTexture(c);
  tex.wrapS = tex.wrapT = THREE.RepeatWrapping;
  const netMat = (w, hh) => {
    const t = tex.clone();
    t.needsUpdate = true;
    t.repeat.set(w / 0.25, hh / 0.25);
    return new THREE.MeshStandardMaterial({
      map: t, transparent: true, alphaTest: 0.3, side: THREE.DoubleSide, roughness: 0.9,
    });
  };
  const back = new THREE.Mesh(new THREE.PlaneGeometry(F.goalWidth, h), netMat(F.goalWidth, h));
  back.position.set(s * d, h / 2, 0);
  back.rotation.y = Math.PI / 2;
  const roof = new THREE.Mesh(new THREE.PlaneGeometry(d, F.goalWidth), netMat(d, F.goalWidth));
  roof.rotation.x = -Math.PI / 2;
  roof.position.set(s * d / 2, h, 0);
  group.add(back, roof);
  for (const t of [-1, 1]) {
    const side = new THREE.Mesh(new THREE.PlaneGeometry(d, h), netMat(d, h));
    side.position.set(s * d / 2, h / 2, t * hw);
    group.add(side);
  }
  for (const m of group.children) m.castShadow = true;
  // Back frame bars at the foot of the net.
  group.position.set(s * F.length / 2, 0, 0);
  return group;
}

// Builds the pitch; returns the group to add to the scene.
export function createPitch(F, renderer) {
  const group = new THREE.Group();
  group.name = 'pitch';
  const W = F.length + 2 * F.margin, H = F.width + 2 * F.margin;
  const surface = new THREE.Mesh(
    new THREE.PlaneGeometry(W, H),
    new THREE.MeshStandardMaterial({ map: markingsTexture(F, renderer), roughness: 0.95 }));
  surface.rotation.x = -Math.PI / 2;
  surface.position.y = Y_LINE;
  surface.receiveShadow = true;
  group.add(surface);

  // Surroundings: a darker apron and a low stand on the far side.
  const apron = new THREE.Mesh(new THREE.PlaneGeometry(W + 60, H + 60),
    new THREE.MeshStandardMaterial({ color: 0x2f5d2a, roughness: 1 }));
  apron.rotation.x = -Math.PI / 2;
  apron.position.y = -0.08;   // well below the pitch: no depth fighting from high cameras
  apron.receiveShadow = true;
  group.add(apron);
  const boardMat = new THREE.MeshStandardMaterial({ color: 0x1d2b44, roughness: 0.6 });
  for (const s of [-1, 1]) {
    // Advertising boards along both touchlines, a stand behind the far one.
    const board = new THREE.Mesh(new THREE.BoxGeometry(F.length + 10, 0.9, 0.1), boardMat);
    board.position.set(0, 0.45, s * (H / 2 + 1.5));
    board.receiveShadow = true;
    group.add(board);
  }
  // Stepped stands with alternating seat colours behind the far touchline
  // (the broadcast camera's background) and behind both goals.
  const seat = [new THREE.MeshStandardMaterial({ color: 0x2b4266, roughness: 0.9 }),
    new THREE.MeshStandardMaterial({ color: 0x35507a, roughness: 0.9 })];
  const stand = (length, x, z, rotY) => {
    const g = new THREE.Group();
    for (let i = 0; i < 8; i++) {
      const h = 0.8 + i * 0.8;
      const tier = new THREE.Mesh(new THREE.BoxGeometry(length, h, 1.6), seat[i % 2]);
      tier.position.set(0, h / 2, -(i * 1.6));
      tier.receiveShadow = true;
      g.add(tier);
    }
    g.position.set(x, 0, z);
    g.rotation.y = rotY;
    group.add(g);
  };
  stand(F.length + 24, 0, -(H / 2 + 4), 0);
  stand(H + 8, -(W / 2 + 6), 0, Math.PI / 2);
  stand(H + 8, W / 2 + 6, 0, -Math.PI / 2);
  group.add(makeGoal(F, -1), makeGoal(F, 1));
  return group;
}
