// Gunzips a byte stream with the browser's DecompressionStream without
// losing what comes before a cut.
//
// A gzip stream cut short makes the decompressor fail when its input ends,
// and the Streams standard then discards whatever output it still had
// queued. With `raw.pipeThrough(new DecompressionStream('gzip'))` how much
// that is depends on how far the pipe ran ahead of the reader: a cut log
// played 276 frames on a busy machine and over 1,000 on a quiet one. So
// here the raw bytes are written in by hand, as the reader needs them; the
// output is taken out as soon as it is made, into a queue of our own; and
// the input is closed (which is when a cut shows) only after everything the
// written bytes made has been taken. A cut then costs nothing but the bytes
// after it; read() throws only once the queue is empty.

const tick = () => new Promise((resolve) => setTimeout(resolve, 0));

// rawReader: a ReadableStreamDefaultReader of the compressed bytes, whose
// first chunk `head` has been read already (it told gzip from plain);
// onRaw(n): called with the size of each compressed chunk taken.
// Returns { read(): Promise<{ value, done }>, cancel() }, like a reader.
export function gunzipReader(rawReader, head, onRaw = () => {}) {
  const ds = new DecompressionStream('gzip');
  const writer = ds.writable.getWriter();
  const out = ds.readable.getReader();
  const queue = [];
  let failure = null, finished = false, rawDone = false, closed = false, wake = null;
  const signal = () => { const w = wake; wake = null; w?.(); };
  // Takes every output chunk the moment it is made: nothing waits in the
  // decompressor's own queue when it fails.
  (async () => {
    try {
      for (;;) {
        const { value, done } = await out.read();
        if (done) break;
        queue.push(value);
        signal();
      }
    } catch (err) {
      failure = err;
    }
    finished = true;
    signal();
  })();
  // The writer's errors show through the output (a cut) or are not ours.
  const write = (chunk) => writer.write(chunk).catch(() => {});
  let pendingHead = head?.length ? head : null;

  async function feed() {
    if (pendingHead) {
      const h = pendingHead;
      pendingHead = null;
      onRaw(h.length);
      await write(h);
      return;
    }
    const { value, done } = await rawReader.read();
    if (done) { rawDone = true; return; }
    onRaw(value.length);
    await write(value);  // resolves once its output was handed on
  }

  return {
    async read() {
      for (;;) {
        if (queue.length) return { value: queue.shift(), done: false };
        if (finished) {
          if (failure) throw failure;
          return { value: undefined, done: true };
        }
        if (!rawDone) {
          await feed();
          continue;
        }
        if (!closed) {
          // Let the loop above take the last written bytes' output (a
          // macrotask runs after all pending promise reactions), then end
          // the input: a complete stream closes, a cut one fails.
          await tick();
          if (queue.length) continue;
          closed = true;
          writer.close().catch(() => {});
          continue;
        }
        await new Promise((resolve) => { wake = resolve; });
      }
    },
    cancel(reason) {
      writer.abort(reason).catch(() => {});
      return rawReader.cancel(reason);
    },
  };
}
