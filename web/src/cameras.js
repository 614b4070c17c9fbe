// Camera modes. Each mode computes where the camera wants to be from the
// current (interpolated) view; the camera eases towards it so that cuts
// inside a mode are smooth. Orbit and free hand the camera to the user.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { CloseupAim } from './model/sightline.js';

export const CAMERA_MODES = [
  { id: 'director', key: '0', label: 'Director' },
  { id: 'broadcast', key: '1', label: 'Broadcast' },
  { id: 'orbit', key: '2', label: 'Orbit' },
  { id: 'free', key: '3', label: 'Free' },
  { id: 'player', key: '4', label: 'Player view' },
  { id: 'follow', key: '5', label: 'Follow' },
  { id: 'goal', key: '6', label: 'Goal line' },
  { id: 'top', key: '7', label: 'Top-down' },
  { id: 'closeup', key: '8', label: 'Close-up' },
];

const DEG = Math.PI / 180;

export class Cameras {
  constructor(camera, dom, field) {
    this.camera = camera;
    this.dom = dom;
    this.field = field;
    // The director's cut (director.js) unless the spectator picks a camera.
    this.mode = 'director';
    this.director = null;
    this.goal = new THREE.Vector3();         // where the camera wants to be
    this.look = new THREE.Vector3(0, 0, 0);  // smoothed look-at point
    this.lookGoal = new THREE.Vector3();
    this.fovGoal = 40;
    this.snap = true;
    this.closeupAim = new CloseupAim();   // the close-up's bearing, clear of other players
    this.orbit = new OrbitControls(camera, dom);
    this.orbit.enabled = false;
    this.orbit.enableDamping = true;
    this.orbit.maxPolarAngle = 88 * DEG;
    this.orbit.minDistance = 3;
    this.orbit.maxDistance = 250;
    // Free camera: WASD/arrows move, Q/E down/up, drag to look.
    this.keys = new Set();
    this.yaw = 0; this.pitch = -0.3;
    this.dragging = null;
    window.addEventListener('keydown', (e) => { if (!e.target.closest?.('input,select')) this.keys.add(e.code); });
    window.addEventListener('keyup', (e) => this.keys.delete(e.code));
    window.addEventListener('blur', () => this.keys.clear());
    dom.addEventListener('pointerdown', (e) => {
      if (this.mode === 'free') this.dragging = { x: e.clientX, y: e.clientY };
    });
    window.addEventListener('pointerup', () => { this.dragging = null; });
    window.addEventListener('pointermove', (e) => {
      if (!this.dragging || this.mode !== 'free') return;
      this.yaw -= (e.clientX - this.dragging.x) * 0.004;
      this.pitch = Math.max(-1.5, Math.min(1.5, this.pitch - (e.clientY - this.dragging.y) * 0.004));
      this.dragging = { x: e.clientX, y: e.clientY };
    });
  }

  setMode(mode) {
    if (!CAMERA_MODES.some((m) => m.id === mode) || mode === this.mode) return;
    this.mode = mode;
    this.snap = true;
    this.orbit.enabled = mode === 'orbit';
    if (mode === 'orbit') {
      // Start wide, the whole pitch in view from the main stand, then the
      // user turns, pans and zooms around the ball.
      this.orbit.target.set(0, 0, 0);
      this.camera.position.set(0, 60, this.field.width / 2 + 55);
      this.camera.fov = 40;
      this.camera.updateProjectionMatrix();
      this.orbit.update();
    }
    if (mode === 'free') {
      const d = new THREE.Vector3();
      this.camera.getWorldDirection(d);
      this.yaw = Math.atan2(-d.x, -d.z);
      this.pitch = Math.asin(Math.max(-1, Math.min(1, d.y)));
    }
  }

  // view: { ball: {x,y,z}, players: Players, selected: key|null, at: stream position }
  // Returns the player key the camera needs hidden (first person), or null.
  update(dt, view) {
    const cam = this.camera;
    const F = this.field;
    const ball = new THREE.Vector3(view.ball.x, Math.max(0, view.ball.z), view.ball.y);
    const k = this.snap ? 1 : 1 - Math.exp(-dt * 3);
    const rig = view.selected ? view.players.get(view.selected) : null;
    const pose = rig?.pose && rig.root.visible !== undefined ? rig.pose : null;
    let hide = null;
    const aspect = cam.aspect || 1;

    switch (this.mode) {
      case 'director': {
        if (this.director) {
          this.director.drive(cam, dt, view, aspect, this.field);
          this.snap = false;
          return null;
        }
        this._overview(aspect);
        break;
      }
      case 'broadcast': {
        // From the main stand on the +y side, level with the ball, zoomed.
        // A portrait screen sees little width: come closer and higher.
        const bx = THREE.MathUtils.clamp(ball.x, -F.length / 2, F.length / 2);
        const bz = THREE.MathUtils.clamp(ball.z, -F.width / 2, F.width / 2);
        if (aspect < 1) this.goal.set(bx * 0.9, 30, F.width / 2 + 22);
        else this.goal.set(bx * 0.8, 22, F.width / 2 + 40);
        this.lookGoal.set(bx, 0, bz * 0.7);
        this.fovGoal = aspect < 1 ? 50 : 24;
        break;
      }
      case 'orbit': {
        // Orbit about the point the user chose (right-drag pans it).
        this.orbit.update();
        this.look.copy(this.orbit.target);
        this.snap = false;
        return null;
      }
      case 'free': {
        const speed = (this.keys.has('ShiftLeft') || this.keys.has('ShiftRight') ? 40 : 15) * dt;
        const fwd = new THREE.Vector3(-Math.sin(this.yaw), 0, -Math.cos(this.yaw));
        const right = new THREE.Vector3(-fwd.z, 0, fwd.x);
        const has = (...c) => c.some((x) => this.keys.has(x));
        if (has('KeyW', 'ArrowUp')) cam.position.addScaledVector(fwd, speed);
        if (has('KeyS', 'ArrowDown')) cam.position.addScaledVector(fwd, -speed);
        if (has('KeyD', 'ArrowRight')) cam.position.addScaledVector(right, speed);
        if (has('KeyA', 'ArrowLeft')) cam.position.addScaledVector(right, -speed);
        if (has('KeyE')) cam.position.y += speed;
        if (has('KeyQ')) cam.position.y = Math.max(0.3, cam.position.y - speed);
        cam.rotation.set(this.pitch, this.yaw, 0, 'YXZ');
        this.snap = false;
        return null;
      }
      case 'player': {
        const m = rig ? view.players.headMatrix(rig.key) : null;
        if (m) {
          // From the head joint, looking along the head's forward (+X).
          const head = new THREE.Vector3().setFromMatrixPosition(m);
          const fwd = new THREE.Vector3(1, 0, 0).transformDirection(m);
          this.goal.copy(head).addScaledVector(fwd, 0.12);
          this.lookGoal.copy(head).addScaledVector(fwd, 10);
          this.lookGoal.y = Math.min(this.lookGoal.y, head.y);
          hide = rig.key;
          this.fovGoal = 70;
          // First person moves with the head: no lag.
          cam.position.copy(this.goal);
          this.look.lerp(this.lookGoal, 1 - Math.exp(-dt * 10));
          cam.fov = this.fovGoal;
          cam.updateProjectionMatrix();
          cam.lookAt(this.snap ? this.lookGoal : this.look);
          if (this.snap) this.look.copy(this.lookGoal);
          this.snap = false;
          return hide;
        }
        this._overview(aspect);
        break;
      }
      case 'follow': {
        if (pose) {
          const h = -pose.heading * DEG;
          const dir = new THREE.Vector3(Math.cos(h), 0, -Math.sin(h));
          const p = new THREE.Vector3(pose.x, 0, pose.y);
          this.goal.copy(p).addScaledVector(dir, -7).setY(3.5);
          this.lookGoal.copy(p).addScaledVector(dir, 5).setY(0.8);
          this.fovGoal = 50;
        } else this._overview(aspect);
        break;
      }
      case 'closeup': {
        // Beside the chosen player, from the main stand's side at chest
        // height: his body, his kicks. (His heading turns too often to
        // hang the camera on it.)
        if (pose) {
          // Someone in the way for a moment is let pass; for longer, a cut
          // to a bearing from which no one is (model/sightline.js).
          const others = view.players.positions?.(rig?.key) ?? [];
          const at = this.closeupAim.update(dt, view.at, pose, others);
          this.goal.set(at.x, 1.35, at.y);
          this.lookGoal.set(pose.x, 0.8, pose.y);
          this.fovGoal = aspect < 1 ? 55 : 38;
          this.snap = true;   // held on him: his interpolated pose is smooth already
        } else this._overview(aspect);
        break;
      }
      case 'goal': {
        // The goal line the ball is nearer to, seen along itself from beside
        // the pitch (level with the line, as a referee's goal-line camera):
        // the line runs straight up the screen through the goal mouth, so a
        // ball over it is plainly over.
        const s = ball.x >= 0 ? 1 : -1;
        this.goal.set(s * F.length / 2, 2.5, F.width / 2 + 9);
        this.lookGoal.set(s * F.length / 2, 0.8, 0);
        this.fovGoal = aspect < 1 ? 45 : 28;
        break;
      }
      case 'top': {
        // The monitor's view: -Z (the top touchline) up on the screen.
        const vfov = 40;
        const needH = Math.max(F.width + 2 * F.margin, (F.length + 2 * F.margin) / aspect);
        const h = needH / 2 / Math.tan((vfov / 2) * DEG);
        this.goal.set(0, h, 0.001);
        this.lookGoal.set(0, 0, 0);
        this.fovGoal = vfov;
        break;
      }
      default: break;
    }
    if (this.snap) {
      cam.position.copy(this.goal);
      this.look.copy(this.lookGoal);
      cam.fov = this.fovGoal;
    } else {
      cam.position.lerp(this.goal, k);
      this.look.lerp(this.lookGoal, 1 - Math.exp(-dt * 5));
      cam.fov += (this.fovGoal - cam.fov) * k;
    }
    cam.up.set(0, 1, 0);
    if (this.mode === 'top') cam.up.set(0, 0, -1);
    cam.lookAt(this.look);
    cam.updateProjectionMatrix();
    this.snap = false;
    return hide;
  }

  // Fallback for the player modes while no player is chosen.
  _overview(aspect) {
    const F = this.field;
    this.goal.set(0, 45, F.width / 2 + 45);
    this.lookGoal.set(0, 0, 0);
    this.fovGoal = aspect < 1 ? 60 : 40;
  }
}
