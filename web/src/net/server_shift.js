// The relay's time shift on the live game (issue 20): the page keeps only
// what it received since it joined (net/timeshift.js), so a spectator who
// joined late asks the relay for earlier moments. {"type":"timeshift",
// "action":"seek","time":CYCLE} switches this connection to a private
// replay of the channel's recording (a new hello and keyframe follow, and
// the replay bar then drives it with {"type":"replay",...}, as for a
// recording); {"type":"timeshift","action":"live"} comes back. The relay
// answers {"type":"timeshift","mode":"replay"|"live"} (with "error" when
// the channel is not recorded: the page's own history stays the fallback).
import { ServerReplay } from '../recordings.js';

export class ServerShift {
  // send(obj): a text message to the relay.
  constructor(send) {
    this.send = send;
    this.mode = 'live';          // 'live' | 'pending' | 'replay'
    this.replay = new ServerReplay('time shift', send);
    this.error = null;
    this.then = null;            // a replay command to send once the replay runs
    this.firstLive = null;       // the cycle of the first live frame this page kept
    this.liveTime = 0;           // the newest live cycle
    this.requests = 0;
  }

  get active() { return this.mode !== 'live'; }

  // A live frame the page kept (not during the shift).
  noteLive(frame) {
    if (this.firstLive === null || frame.time < this.firstLive - 50) this.firstLive = frame.time;
    this.liveTime = frame.time;
  }

  // Did the page join after `cycle`? (its own history does not reach it)
  before(cycle) { return this.firstLive !== null && cycle < this.firstLive; }

  // To the relay's recording at `cycle`, then `then` (a replay command) if given.
  enter(cycle, then = null) {
    this.send({ type: 'timeshift', action: 'seek', time: Math.max(0, Math.round(cycle)) });
    this.mode = 'pending';
    this.then = then;
    this.error = null;
    this.requests++;
  }

  // A control message; true when it belonged to the time shift.
  control(msg) {
    if (msg.type === 'timeshift') {
      this.mode = msg.mode === 'replay' ? 'replay' : 'live';
      this.error = msg.error ?? null;
      if (this.mode === 'live') { this.replay.state = null; this.then = null; }
      return true;
    }
    if (msg.type === 'replay' && this.active) {
      this.replay.status(msg);
      if (this.then) {
        const cmd = this.then;
        this.then = null;
        this.replay.command(cmd);
      }
      return true;
    }
    return false;
  }

  // The replay bar's commands while shifted; 'live' returns.
  command(cmd, arg) {
    if (cmd === 'live') this.send({ type: 'timeshift', action: 'live' });
    else this.replay.command(cmd, arg);
  }

  bar() {
    const b = this.replay.bar();
    return { ...b, label: this.replay.state ? `${b.label} · server` : 'rewinding…' };
  }

  stats() {
    return { mode: this.mode, error: this.error, firstLive: this.firstLive, requests: this.requests,
      time: this.replay.state?.time ?? null };
  }
}
