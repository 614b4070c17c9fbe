// Recordings kept by the relay (GET /recordings; /ws?recording=NAME opens a
// private replay that this page steers with {"type":"replay","action":...}
// and that reports {"type":"replay","time","paused","speed","first_time",
// "last_time","goals"}: server/replay/replay_player.hpp). The replay bar is
// the same as the live game's time shift; here it drives the server.

export class ServerReplay {
  constructor(name, send) {
    this.name = name;
    this.send = send;
    this.state = null;   // the last status from the server
  }

  // A status message from the server.
  status(msg) { this.state = msg; }

  command(cmd, arg) {
    const s = this.state;
    const act = (action, extra = {}) => this.send({ type: 'replay', action, ...extra });
    switch (cmd) {
      case 'toggle': act('toggle'); break;
      case 'seek':
        if (s) act('seek', { time: Math.round(s.first_time + arg * (s.last_time - s.first_time)) });
        break;
      case 'speed': act('speed', { speed: arg }); break;
      case 'prev_goal': act('prev_goal'); break;
      case 'next_goal': act('next_goal'); break;
      case 'live': location.search = ''; break;   // leave the recording for the live game
      default: break;
    }
  }

  // For updateReplayBar(): the position in the recording and its clock.
  bar() {
    const s = this.state;
    if (!s) return { available: true, active: true, paused: false, fraction: 0, behindMs: 0, speed: 1, label: this.name };
    const span = Math.max(1, s.last_time - s.first_time);
    const secs = Math.floor(s.time / 10);
    return {
      available: true, active: true, paused: !!s.paused, speed: s.speed ?? 1,
      fraction: (s.time - s.first_time) / span,
      label: `${String(Math.floor(secs / 60)).padStart(2, '0')}:${String(secs % 60).padStart(2, '0')}`,
    };
  }
}

// Fills the recordings menu from the relay; hidden when there are none.
export async function listRecordings(select, current) {
  try {
    const res = await fetch('./recordings', { cache: 'no-store' });
    if (!res.ok) return;
    const { recordings = [] } = await res.json();
    if (!recordings.length) return;
    select.hidden = false;
    for (const r of recordings) {
      const o = document.createElement('option');
      o.value = r.name;
      o.textContent = r.name.replace(/\.mcrec$/, '');
      o.selected = r.name === current;
      select.appendChild(o);
    }
    select.addEventListener('change', () => {
      location.search = select.value ? `?recording=${encodeURIComponent(select.value)}` : '';
    });
  } catch { /* no recordings offered */ }
}
