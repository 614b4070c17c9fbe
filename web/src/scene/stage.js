// The renderer, the scene, the sky and the lights. Field coordinates map to
// the Y-up scene as X = x, Z = y (rcss-protocol.md section 1), so seen from
// above with -Z up the picture is the monitor's.
import * as THREE from 'three';

// options: { antialias, shadows } (URL ?aa=0, ?shadows=0 for weak devices).
export function createStage(canvas, { antialias = true, shadows = true } = {}) {
  const renderer = new THREE.WebGLRenderer({ canvas, antialias, powerPreference: 'high-performance' });
  const maxRatio = Math.min(window.devicePixelRatio || 1, 2);
  renderer.setPixelRatio(maxRatio);
  renderer.shadowMap.enabled = shadows;
  renderer.shadowMap.type = THREE.PCFShadowMap;
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  renderer.toneMappingExposure = 1.05;

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x8fb8de);
  scene.fog = new THREE.Fog(0x8fb8de, 160, 420);

  // Sky light and ground bounce, so that shaded sides are never black.
  const hemi = new THREE.HemisphereLight(0xdfefff, 0x3c5a2a, 1.1);
  scene.add(hemi);

  // The sun: one directional light whose shadow covers the whole pitch.
  const sun = new THREE.DirectionalLight(0xfff4e0, 2.2);
  sun.position.set(-30, 70, 45);
  sun.castShadow = true;
  sun.shadow.mapSize.set(2048, 2048);
  const s = sun.shadow.camera;
  s.left = -70; s.right = 70; s.top = 50; s.bottom = -50; s.near = 10; s.far = 200;
  sun.shadow.bias = -0.0004;
  sun.shadow.normalBias = 0.02;
  scene.add(sun);
  scene.add(sun.target);

  const camera = new THREE.PerspectiveCamera(40, 1, 0.1, 800);
  camera.position.set(0, 40, 70);
  camera.lookAt(0, 0, 0);

  function resize() {
    const w = canvas.clientWidth || window.innerWidth;
    const h = canvas.clientHeight || window.innerHeight;
    if (canvas.width !== Math.floor(w * renderer.getPixelRatio()) ||
        canvas.height !== Math.floor(h * renderer.getPixelRatio())) {
      renderer.setSize(w, h, false);
    }
    camera.aspect = w / Math.max(1, h);
    camera.updateProjectionMatrix();
  }
  // Dynamic resolution: a slow GPU renders fewer pixels before it renders
  // fewer pictures. Called about once a second with the measured rate.
  let scale = 1;
  function adapt(fps) {
    const before = scale;
    if (fps < 24 && scale > 0.6) scale = Math.max(0.6, scale * 0.85);
    else if (fps > 50 && scale < 1) scale = Math.min(1, scale * 1.1);
    if (scale !== before) renderer.setPixelRatio(maxRatio * scale);
  }
  resize();
  return { renderer, scene, camera, sun, resize, adapt, get scale() { return scale; } };
}
