// The HUD: scoreboard, clock, play mode, event banners, the chosen player's
// card, the stats overlay and the connection status. DOM only, no three.js.
import { playModeLabel } from './model/playmodes.js';

const $ = (id) => document.getElementById(id);

export class Hud {
  constructor() {
    this.el = {
      leftName: document.querySelector('#scoreboard .left .name'),
      rightName: document.querySelector('#scoreboard .right .name'),
      scoreL: $('score-left'), scoreR: $('score-right'), clock: $('clock'),
      mode: $('playmode'), banner: $('banner'), status: $('status'), toast: $('toast'),
      stats: $('stats'), fps: $('st-fps'), kbps: $('st-kbps'), delay: $('st-delay'),
      dropped: $('st-dropped'), card: $('player-card'), pcName: $('pc-name'),
      pcStamina: $('pc-stamina'), pcText: $('pc-stamina-text'),
    };
    this.bannerTimer = 0;
    this.toastTimer = 0;
    this.last = {};
    this.cyclesPerSecond = 10;
  }

  // teams: { left: {name, color}, right: {...} } with THREE.Color-like .getStyle() or CSS strings.
  setTeams(left, right) {
    this.el.leftName.textContent = left.name;
    this.el.rightName.textContent = right.name;
    document.documentElement.style.setProperty('--left', left.css);
    document.documentElement.style.setProperty('--right', right.css);
    this.teams = { 1: left, [-1]: right };
  }

  // Text that changes rarely is only written when it changes.
  _set(key, el, text) {
    if (this.last[key] !== text) { this.last[key] = text; el.textContent = text; }
  }

  update(f) {
    this._set('sl', this.el.scoreL, String(f.scoreLeft ?? 0));
    this._set('sr', this.el.scoreR, String(f.scoreRight ?? 0));
    // Simulation time: cycle / 10 Hz, as mm:ss (plus stoppage cycles, if any).
    const secs = Math.floor((f.time ?? 0) / this.cyclesPerSecond);
    const mm = String(Math.floor(secs / 60)).padStart(2, '0');
    const ss = String(secs % 60).padStart(2, '0');
    this._set('clock', this.el.clock, `${mm}:${ss}${f.stoppage ? ` +${f.stoppage}` : ''}`);
    this._set('mode', this.el.mode, playModeLabel(f.playMode));
  }

  // kind: 'goal' | 'card-yellow' | 'card-red' | 'foul'
  banner(text, kind, ms = 3500) {
    const b = this.el.banner;
    b.textContent = text;
    b.className = `show ${kind}`;
    clearTimeout(this.bannerTimer);
    this.bannerTimer = setTimeout(() => { b.className = kind; }, ms);
    this.lastBanner = { text, kind, at: performance.now() };
    this.recentBanners = [...(this.recentBanners ?? []).slice(-9), this.lastBanner];
  }

  // Connection state: null hides it; `lost` draws it as an alarm.
  status(text, lost = false) {
    const s = this.el.status;
    if (!text) { s.hidden = true; return; }
    s.hidden = false;
    s.textContent = text;
    s.classList.toggle('lost', lost);
  }

  // A short-lived error line (bad message, decoder error).
  toast(text, ms = 4000) {
    const t = this.el.toast;
    t.hidden = false;
    t.textContent = text;
    clearTimeout(this.toastTimer);
    this.toastTimer = setTimeout(() => { t.hidden = true; }, ms);
  }

  showStats(on) { this.el.stats.hidden = !on; }

  stats({ fps, kbps, delayMs, dropped }) {
    this._set('fps', this.el.fps, fps.toFixed(0));
    this._set('kbps', this.el.kbps, kbps.toFixed(0));
    this._set('delay', this.el.delay, Number.isFinite(delayMs) ? `${Math.round(delayMs)} ms` : '–');
    this._set('dropped', this.el.dropped, String(dropped));
  }

  // The chosen player: side, unum, goalie, stamina (NaN when the stream has none).
  player(p) {
    const c = this.el.card;
    if (!p) { c.hidden = true; return; }
    c.hidden = false;
    const team = this.teams?.[p.side];
    this._set('pcName', this.el.pcName, `#${p.unum}${p.goalie ? ' (GK)' : ''} · ${team?.name ?? ''}`);
    c.querySelector('.chip').style.background = team?.css ?? '#fff';
    const max = p.staminaMax || 8000;  // rcssserver stamina_max default
    if (Number.isFinite(p.stamina)) {
      const frac = Math.max(0, Math.min(1, p.stamina / max));
      this.el.pcStamina.style.width = `${(frac * 100).toFixed(1)}%`;
      this._set('pcText', this.el.pcText, `stamina ${Math.round(p.stamina)} / ${max}`);
    } else {
      this.el.pcStamina.style.width = '0';
      this._set('pcText', this.el.pcText, 'stamina not in this stream');
    }
  }
}
