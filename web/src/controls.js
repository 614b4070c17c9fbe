// Buttons and keys: camera switching, overlay toggles, player choice by
// clicking, and the recording controls when the relay offers them.
import { CAMERA_MODES } from './cameras.js';

// app: { setCamera(id), toggle(name) -> bool, selectAt(ndc), cyclePlayer(dir),
//        deselect(), replay(cmd, arg) }
export function bindControls(app, canvas) {
  const bar = document.getElementById('camera-bar');
  for (const m of CAMERA_MODES) {
    const b = document.createElement('button');
    b.dataset.camera = m.id;
    b.innerHTML = `${m.label}<kbd>${m.key}</kbd>`;
    b.title = `${m.label} camera (${m.key})`;
    b.addEventListener('click', () => app.setCamera(m.id));
    bar.appendChild(b);
  }
  for (const b of document.querySelectorAll('[data-toggle]')) {
    b.addEventListener('click', () => b.classList.toggle('on', app.toggle(b.dataset.toggle)));
  }

  const keyToggles = { KeyN: 'labels', KeyO: 'offside', KeyR: 'reach', KeyT: 'reachmap', KeyM: 'sound', KeyI: 'stats' };
  window.addEventListener('keydown', (e) => {
    if (e.target.closest?.('input,select,textarea') || e.ctrlKey || e.metaKey || e.altKey) return;
    const cam = CAMERA_MODES.find((m) => m.key === e.key);
    if (cam) { app.setCamera(cam.id); return; }
    if (keyToggles[e.code] && app.cameraMode() !== 'free') {
      const name = keyToggles[e.code];
      const on = app.toggle(name);
      document.querySelector(`[data-toggle="${name}"]`)?.classList.toggle('on', on);
      return;
    }
    if (e.key === ']' || e.key === 'Tab') { e.preventDefault(); app.cyclePlayer(e.shiftKey ? -1 : 1); }
    else if (e.key === '[') app.cyclePlayer(-1);
    else if (e.key === 'Escape') app.deselect();
    else if (e.code === 'KeyP' || (e.code === 'Space' && app.cameraMode() !== 'free')) { e.preventDefault(); app.replay('toggle'); }
    else if (e.code === 'KeyG') app.replay('prev_goal');
    else if (e.code === 'KeyH') app.replay('next_goal');
    else if (e.code === 'KeyL') app.replay('live');
  });

  // A click (not a drag) on the canvas chooses the player under it.
  let down = null;
  canvas.addEventListener('pointerdown', (e) => { down = { x: e.clientX, y: e.clientY, t: performance.now() }; });
  canvas.addEventListener('pointerup', (e) => {
    if (!down) return;
    const moved = Math.hypot(e.clientX - down.x, e.clientY - down.y);
    const quick = performance.now() - down.t < 500;
    down = null;
    if (moved > 6 || !quick) return;
    const r = canvas.getBoundingClientRect();
    app.selectAt({ x: ((e.clientX - r.left) / r.width) * 2 - 1, y: -((e.clientY - r.top) / r.height) * 2 + 1 });
  });

  // Time shift / replay bar.
  const $ = (id) => document.getElementById(id);
  $('rp-play').addEventListener('click', () => app.replay('toggle'));
  $('rp-prev-goal').addEventListener('click', () => app.replay('prev_goal'));
  $('rp-next-goal').addEventListener('click', () => app.replay('next_goal'));
  $('rp-live').addEventListener('click', () => app.replay('live'));
  $('rp-speed').addEventListener('change', (e) => app.replay('speed', Number(e.target.value)));
  const seek = $('rp-seek');
  seek.addEventListener('input', () => app.replay('seek', Number(seek.value) / 1000));
  seek.addEventListener('pointerdown', () => { seek.dataset.dragging = '1'; });
  window.addEventListener('pointerup', () => { delete seek.dataset.dragging; });
}

// Shows the time-shift state: { available, active, paused, fraction, behindMs, speed }.
export function updateReplayBar(st) {
  const $ = (id) => document.getElementById(id);
  $('replay').hidden = !st.available;
  if (!st.available) return;
  const seek = $('rp-seek');
  if (!seek.dataset.dragging) seek.value = String(Math.round(st.fraction * 1000));
  const s = Math.round(st.behindMs / 1000);
  $('rp-behind').textContent = st.label ?? (st.active ? `-${Math.floor(s / 60)}:${String(s % 60).padStart(2, '0')}` : 'live');
  $('rp-play').textContent = st.active && st.paused ? 'Play' : 'Pause';
  $('rp-live').classList.toggle('live', !st.active);
  const speed = $('rp-speed');
  if (document.activeElement !== speed && Number(speed.value) !== st.speed) speed.value = String(st.speed);
}

export function markCamera(id) {
  for (const b of document.querySelectorAll('[data-camera]')) b.classList.toggle('on', b.dataset.camera === id);
}
