// Stereo (issue 20). Virtual RoboCup showed its games in stereo on a
// Responsive Workbench; the page offers two ways:
//  * side by side: the picture drawn twice, for the left and the right eye,
//    each in one half of the screen (a 3D TV, a phone in a cardboard
//    viewer, cross-eyed viewing). Any screen; key `V` or the "3D" button.
//  * WebXR: a "VR" button, shown only when the browser offers an
//    `immersive-vr` session, puts the spectator in a seat: high in the main
//    stand, or on the touchline at eye level. The headset moves the view.
import * as THREE from 'three';

// The stereo base: wider than a pair of eyes (6.4 cm), as stadium stereo
// cameras are, so that depth reads at 40 m.
export const EYE_SEPARATION = 0.25;

export class Stereo {
  // stage: scene/stage.js ({ renderer, scene, camera }); field: { width }.
  constructor(stage, field) {
    this.stage = stage;
    this.field = field;
    this.mode = 'off';          // 'off' | 'side-by-side'
    this.eyes = new THREE.StereoCamera();
    this.eyes.eyeSep = EYE_SEPARATION;
    this.eyes.aspect = 0.5;     // each eye gets half the width
    this.size = new THREE.Vector2();
    this.views = 1;             // views drawn in the last picture
    this.xr = { supported: false, presenting: false, seat: null, requested: 0, error: null };
    this.dolly = new THREE.Group();
    this.dolly.name = 'xr-seat';
    this.buttons = {};
    this._makeButtons();
    this._checkXR();
  }

  toggle() {
    this.mode = this.mode === 'side-by-side' ? 'off' : 'side-by-side';
    this.buttons.sbs?.classList.toggle('on', this.mode === 'side-by-side');
    return this.mode;
  }

  // Draws the picture: once, twice side by side, or for the headset.
  render() {
    const { renderer, scene, camera } = this.stage;
    if (renderer.xr.isPresenting || this.mode !== 'side-by-side') {
      renderer.render(scene, camera);
      this.views = renderer.xr.isPresenting ? 2 : 1;
      return;
    }
    camera.updateMatrixWorld();
    this.eyes.update(camera);
    renderer.getSize(this.size);
    const w = Math.floor(this.size.x / 2), h = this.size.y;
    renderer.setScissorTest(true);
    renderer.setScissor(0, 0, w, h);
    renderer.setViewport(0, 0, w, h);
    renderer.render(scene, this.eyes.cameraL);
    renderer.setScissor(w, 0, this.size.x - w, h);
    renderer.setViewport(w, 0, this.size.x - w, h);
    renderer.render(scene, this.eyes.cameraR);
    renderer.setScissorTest(false);
    renderer.setViewport(0, 0, this.size.x, this.size.y);
    this.views = 2;
  }

  stats() {
    return { mode: this.mode, views: this.views, xr: { ...this.xr } };
  }

  // --- buttons ---------------------------------------------------------------

  _makeButtons() {
    if (typeof document === 'undefined') return;
    const bar = document.getElementById('toggle-bar');
    if (!bar) return;
    const sbs = document.createElement('button');
    sbs.textContent = '3D';
    sbs.title = 'Side-by-side stereo (V)';
    sbs.dataset.stereo = 'side-by-side';
    sbs.addEventListener('click', () => this.toggle());
    bar.appendChild(sbs);
    this.buttons.sbs = sbs;
    for (const [seat, label] of [['stand', 'VR'], ['touchline', 'VR pitch-side']]) {
      const b = document.createElement('button');
      b.textContent = label;
      b.title = seat === 'stand' ? 'Watch in VR from a seat in the main stand' : 'Watch in VR from the touchline';
      b.dataset.vr = seat;
      b.hidden = true;
      b.addEventListener('click', () => this.enterVR(seat));
      bar.appendChild(b);
      this.buttons[seat] = b;
    }
    window.addEventListener('keydown', (e) => {
      if (e.code !== 'KeyV' || e.ctrlKey || e.metaKey || e.altKey || e.target.closest?.('input,select,textarea')) return;
      this.toggle();
    });
  }

  async _checkXR() {
    try {
      if (typeof navigator === 'undefined' || !navigator.xr?.isSessionSupported) return;
      this.xr.supported = !!(await navigator.xr.isSessionSupported('immersive-vr'));
    } catch {
      this.xr.supported = false;
    }
    for (const seat of ['stand', 'touchline']) if (this.buttons[seat]) this.buttons[seat].hidden = !this.xr.supported;
  }

  // --- WebXR -------------------------------------------------------------------

  // Where the spectator sits (the headset's floor origin), facing the pitch (-Z).
  seatPosition(seat) {
    const halfW = (this.field?.width ?? 68) / 2;
    return seat === 'touchline' ? new THREE.Vector3(-8, 0, halfW + 2.5) : new THREE.Vector3(0, 14, halfW + 30);
  }

  async enterVR(seat) {
    const { renderer, scene, camera } = this.stage;
    this.xr.requested++;
    try {
      const session = await navigator.xr.requestSession('immersive-vr', { optionalFeatures: ['local-floor'] });
      renderer.xr.enabled = true;
      renderer.xr.setReferenceSpaceType('local-floor');
      this.dolly.position.copy(this.seatPosition(seat));
      scene.add(this.dolly);
      this.dolly.add(camera);
      camera.position.set(0, 0, 0);
      this.xr.seat = seat;
      this.xr.presenting = true;
      session.addEventListener('end', () => {
        this.dolly.remove(camera);
        scene.remove(this.dolly);
        renderer.xr.enabled = false;
        this.xr.presenting = false;
        this.xr.seat = null;
      });
      await renderer.xr.setSession(session);
    } catch (e) {
      this.xr.error = String(e?.message ?? e);
    }
  }
}
