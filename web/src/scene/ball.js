// The ball: a patterned sphere that rolls with its motion, and a soft
// shadow disc on the grass whose size and darkness tell its height.
import * as THREE from 'three';

// A little larger than rcssserver's 0.085 m so that it reads on a phone.
export const BALL_RADIUS = 0.13;

function ballTexture() {
  const c = document.createElement('canvas');
  c.width = 256; c.height = 128;
  const g = c.getContext('2d');
  g.fillStyle = '#f4f4f4';
  g.fillRect(0, 0, 256, 128);
  g.fillStyle = '#202020';
  for (let i = 0; i < 6; i++) {
    for (let r = 0; r < 3; r++) {
      g.beginPath();
      g.arc(i * 43 + (r % 2) * 21 + 10, 20 + r * 44, 11, 0, 2 * Math.PI);
      g.fill();
    }
  }
  const t = new THREE.CanvasTexture(c);
  t.colorSpace = THREE.SRGBColorSpace;
  return t;
}

function shadowTexture() {
  const c = document.createElement('canvas');
  c.width = c.height = 64;
  const g = c.getContext('2d');
  const grd = g.createRadialGradient(32, 32, 2, 32, 32, 32);
  grd.addColorStop(0, 'rgba(0,0,0,0.7)');
  grd.addColorStop(1, 'rgba(0,0,0,0)');
  g.fillStyle = grd;
  g.fillRect(0, 0, 64, 64);
  return new THREE.CanvasTexture(c);
}

export class Ball {
  constructor(scene) {
    this.mesh = new THREE.Mesh(new THREE.SphereGeometry(BALL_RADIUS, 24, 16),
      new THREE.MeshStandardMaterial({ map: ballTexture(), roughness: 0.45 }));
    this.mesh.castShadow = true;
    this.mesh.name = 'ball';
    this.shadow = new THREE.Mesh(new THREE.PlaneGeometry(1, 1),
      new THREE.MeshBasicMaterial({ map: shadowTexture(), transparent: true, depthWrite: false }));
    this.shadow.rotation.x = -Math.PI / 2;
    this.shadow.position.y = 0.02;
    scene.add(this.mesh, this.shadow);
    this.last = null;
  }

  // b: { x, y, z } in field metres; z is the height of the ball's centre
  // above the grass, or of its bottom if the stream gives 0 on the ground.
  update(b) {
    const y = Math.max(BALL_RADIUS, b.z + (b.z < BALL_RADIUS * 0.5 ? BALL_RADIUS : 0));
    const p = this.mesh.position;
    if (this.last) {
      // Roll: turn about the axis perpendicular to the motion on the grass.
      const dx = b.x - this.last.x, dz = b.y - this.last.y;
      const d = Math.hypot(dx, dz);
      if (d > 1e-4 && d < 5) {
        const axis = new THREE.Vector3(dz / d, 0, -dx / d);
        this.mesh.rotateOnWorldAxis(axis, d / BALL_RADIUS);
      }
    }
    this.last = { x: b.x, y: b.y };
    p.set(b.x, y, b.y);
    const h = y - BALL_RADIUS;
    const s = BALL_RADIUS * 2.6 * (1 + h * 0.25);
    this.shadow.scale.set(s, s, 1);
    this.shadow.position.x = b.x;
    this.shadow.position.z = b.y;
    this.shadow.material.opacity = Math.max(0.15, 1 - h * 0.12);
  }
}
