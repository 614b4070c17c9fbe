// The players' bodies (issue 20): one skinned mesh per player, generated in
// code (model/body_geometry.js from assets/body.json) and driven by the
// skeleton's joints, which the stream's angles turn. Shirts, shorts and
// socks in the kit's colours, dark boots, a few skin and hair tones, the
// number on the back, the chest and the shorts. Two levels of detail: far
// players (over 28 m from the camera) get a mesh with half the points and
// no numbers, switched by three.js LOD objects as the picture is drawn.
//
// One draw call per player and level: the regions are vertex colours of a
// single material, the positions, normals and weights shared by all players.
import * as THREE from 'three';
import { buildBodyGeometry, tonesOf } from '../model/body_geometry.js';
import { numberTexture, contrastColor } from './kit.js';

export const FAR_METRES = 28;

// The description, fetched once with the page's modules; null when it is
// missing (the page then draws the skeleton's boxes).
let spec = null;
try {
  const r = await fetch(new URL('../../assets/body.json', import.meta.url));
  if (r.ok) spec = await r.json();
} catch {
  spec = null;
}

const REGION_FALLBACK = { boot: '#161616' };

export class BodyFactory {
  // The factory for a skeleton, or null when the bodies cannot be made for
  // it (not the server's human skeleton, or no description).
  static for(skel) {
    if (!spec) return null;
    const levels = [0, 1].map((lod) => buildBodyGeometry(spec, skel, lod));
    if (levels.some((m) => !m)) return null;
    return new BodyFactory(skel, levels);
  }

  constructor(skel, levels) {
    this.skel = skel;
    this.spec = spec;
    this.levels = levels.map((m) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(m.positions, 3));
      g.setAttribute('skinIndex', new THREE.Uint16BufferAttribute(m.skinIndex, 4));
      g.setAttribute('skinWeight', new THREE.BufferAttribute(m.skinWeight, 4));
      g.setIndex(new THREE.BufferAttribute(m.index, 1));
      g.computeVertexNormals();
      return { mesh: m, geometry: g };
    });
    this.material = new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.78, metalness: 0 });
    this.decalMaterials = new Map();
    this.sphere = new THREE.Sphere(new THREE.Vector3(0, 0, 0), 1.6);
  }

  // colours: { shirt, shorts, sock } THREE.Color of the kit; returns the
  // meshes to add under the player's root, bound to `bones` (the joints, in
  // the rest pose now), and a dispose().
  make(root, bones, colours, side, unum, goalie) {
    const tones = tonesOf(this.spec, side, unum);
    const byRegion = {
      shirt: colours.shirt, shorts: colours.shorts, sock: colours.sock,
      boot: new THREE.Color(REGION_FALLBACK.boot), skin: new THREE.Color(tones.skin), hair: new THREE.Color(tones.hair),
    };
    const table = this.spec.regions.map((r) => byRegion[r] ?? colours.shirt);
    const lod = new THREE.LOD();
    lod.name = 'body';
    const geometries = [];
    const meshes = this.levels.map(({ mesh, geometry }, level) => {
      const g = new THREE.BufferGeometry();
      for (const name of ['position', 'normal', 'skinIndex', 'skinWeight']) g.setAttribute(name, geometry.getAttribute(name));
      g.setIndex(geometry.getIndex());
      const c = new Float32Array(mesh.vertexCount * 3);
      for (let i = 0; i < mesh.vertexCount; i++) {
        const col = table[mesh.region[i]];
        c[3 * i] = col.r; c[3 * i + 1] = col.g; c[3 * i + 2] = col.b;
      }
      g.setAttribute('color', new THREE.BufferAttribute(c, 3));
      geometries.push(g);
      const m = new THREE.SkinnedMesh(g, this.material);
      m.castShadow = true;
      m.frustumCulled = true;
      m.boundingSphere = this.sphere;   // any pose: the root is the pelvis
      lod.addLevel(m, level === 0 ? 0 : FAR_METRES);
      return m;
    });
    root.add(lod);
    root.updateMatrixWorld(true);
    const skeleton = new THREE.Skeleton(bones);
    for (const m of meshes) m.bind(skeleton);

    // Numbers: back, chest, shorts; near players only.
    const jointIndex = new Map(this.skel.joints.map((j, i) => [j.name, i]));
    const ink = contrastColor(colours.shirt);
    const decals = [];
    for (const n of this.spec.numbers) {
      const j = jointIndex.get(n.j);
      if (j === undefined) continue;
      const onShorts = /thigh|pelvis/.test(n.j);
      const key = `${unum}|${(onShorts ? contrastColor(colours.shorts) : ink).getHexString()}`;
      let mat = this.decalMaterials.get(key);
      if (!mat) {
        mat = new THREE.MeshBasicMaterial({ map: numberTexture(unum, onShorts ? contrastColor(colours.shorts) : ink),
          transparent: true, depthWrite: false, polygonOffset: true, polygonOffsetFactor: -2, toneMapped: false });
        this.decalMaterials.set(key, mat);
      }
      const plane = new THREE.Mesh(new THREE.PlaneGeometry(n.size, n.size), mat);
      plane.rotation.y = n.face < 0 ? -Math.PI / 2 : Math.PI / 2;
      const near = new THREE.LOD();
      near.position.fromArray(n.at);
      near.addLevel(plane, 0);
      near.addLevel(new THREE.Object3D(), FAR_METRES);
      bones[j].add(near);
      decals.push(plane);
    }
    return {
      lod, meshes, skeleton, goalie,
      dispose: () => {
        for (const g of geometries) g.dispose();
        for (const d of decals) d.geometry.dispose();
        skeleton.dispose();
      },
    };
  }
}
