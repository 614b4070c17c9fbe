// The WebSocket to the relay: connects, hands text messages (JSON control
// messages) and binary messages (pose frames) to the page, and reconnects
// with exponential backoff when the feed is lost. It also notices a feed that
// is open but silent.

export class Stream {
  // handlers: { onStatus(state, info), onText(obj), onBinary(ArrayBuffer),
  //             onBadMessage(error) }
  constructor(url, handlers, { minBackoffMs = 250, maxBackoffMs = 8000, silentMs = 4000 } = {}) {
    this.url = url;
    this.h = handlers;
    this.minBackoffMs = minBackoffMs;
    this.maxBackoffMs = maxBackoffMs;
    this.silentMs = silentMs;
    this.ws = null;
    this.attempt = 0;
    this.retryTimer = 0;
    this.watchTimer = 0;
    this.lastMessageAt = 0;
    this.bytes = 0;          // received, for kbit/s
    this.connects = 0;       // successful opens
    this.stopped = false;
  }

  start() {
    this.stopped = false;
    this._connect();
    this.watchTimer = setInterval(() => this._watch(), 500);
  }

  stop() {
    this.stopped = true;
    clearTimeout(this.retryTimer);
    clearInterval(this.watchTimer);
    this.ws?.close();
  }

  send(obj) {
    if (this.ws?.readyState === WebSocket.OPEN) this.ws.send(JSON.stringify(obj));
  }

  // The hello arrived: the connection is good, the next loss starts the
  // backoff from the beginning again.
  healthy() { this.attempt = 0; }

  _connect() {
    clearTimeout(this.retryTimer);
    this.h.onStatus?.('connecting', { attempt: this.attempt });
    let ws;
    try {
      ws = new WebSocket(this.url);
    } catch (e) {
      this._retry(String(e));
      return;
    }
    ws.binaryType = 'arraybuffer';
    this.ws = ws;
    ws.onopen = () => {
      this.connects++;
      this.lastMessageAt = performance.now();
      this.h.onStatus?.('open', {});
    };
    ws.onmessage = (ev) => {
      this.lastMessageAt = performance.now();
      if (typeof ev.data === 'string') {
        this.bytes += ev.data.length;
        let msg;
        try {
          msg = JSON.parse(ev.data);
        } catch (e) {
          this.h.onBadMessage?.(`control message is not JSON: ${e.message}`);
          return;
        }
        if (!msg || typeof msg !== 'object' || typeof msg.type !== 'string') {
          this.h.onBadMessage?.('control message without a "type"');
          return;
        }
        this.h.onText?.(msg);
      } else {
        this.bytes += ev.data.byteLength;
        this.h.onBinary?.(ev.data);
      }
    };
    ws.onclose = (ev) => {
      if (this.ws !== ws) return;
      this.ws = null;
      if (!this.stopped) this._retry(ev.reason || `closed (${ev.code})`);
    };
    ws.onerror = () => { /* onclose follows and retries */ };
  }

  _retry(reason) {
    if (this.stopped) return;
    // 250 ms, 500 ms, 1 s ... 8 s, each +-20 % so clients do not reconnect in step.
    const base = Math.min(this.maxBackoffMs, this.minBackoffMs * 2 ** this.attempt);
    const delay = Math.round(base * (0.8 + 0.4 * Math.random()));
    this.attempt++;
    this.retryAt = performance.now() + delay;
    this.h.onStatus?.('lost', { reason, delay, attempt: this.attempt });
    this.retryTimer = setTimeout(() => this._connect(), delay);
  }

  // An open socket that has said nothing for a while is treated as lost.
  _watch() {
    if (!this.ws || this.ws.readyState !== WebSocket.OPEN) return;
    const quiet = performance.now() - this.lastMessageAt;
    if (quiet > this.silentMs * 2) {
      const ws = this.ws;
      this.ws = null;
      ws.close();
      this._retry('no data');
    } else if (quiet > this.silentMs) {
      this.h.onStatus?.('silent', { quietMs: quiet });
    }
  }
}
