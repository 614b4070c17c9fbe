// The kick sound, synthesised with WebAudio (no audio files): a short
// filtered noise burst for the contact and a low sine thump for the body.
// Browsers start audio only after a user gesture, so the context is created
// lazily and resumed on the first click or key.

export class KickSound {
  constructor() {
    this.ctx = null;
    this.enabled = true;
    this.played = 0;
    const unlock = () => this._context()?.resume?.();
    window.addEventListener('pointerdown', unlock, { capture: true });
    window.addEventListener('keydown', unlock, { capture: true });
  }

  _context() {
    if (this.ctx) return this.ctx;
    const AC = window.AudioContext || window.webkitAudioContext;
    if (!AC) return null;
    this.ctx = new AC();
    // One second of white noise, reused by every kick.
    const n = this.ctx.sampleRate;
    this.noise = this.ctx.createBuffer(1, n, n);
    const d = this.noise.getChannelData(0);
    for (let i = 0; i < n; i++) d[i] = Math.random() * 2 - 1;
    return this.ctx;
  }

  // strength 0..1 (kick power when known); delaySec: when, from now, the
  // contact happens (0 = now).
  kick(strength = 0.7, delaySec = 0) {
    this.played++;
    if (!this.enabled) return;
    const ctx = this._context();
    if (!ctx || ctx.state !== 'running') return;
    const t0 = ctx.currentTime + Math.max(0, delaySec);
    const gain = 0.25 + 0.5 * strength;

    const src = ctx.createBufferSource();
    src.buffer = this.noise;
    const bp = ctx.createBiquadFilter();
    bp.type = 'bandpass';
    bp.frequency.value = 1400;
    bp.Q.value = 0.9;
    const ng = ctx.createGain();
    ng.gain.setValueAtTime(gain, t0);
    ng.gain.exponentialRampToValueAtTime(0.001, t0 + 0.06);
    src.connect(bp).connect(ng).connect(ctx.destination);
    src.start(t0, Math.random() * 0.5, 0.08);

    const osc = ctx.createOscillator();
    osc.type = 'sine';
    osc.frequency.setValueAtTime(160, t0);
    osc.frequency.exponentialRampToValueAtTime(60, t0 + 0.09);
    const og = ctx.createGain();
    og.gain.setValueAtTime(gain * 0.9, t0);
    og.gain.exponentialRampToValueAtTime(0.001, t0 + 0.12);
    osc.connect(og).connect(ctx.destination);
    osc.start(t0);
    osc.stop(t0 + 0.13);
  }
}
