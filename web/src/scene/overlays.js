// Tactical overlays drawn on the grass: the offside line of each team, the
// reach of every player (kickable circle; the goalie's catch area), and the
// reach map when the stream carries one ("reach_map" messages, SPEC 5.4:
// which team gets first to each cell, from human motion capture).
// When the stream carries the data (frame.extras.offside = {l, r} in field
// x), it is used; otherwise the line is derived from the positions the
// stream carries (second-last defender or the ball, within the own half).
import * as THREE from 'three';
import { STATE } from '../model/playmodes.js';

export class Overlays {
  constructor(scene, field, params = {}) {
    this.field = field;
    const p = (k, d) => (Number.isFinite(params[k]) ? params[k] : d);
    // rcssserver defaults (server_param): kickable = player_size + kickable_margin.
    this.kickable = p('player_size', 0.3) + p('kickable_margin', 0.7) + p('ball_size', 0.085);
    this.catchLength = p('catchable_area_l', 1.2);
    this.catchWidth = p('catchable_area_w', 1.0);
    this.group = new THREE.Group();
    scene.add(this.group);

    const lineGeo = new THREE.PlaneGeometry(0.18, field.width);
    this.offside = [1, -1].map((side) => {
      const m = new THREE.Mesh(lineGeo, new THREE.MeshBasicMaterial({
        color: side === 1 ? 0x00e5ff : 0xff4fd8, transparent: true, opacity: 0.85, depthWrite: false }));
      m.rotation.x = -Math.PI / 2;
      m.position.y = 0.03;
      m.visible = false;
      this.group.add(m);
      return m;
    });
    this.reachGeo = new THREE.RingGeometry(this.kickable - 0.05, this.kickable, 40);
    this.catchGeo = new THREE.PlaneGeometry(this.catchLength, this.catchWidth * 2);
    this.reach = [];
    this.showOffside = false;
    this.showReach = false;
    this.showReachMap = false;
    this.reachMap = null;    // { mesh, texture, w, h, cell, x0, y0 }
    this.reachColors = null; // the colours the last map was painted with
  }

  // Run-length "l37c2r14n5" -> one letter per cell, or null when malformed.
  static decodeCells(rle, count) {
    let out = '';
    const re = /([nlrc])(\d{1,7})/gy;
    let m;
    while ((m = re.exec(rle)) !== null) {
      const n = Number(m[2]);
      if (n < 1 || out.length + n > count) return null;
      out += m[1].repeat(n);
      if (re.lastIndex === rle.length) break;
    }
    return out.length === count && re.lastIndex === rle.length ? out : null;
  }

  // A "reach_map" message: paints a translucent texture over its grid
  // (left team colour, right team colour, white where contested).
  setReachMap(msg, colors) {
    const g = msg?.grid;
    if (!g || !(g.w > 0 && g.h > 0 && g.w <= 512 && g.h <= 512 && g.cell > 0)) return false;
    const cells = Overlays.decodeCells(String(msg.cells ?? ''), g.w * g.h);
    if (!cells) return false;
    let rm = this.reachMap;
    if (!rm || rm.w !== g.w || rm.h !== g.h || rm.cell !== g.cell || rm.x0 !== g.x0 || rm.y0 !== g.y0) {
      if (rm) { this.group.remove(rm.mesh); rm.texture.dispose(); rm.mesh.geometry.dispose(); rm.mesh.material.dispose(); }
      const data = new Uint8Array(g.w * g.h * 4);
      const texture = new THREE.DataTexture(data, g.w, g.h, THREE.RGBAFormat);
      texture.magFilter = THREE.NearestFilter;
      texture.minFilter = THREE.NearestFilter;
      const mesh = new THREE.Mesh(new THREE.PlaneGeometry(g.w * g.cell, g.h * g.cell),
        new THREE.MeshBasicMaterial({ map: texture, transparent: true, depthWrite: false }));
      mesh.rotation.x = -Math.PI / 2;
      mesh.position.set(g.x0 + g.w * g.cell / 2, 0.025, g.y0 + g.h * g.cell / 2);
      this.group.add(mesh);
      rm = this.reachMap = { mesh, texture, data, w: g.w, h: g.h, cell: g.cell, x0: g.x0, y0: g.y0 };
    }
    const rgb = (c) => [Math.round(c.r * 255), Math.round(c.g * 255), Math.round(c.b * 255)];
    const paint = { l: [...rgb(colors[1]), 90], r: [...rgb(colors[-1]), 90], c: [255, 255, 255, 70], n: [0, 0, 0, 0] };
    // Texture row 0 is the plane's bottom edge, which lies at field +y.
    for (let j = 0; j < g.h; j++) {
      const row = (g.h - 1 - j) * g.w;
      for (let i = 0; i < g.w; i++) rm.data.set(paint[cells[j * g.w + i]], (row + i) * 4);
    }
    rm.texture.needsUpdate = true;
    rm.ball = msg.ball ?? null;
    return true;
  }

  _reachMesh(i) {
    if (!this.reach[i]) {
      const ring = new THREE.Mesh(this.reachGeo, new THREE.MeshBasicMaterial({
        color: 0xffffff, transparent: true, opacity: 0.55, depthWrite: false }));
      ring.rotation.x = -Math.PI / 2;
      const cat = new THREE.Mesh(this.catchGeo, new THREE.MeshBasicMaterial({
        color: 0xffffff, transparent: true, opacity: 0.25, depthWrite: false }));
      cat.rotation.x = -Math.PI / 2;
      const g = new THREE.Group();
      g.add(ring, cat);
      g.position.y = 0.035;
      this.group.add(g);
      this.reach[i] = { g, ring, cat };
    }
    return this.reach[i];
  }

  // The offside line each team's opponents must not pass: defending side
  // `side` (1 left, -1 right) -> field x, or null.
  static offsideX(players, ball, side) {
    const xs = players.filter((p) => p.side === side && p.state !== 0).map((p) => p.x);
    if (xs.length < 2) return null;
    xs.sort((a, b) => (side === 1 ? a - b : b - a));   // own goal first
    let x = xs[1];                                     // second-last defender
    if (side === 1) x = Math.min(x, ball.x, 0); else x = Math.max(x, ball.x, 0);
    return x;
  }

  update(view, colors) {
    const F = this.field;
    if (this.reachMap) this.reachMap.mesh.visible = this.showReachMap;
    for (const [k, side] of [[0, 1], [1, -1]]) {
      const line = this.offside[k];
      let x = null;
      if (this.showOffside) {
        const given = view.extras?.offside?.[side === 1 ? 'l' : 'r'];
        x = Number.isFinite(given) ? given : Overlays.offsideX(view.players, view.ball, side);
      }
      line.visible = x !== null && Math.abs(x) <= F.length / 2;
      if (line.visible) {
        line.position.x = x;
        line.material.color.copy(colors[-side]);   // drawn in the attackers' colour
      }
    }
    view.players.forEach((p, i) => {
      if (!this.showReach && !this.reach[i]) return;
      const r = this._reachMesh(i);
      r.g.visible = this.showReach && p.state !== 0;
      if (!r.g.visible) return;
      r.g.position.x = p.x;
      r.g.position.z = p.y;
      r.g.rotation.y = -p.heading * Math.PI / 180;
      r.ring.material.color.copy(colors[p.side]);
      const goalie = (p.state & STATE.GOALIE) !== 0;
      r.cat.visible = goalie;
      // The catch area extends forward from the goalie along the body.
      r.cat.position.x = this.catchLength / 2;
      r.ring.material.opacity = (p.state & STATE.KICK) ? 0.95 : 0.55;
    });
  }
}
