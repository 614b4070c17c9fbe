// Players: the skeleton definition becomes a hierarchy of joint nodes (the
// bones of a skinned body, scene/body_mesh.js; for another skeleton, one box
// or sphere per joint); a pose becomes the joint transforms.
//
// Per player: root node at (x, z, y) turned by -heading about +Y (field to
// scene, rcss-protocol.md section 1), then the joints with
// M_j = M_parent * T(offset) * R_local (proto/skeleton.hpp). Joint 0 is the
// pelvis and sits at the root position the frame gives, so its rest offset
// is not added again.
import * as THREE from 'three';
import { findJoint, partOf } from '../model/skeleton.js';
import { STATE } from '../model/playmodes.js';
import { makeKit, numberTexture, contrastColor } from './kit.js';
import { HeadSmoother } from '../model/neck.js';
import { FatiguePose, tiredness } from '../model/fatigue.js';
import { grassLift } from '../model/ground.js';
import { playModeName } from '../model/playmodes.js';
import { BodyFactory } from './body_mesh.js';

const DEG = Math.PI / 180;
const AXES = { x: new THREE.Vector3(1, 0, 0), y: new THREE.Vector3(0, 1, 0), z: new THREE.Vector3(0, 0, 1) };
const _q = new THREE.Quaternion();
const LABEL_SIZE = 0.016;  // fraction of the view's height

// R_local = R_dofs[0](a0) * R_dofs[1](a1) * ... written into `out`.
export function localRotation(dofs, angles, first, out) {
  out.identity();
  for (let k = 0; k < dofs.length; k++) {
    const a = angles[first + k];
    if (a) out.multiply(_q.setFromAxisAngle(AXES[dofs[k]], a * DEG));
  }
  return out;
}

// The joint that wears the shirt number: the largest 'shirt' box.
function chestJoint(skel) {
  let best = -1, vol = 0;
  skel.joints.forEach((j, i) => {
    if (partOf(j.name) !== 'shirt' || j.segment.shape !== 'box') return;
    const v = j.segment.size[0] * j.segment.size[1] * j.segment.size[2];
    if (v > vol) { vol = v; best = i; }
  });
  return best;
}

export class Players {
  // skel: normalizeSkeleton() result; teams: hello { left, right }.
  constructor(scene, skel, teams = {}) {
    this.scene = scene;
    this.skel = skel;
    this.kits = { 1: makeKit('left', teams.left), [-1]: makeKit('right', teams.right) };
    this.group = new THREE.Group();
    this.group.name = 'players';
    scene.add(this.group);
    this.headJoint = findJoint(skel, /head/i);
    if (this.headJoint < 0) this.headJoint = skel.joints.length - 1;
    this.chest = chestJoint(skel);
    this.rigs = new Map();       // `${side}:${unum}` -> rig
    this.pickables = [];         // meshes for the ray caster
    this.showLabels = true;
    this.selected = null;        // rig key
    this.hiddenKey = null;       // first-person view hides this player's head
    // Heads turn at human speed where they are drawn (model/neck.js).
    this.heads = new HeadSmoother(skel);
    // Smooth skinned bodies for the server's skeleton; boxes otherwise.
    this.bodies = BodyFactory.for(skel);
    // Tired players lean, swing their arms less, rest their hands on their knees.
    this.fatigue = new FatiguePose(skel);
    // ?tired draws every player exhausted: to see the fatigue poses.
    this.allTired = typeof location !== 'undefined' && new URLSearchParams(location.search).has('tired');
    this.lastUpdate = null;

    const ringGeo = new THREE.RingGeometry(0.55, 0.7, 40);
    this.ring = new THREE.Mesh(ringGeo, new THREE.MeshBasicMaterial({
      color: 0xffffff, transparent: true, opacity: 0.9, depthWrite: false }));
    this.ring.rotation.x = -Math.PI / 2;
    this.ring.position.y = 0.03;
    this.ring.visible = false;
    scene.add(this.ring);
  }

  dispose() {
    this.scene.remove(this.group);
    this.scene.remove(this.ring);
    this.group.traverse((o) => { if (o.isMesh && !o.isSkinnedMesh) o.geometry.dispose(); });
    for (const rig of this.rigs.values()) rig.body?.dispose();
  }

  _buildRig(side, unum, goalie) {
    const kit = this.kits[side] ?? this.kits[1];
    const mats = goalie ? kit.goalie : kit.field;
    const root = new THREE.Group();
    const nodes = [];
    const key = `${side}:${unum}`;
    this.skel.joints.forEach((j, i) => {
      const node = new THREE.Bone();
      if (i > 0) node.position.fromArray(j.offset);
      (i === 0 ? root : nodes[j.parent]).add(node);
      nodes.push(node);
      const s = j.segment;
      let geo = null;
      if (s.shape === 'sphere' && s.size[0] > 0) geo = new THREE.SphereGeometry(s.size[0], 16, 12);
      else if (s.shape === 'box' && s.size[0] > 0 && s.size[1] > 0 && s.size[2] > 0)
        geo = new THREE.BoxGeometry(...s.size);
      if (!geo) return;
      const mesh = new THREE.Mesh(geo, mats[partOf(j.name)] ?? mats.shirt);
      mesh.position.fromArray(s.center);
      mesh.castShadow = true;
      // With a body the boxes are not drawn; they stay for picking.
      mesh.visible = !this.bodies;
      mesh.userData.playerKey = key;
      mesh.userData.joint = i;
      node.add(mesh);
      this.pickables.push(mesh);
    });
    let body = null;
    if (this.bodies) {
      body = this.bodies.make(root, nodes, { shirt: mats.shirt.color, shorts: mats.shorts.color, sock: mats.sock.color },
        side, unum, goalie);
    }
    // Shirt numbers on the back and the front of the chest.
    if (!body && this.chest >= 0) {
      const s = this.skel.joints[this.chest].segment;
      const shirt = goalie ? kit.goalieColor : kit.shirtColor;
      const tex = numberTexture(unum, contrastColor(shirt));
      const mat = new THREE.MeshBasicMaterial({ map: tex, transparent: true, depthWrite: false,
        polygonOffset: true, polygonOffsetFactor: -2 });
      const h = Math.min(s.size[1], s.size[2]) * 0.85;
      for (const [dir, scale] of [[-1, 1], [1, 0.5]]) {
        const p = new THREE.Mesh(new THREE.PlaneGeometry(h * scale, h * scale), mat);
        p.position.set(s.center[0] + dir * (s.size[0] / 2 + 0.004), s.center[1] + (dir > 0 ? h * 0.2 : 0), s.center[2]);
        p.rotation.y = dir < 0 ? -Math.PI / 2 : Math.PI / 2;
        nodes[this.chest].add(p);
      }
    }
    // A number label above the head, readable from the broadcast camera.
    const label = new THREE.Sprite(new THREE.SpriteMaterial({
      map: numberTexture(unum, (goalie ? kit.goalieColor : kit.shirtColor), 'rgba(0,0,0,0.85)'),
      depthWrite: false, sizeAttenuation: false }));
    // Constant size on screen, like a broadcast graphic, at any distance.
    label.scale.set(LABEL_SIZE, LABEL_SIZE, 1);
    label.renderOrder = 10;
    this.group.add(root, label);
    return { key, side, unum, goalie, root, nodes, label, body, visible: true, pose: null };
  }

  // The rig for a player, rebuilt when its role (goalie or not) changes.
  _rig(p) {
    const key = `${p.side}:${p.unum}`;
    const goalie = (p.state & STATE.GOALIE) !== 0;
    let rig = this.rigs.get(key);
    if (rig && rig.goalie !== goalie) {
      this.group.remove(rig.root, rig.label);
      rig.body?.dispose();
      this.pickables = this.pickables.filter((m) => m.userData.playerKey !== key);
      rig = null;
    }
    if (!rig) {
      rig = this._buildRig(p.side, p.unum, goalie);
      this.rigs.set(key, rig);
    }
    return rig;
  }

  // Applies one (interpolated) frame's players. ctx (optional): { stamina:
  // { 1: left[11], -1: right[11] }, staminaMax, playMode, ball } for fatigue.
  update(players, ctx = {}) {
    const skel = this.skel;
    const seen = new Set();
    const now = performance.now();
    const dt = this.lastUpdate === null ? 0 : (now - this.lastUpdate) / 1000;
    this.lastUpdate = now;
    const stoppage = ctx.playMode !== undefined && ctx.playMode !== null && playModeName(ctx.playMode) !== 'play_on';
    for (const p of players) {
      const rig = this._rig(p);
      seen.add(rig.key);
      rig.pose = p;
      // Disconnected players (state 0) are parked off the pitch: not drawn.
      const visible = p.state !== 0;
      rig.root.visible = visible;
      // The chosen player has its ring and card instead of a label.
      rig.label.visible = visible && this.showLabels && rig.key !== this.selected;
      if (!visible) continue;
      rig.root.rotation.set(0, -p.heading * DEG, 0);
      const smooth = this.heads.apply(rig.key, p, dt);
      if (!rig.drawn || rig.drawn.length !== smooth.length) rig.drawn = new Float32Array(smooth.length);
      const angles = rig.drawn;
      angles.set(smooth);
      rig.tired = this.allTired ? 1 : tiredness(ctx.stamina?.[p.side]?.[p.unum - 1], ctx.staminaMax);
      const drop = this.fatigue.apply(rig.key, p, angles, rig.tired, dt, { stoppage, ball: ctx.ball });
      // Resting on the grass: a blend of two frames can dip a sole under it.
      const lift = grassLift(skel, angles, p.z - drop);
      rig.root.position.set(p.x, p.z - drop + lift, p.y);
      for (let i = 0; i < skel.joints.length; i++) {
        const j = skel.joints[i];
        localRotation(j.dofs, angles, j.angleIndex, rig.nodes[i].quaternion);
      }
      rig.label.position.set(p.x, p.z + 1.15, p.y);
      if (rig.key === this.hiddenKey) rig.root.visible = false;
    }
    for (const [key, rig] of this.rigs) {
      if (!seen.has(key)) { rig.root.visible = false; rig.label.visible = false; }
    }
    const sel = this.selected && this.rigs.get(this.selected);
    this.ring.visible = !!(sel && sel.root.visible);
    if (this.ring.visible) {
      this.ring.position.x = sel.pose.x;
      this.ring.position.z = sel.pose.y;
      this.ring.material.color.copy(this.kits[sel.side].shirtColor);
    }
  }

  // The player key under a normalized device coordinate, or null.
  pick(ndc, camera) {
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, camera);
    const hits = ray.intersectObjects(this.pickables.filter((m) => {
      const rig = this.rigs.get(m.userData.playerKey);
      return rig && rig.root.visible;
    }), false);
    if (hits.length) return hits[0].object.userData.playerKey;
    // Forgiving pick: the nearest player to where the ray meets the grass.
    const t = -ray.ray.origin.y / ray.ray.direction.y;
    if (!(t > 0)) return null;
    const gx = ray.ray.origin.x + t * ray.ray.direction.x;
    const gz = ray.ray.origin.z + t * ray.ray.direction.z;
    let best = null, bd = 1.5;
    for (const rig of this.rigs.values()) {
      if (!rig.root.visible || !rig.pose) continue;
      const d = Math.hypot(rig.pose.x - gx, rig.pose.y - gz);
      if (d < bd) { bd = d; best = rig.key; }
    }
    return best;
  }

  // World matrix of a player's head joint (for the first-person camera).
  headMatrix(key) {
    const rig = this.rigs.get(key);
    if (!rig || !rig.pose) return null;
    const wasVisible = rig.root.visible;
    rig.root.visible = true;
    rig.root.updateWorldMatrix(true, true);
    rig.root.visible = wasVisible;
    return rig.nodes[this.headJoint].matrixWorld;
  }

  // How many drawn bodies are at each level of detail: { near, far, boxes }.
  lodCounts() {
    const out = { near: 0, far: 0, boxes: 0 };
    for (const rig of this.rigs.values()) {
      if (!rig.root.visible) continue;
      if (!rig.body) out.boxes++;
      else if (rig.body.lod.getCurrentLevel() === 0) out.near++;
      else out.far++;
    }
    return out;
  }

  get(key) { return this.rigs.get(key) ?? null; }

  // Field positions ({x, y}) of the players on the pitch but `except` (a key).
  positions(except = null) {
    const out = [];
    for (const rig of this.rigs.values())
      if (rig.key !== except && rig.pose && rig.root.visible) out.push({ x: rig.pose.x, y: rig.pose.y });
    return out;
  }
  keys() { return [...this.rigs.keys()]; }
}
