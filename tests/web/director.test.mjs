// The director on the page (issue 20), against matchcast-server playing the
// bundled game at 2x (its first goal, HELIOS_B's at cycle 720, comes about
// 45 s in): the page starts on the director's camera, cuts at the kick-off
// and follows play without shaking; at the goal it shows the scorer, then
// the replay from two angles under a "REPLAY" mark, then catches up with
// live. A manual camera overrides the director, which comes back on
// request. The bodies up close, stereo side by side, the VR button.
// Screenshots of each shot go to $MATCHCAST_OUTPUT_DIR.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { launchBrowser, shot, startServer, stats, waitFor } from './harness.mjs';

const SPEED = 2;

describe('the director on the page', { timeout: 420000 }, () => {
  let server, browser, page;
  const errors = [];
  const director = async () => (await stats(page))?.director ?? null;
  // Named after the shot on screen when the picture is taken (a slow
  // machine may take it a moment after the state the test waited for).
  const snap = async (name) => {
    const d = await director();
    const now = (d?.replaying ? `replay-${d.angle}` : d?.shot)?.replaceAll('_', '-');
    await page.screenshot({ path: shot(`director-${name}${now && !name.includes(now) ? `-showing-${now}` : ''}`) });
  };

  // The operator's feed control (POST /control/feed/stop|start).
  const TOKEN = 'director-test';
  const feed = async (action) => {
    const r = await fetch(`${server.url}control/feed/${action}?channel=live`,
      { method: 'POST', headers: { Authorization: `Bearer ${TOKEN}` } });
    assert.equal(r.status, 200, `feed/${action}: ${await r.text()}`);
  };

  before(async () => {
    // The page is ready before the game starts, so that it sees the kick-off:
    // the feed is stopped at once, the page loads, then the game starts again.
    server = await startServer({ args: ['--speed', String(SPEED), '--loop', 'false', '--control-token', TOKEN] });
    await feed('stop');
    browser = await launchBrowser();
    page = await browser.newPage({ viewport: { width: 960, height: 540 } });
    page.on('pageerror', (e) => errors.push(e.message));
    page.setDefaultTimeout(20000);
    await page.goto(`${server.url}?fixed-quality&stats`, { timeout: 20000 });
    await waitFor(page, async () => (await stats(page))?.hello, 'the hello', 30000);
    await feed('start');
  });

  after(async () => {
    await browser?.close().catch(() => {});
    await server?.stop();
  });

  test('the director is the default, cuts at the kick-off and follows play smoothly', async () => {
    await waitFor(page, async () => (await director())?.log.length > 0, 'the first shot');
    const s = await stats(page);
    assert.equal(s.camera, 'director', 'a new spectator watches the director');
    const d0 = await director();
    // The track: a cut to the wide shot on the kick-off's first frame.
    assert.deepEqual(d0.received[0], { seq: 0, shot: 'wide', cut: true }, JSON.stringify(d0.received));
    if (d0.shot === 'wide') await snap('kickoff-wide');
    // The page shows it if it drew a picture within those 3 s (at 2x, 1.5 s:
    // a software renderer on a loaded machine may draw its first one later).
    if (d0.log[0].seq < 60) assert.equal(d0.log[0].shot, 'wide', `the page showed the kick-off wide: ${JSON.stringify(d0.log)}`);
    else console.log(`# the page's first picture came at seq ${d0.log[0].seq}, after the kick-off's wide shot`);
    // Then a cut to the play.
    const play = await waitFor(page, async () => {
      const d = await director();
      return d.log.some((e) => e.shot === 'tracking' || e.shot === 'attack') ? d : null;
    }, 'a cut to the play', 20000, 100);
    await snap(`play-${play.shot}`);
    // No cut comes sooner than ~3 s of game after the last (the first entry
    // is where the page came in: maybe a repeat of the kick-off's cut).
    for (let i = 2; i < play.log.length; i++) {
      if (play.log[i].shot === 'replay' || play.log[i - 1].shot === 'replay') continue;
      assert.ok(play.log[i].seq - play.log[i - 1].seq >= 30, `cuts too close: ${JSON.stringify(play.log)}`);
    }
    // Smooth: over 40 pictures (4 s at most) without a cut, the camera's acceleration stays
    // small (the ball's 10 Hz steps would show as spikes). Measured on the camera's own
    // clock, the time each picture moved it on: a browser stalled by a loaded machine
    // moves it on at most 0.1 s a picture, and on the wall clock that read as a jerk
    // (76 m/s² in a CI run with another test beside it; 20-40 unloaded).
    const path = await page.evaluate(() => new Promise((resolve) => {
      const out = [];
      const cuts0 = window.matchcast.stats().director.cuts;
      const step = (t) => {
        const c = window.matchcast.cameraStep();
        out.push({ t, p: c.p, dt: c.dt, cuts: window.matchcast.stats().director.cuts - cuts0 });
        if (out.length < 40 && t - out[0].t < 4000) requestAnimationFrame(step); else resolve(out);
      };
      requestAnimationFrame(step);
    }));
    const calm = path.filter((e) => e.cuts === 0);
    if (calm.length > 10) {
      let worst = 0;
      for (let i = 2; i < calm.length; i++) {
        const dt1 = calm[i].dt, dt0 = calm[i - 1].dt;
        if (dt1 <= 0 || dt0 <= 0) continue;
        for (let k = 0; k < 3; k++) {
          const v1 = (calm[i].p[k] - calm[i - 1].p[k]) / dt1, v0 = (calm[i - 1].p[k] - calm[i - 2].p[k]) / dt0;
          worst = Math.max(worst, Math.abs(v1 - v0) / ((dt1 + dt0) / 2));
        }
      }
      console.log(`# camera: ${worst.toFixed(1)} m/s² at most over ${calm.length} pictures`);
      assert.ok(worst < 60, `the camera jerks: ${worst.toFixed(1)} m/s² at most`);
    }
  });

  test('at the first goal: the scorer, the replay from two angles, then live again', async () => {
    // The director's log of shots (with the page's clock) tells the order
    // and the timing however slowly this machine draws; the screenshots are
    // taken as each shot is seen.
    const logged = (d, shot, angle) => d.log.find((e) => e.shot === shot && (!angle || e.angle === angle));
    const scorer = await waitFor(page, async () => {
      const d = await director();
      return logged(d, 'scorer') ? d : null;
    }, 'the scorer shot', 90000, 100);
    if (scorer.shot === 'scorer') await snap('goal-scorer');
    assert.match(logged(scorer, 'scorer').subject ?? '', /^-1:\d+$/, 'the scorer is HELIOS_B\'s (right, -1)');
    const seen = new Set();
    let markSeen = null;
    const d = await waitFor(page, async () => {
      const now = await director();
      if (now.replaying && !seen.has(now.angle)) {
        seen.add(now.angle);
        markSeen ??= await page.evaluate(() => {
          const m = document.getElementById('replay-mark');
          return m && !m.hidden ? { text: m.textContent, box: m.getBoundingClientRect().toJSON() } : null;
        });
        await snap(`replay-${now.angle.replace('_', '-')}`);
      }
      return logged(now, 'replay', 'low_side') && !now.replaying ? now : null;
    }, 'the replay and its end', 40000, 100);
    const i = d.log.findIndex((e) => e.shot === 'scorer');
    const order = d.log.slice(i, i + 4).map((e) => e.angle ?? e.shot);
    assert.deepEqual(order.slice(0, 3), ['scorer', 'behind_goal', 'low_side'], `the goal sequence: ${JSON.stringify(d.log)}`);
    assert.ok(order[3], 'then a live shot');
    assert.ok(markSeen, 'the REPLAY mark is shown during the replay');
    assert.equal(markSeen.text, 'REPLAY');
    assert.ok(markSeen.box.width > 20 && markSeen.box.height > 10, 'and visible');
    assert.equal(d.segments, 2);
    assert.equal(d.mark, false, 'the mark is gone after the replay');
    // Scorer 3 s + replay 12 s of game time (6 s + 3.5 s at 0.6x), paced by
    // the clock; each of the four changes is seen at the next picture, which
    // a software renderer on a loaded machine draws up to a second later.
    const slack = 4 * (1000 / Math.max(1, (await stats(page)).fps)) / 1000 * SPEED;
    const replay = (d.log[i + 3].at - d.log[i + 1].at) / 1000 * SPEED;
    const back = (d.log[i + 3].at - d.log[i].at) / 1000 * SPEED;
    assert.ok(replay > 11 && replay < 12 + slack,
      `the replay took ${replay.toFixed(2)} s of game time: ${JSON.stringify(d.log.slice(i, i + 4))}`);
    assert.ok(back < 15 + slack, `back to live ${back.toFixed(1)} s (game time) after the scorer shot`);
    await snap('after-replay');
    // Catching up: the time shift closes on live.
    await waitFor(page, async () => {
      const s = await stats(page);
      return !s.timeshift.active && s.director.phase === 'live';
    }, 'caught up with live', 30000, 200);
    const end = await director();
    assert.ok(end.replays >= 1, 'the goal was replayed (the second goal, 14 s later, may be too)');
    await snap('live-again');
  });

  test('a manual camera overrides the director, which comes back on request', async () => {
    await page.keyboard.press('1');
    await waitFor(page, async () => (await stats(page)).camera === 'broadcast', 'the broadcast camera', 5000);
    const cuts = (await director()).cuts;
    await page.waitForTimeout(3500);
    let s = await stats(page);
    assert.equal(s.camera, 'broadcast', 'the director does not take the camera back by itself');
    assert.equal(s.director.enabled, false);
    assert.ok(s.director.cuts >= cuts, 'the track is still followed, off screen');
    await page.keyboard.press('0');
    await waitFor(page, async () => (await stats(page)).camera === 'director', 'the director again (key 0)', 5000);
    assert.equal((await director()).enabled, true);
    await page.click('[data-camera="top"]');
    await waitFor(page, async () => (await stats(page)).camera === 'top', 'top-down', 5000);
    await page.click('[data-camera="director"]');
    await waitFor(page, async () => (await stats(page)).camera === 'director', 'the director again (button)', 5000);
    s = await stats(page);
    assert.ok(await page.$eval('[data-camera="director"]', (b) => b.classList.contains('on')), 'its button is lit');
    await snap('back-to-director');
    assert.deepEqual(errors, []);
  });

  test('the bodies: close-ups of players running and kicking; far players at the low level of detail', async () => {
    // The top-down view: every player is far.
    await page.keyboard.press('7');
    await waitFor(page, async () => (await stats(page)).camera === 'top', 'top-down', 5000);
    // A few pictures from up there: the levels are chosen as a picture is drawn.
    const r0 = (await stats(page)).rendered;
    await waitFor(page, async () => (await stats(page)).rendered > r0 + 2, 'pictures from above', 20000);
    const top = await waitFor(page, async () => {
      const b = (await stats(page)).bodies;
      return b && b.far + b.near === 22 && b.far >= 20 ? b : null;
    }, '22 bodies, far from the camera', 10000);
    assert.equal(top.boxes, 0, 'skinned bodies, not boxes');
    assert.ok(top.far >= 20, `far players use the low level: ${JSON.stringify(top)}`);
    // The picture's cost on a GPU: 22 bodies, the pitch, the stands and the
    // HUD's 3D parts. A mid-range laptop GPU draws millions of triangles a
    // frame at 60 frames/s; the budget here is far below that.
    const wideDraw = (await stats(page)).draw;
    console.log(`draw cost, top-down with 22 far bodies: ${JSON.stringify(wideDraw)}`);
    assert.ok(wideDraw.calls > 22 && wideDraw.calls <= 200, `draw calls: ${JSON.stringify(wideDraw)}`);
    assert.ok(wideDraw.triangles > 22 * 1000 && wideDraw.triangles <= 250000, `triangles: ${JSON.stringify(wideDraw)}`);
    // Beside the player nearest the ball, a few moments apart.
    await page.evaluate(() => window.matchcast.select(null));
    await page.keyboard.press('8');
    await waitFor(page, async () => (await stats(page)).camera === 'closeup', 'the close-up', 5000);
    for (let i = 0; i < 3; i++) {
      await page.waitForTimeout(700);
      await page.screenshot({ path: shot(`bodies-closeup-${i}`) });
    }
    const near = (await stats(page)).bodies;
    assert.ok(near.near >= 1, `the player beside the camera at the high level: ${JSON.stringify(near)}`);
    const closeDraw = (await stats(page)).draw;
    console.log(`draw cost, close-up: ${JSON.stringify(closeDraw)} with bodies ${JSON.stringify(near)}`);
    assert.ok(closeDraw.calls <= 200 && closeDraw.triangles <= 250000, `close-up draw cost: ${JSON.stringify(closeDraw)}`);
    await page.keyboard.press('0');
    assert.deepEqual(errors, []);
  });

  // Left and right halves of a screenshot, compared in the page (a 2D canvas
  // decodes the PNG): how much of each is grass, and how many pixels differ
  // between them.
  const halves = (png) => page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const w = Math.floor(img.width / 2), h = Math.floor(img.height * 0.7);   // above the controls
    const L = g.getImageData(0, 0, w, h).data, R = g.getImageData(w, 0, w, h).data;
    let grassL = 0, grassR = 0, differ = 0;
    const grass = (d, i) => d[i + 1] > 90 && d[i + 1] > d[i] * 1.2 && d[i + 1] > d[i + 2] * 1.2;
    for (let i = 0; i < L.length; i += 4) {
      if (grass(L, i)) grassL++;
      if (grass(R, i)) grassR++;
      if (Math.abs(L[i] - R[i]) + Math.abs(L[i + 1] - R[i + 1]) + Math.abs(L[i + 2] - R[i + 2]) > 30) differ++;
    }
    const n = L.length / 4;
    return { grassL: grassL / n, grassR: grassR / n, differ: differ / n };
  }, png.toString('base64'));

  test('a spectator who joins late rewinds through the relay: to a goal before he came, to the kick-off, back to live', async () => {
    const late = await browser.newPage({ viewport: { width: 640, height: 360 } });
    const lateErrors = [];
    late.on('pageerror', (e) => lateErrors.push(e.message));
    await late.goto(`${server.url}?fixed-quality&aa=0&shadows=0`);   // a second page: as light as it gets
    const s0 = await waitFor(late, async () => {
      const s = await stats(late);
      return s?.serverShift?.firstLive > 50 && s.timeshift.last > 60 ? s : null;
    }, 'live frames', 30000);
    // The previous goal is before this page's history: the relay's recording has it.
    // On a loaded machine the first page's tests run long and this one can join
    // just before the second goal; a goal in its own history is replayed from
    // that history first (web/src/main.js), and the next 'g' asks the relay for
    // the one before. (Pressed once only, that run timed out with the page on
    // its own goal.)
    const ownGoals = (await stats(late)).timeshift.goals.length;
    for (let i = 0; i <= ownGoals; i++) await late.keyboard.press('g');
    const g = await waitFor(late, async () => {
      const s = await stats(late);
      return s.serverShift.mode === 'replay' && s.serverShift.time !== null && s.serverShift.time < s0.serverShift.firstLive ? s : null;
    }, 'the relay\'s replay of an earlier goal', 30000);
    assert.ok(g.serverShift.time < s0.serverShift.firstLive,
      `at cycle ${g.serverShift.time}, before the page joined (${s0.serverShift.firstLive})`);
    await late.screenshot({ path: shot('timeshift-server-goal') });
    await late.keyboard.press('l');
    await waitFor(late, async () => (await stats(late)).serverShift.mode === 'live', 'back to live', 20000);
    // The bar's left end: the kick-off.
    await late.$eval('#rp-seek', (e) => { e.value = '0'; e.dispatchEvent(new Event('input', { bubbles: true })); });
    const k = await waitFor(late, async () => {
      const s = await stats(late);
      return s.serverShift.mode === 'replay' && s.serverShift.time !== null && s.serverShift.time < 60 ? s : null;
    }, 'the kick-off from the relay', 30000);
    assert.ok(k.serverShift.time < 60, `at cycle ${k.serverShift.time}`);
    await late.keyboard.press('l');
    await waitFor(late, async () => (await stats(late)).serverShift.mode === 'live', 'live again', 20000);
    assert.deepEqual(lateErrors, []);
    await late.close();
  });

  test('side-by-side stereo draws two views; a VR button appears where the browser offers immersive-vr', async () => {
    await page.keyboard.press('1');   // a steady camera for the comparison
    await waitFor(page, async () => (await stats(page)).camera === 'broadcast', 'broadcast', 5000);
    await page.waitForTimeout(600);
    const mono = await halves(await page.screenshot());
    await page.keyboard.press('v');
    await waitFor(page, async () => (await stats(page)).stereo.views === 2, 'two views', 5000);
    assert.equal((await stats(page)).stereo.mode, 'side-by-side');
    assert.ok(await page.$eval('[data-stereo]', (b) => b.classList.contains('on')), 'the 3D button is lit');
    await page.waitForTimeout(600);
    const png = await page.screenshot({ path: shot('stereo-side-by-side') });
    const sbs = await halves(png);
    assert.ok(sbs.grassL > 0.2 && sbs.grassR > 0.2, `both eyes see the pitch: ${JSON.stringify(sbs)}`);
    assert.ok(Math.abs(sbs.grassL - sbs.grassR) < 0.15, `the same scene in both halves: ${JSON.stringify(sbs)}`);
    assert.ok(sbs.differ > 0.002, `from two eye positions, not one picture twice: ${JSON.stringify(sbs)}`);
    assert.ok(Math.abs(mono.grassL - sbs.grassL) > 0.01 || mono.differ !== sbs.differ, 'not the mono picture');
    await page.click('[data-stereo]');
    await waitFor(page, async () => (await stats(page)).stereo.views === 1, 'one view again', 5000);
    assert.equal(await page.$eval('[data-vr="stand"]', (b) => b.hidden), true, 'no VR button without WebXR');

    // A browser that offers immersive-vr (a stand-in for navigator.xr).
    const vr = await browser.newPage({ viewport: { width: 640, height: 360 } });
    await vr.addInitScript(() => {
      window.__xrRequests = [];
      Object.defineProperty(navigator, 'xr', { configurable: true, value: {
        isSessionSupported: async (mode) => mode === 'immersive-vr',
        requestSession: async (mode, init) => { window.__xrRequests.push({ mode, init }); throw new Error('no headset here'); },
      } });
    });
    await vr.goto(`${server.url}?fixed-quality&aa=0&shadows=0`);
    await vr.waitForFunction(() => document.querySelector('[data-vr="stand"]')?.hidden === false, null, { timeout: 45000 });
    assert.equal(await vr.$eval('[data-vr="touchline"]', (b) => b.hidden), false, 'both seats offered');
    await vr.$eval('[data-vr="stand"]', (b) => b.click());   // (a software renderer this slow fails Playwright's "stable" check)
    await vr.waitForFunction(() => window.__xrRequests.length === 1, null, { timeout: 5000 });
    const req = await vr.evaluate(() => window.__xrRequests[0]);
    assert.equal(req.mode, 'immersive-vr');
    // The seats show as soon as the browser answers; the page's hook and
    // its report of the refused session can come later on a loaded machine
    // (CI saw window.matchcast still undefined here).
    await vr.waitForFunction(() => (window.matchcast?.stats().stereo.xr.error ?? '') !== '', null, { timeout: 20000 });
    const xr = await vr.evaluate(() => window.matchcast.stats().stereo.xr);
    assert.equal(xr.supported, true);
    assert.match(xr.error ?? '', /no headset/, 'a refused session is reported, the page goes on');
    await vr.close();
    assert.deepEqual(errors, []);
  });
});
