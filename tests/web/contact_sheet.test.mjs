// The close-up contact sheet drawn by the page itself (issue 23), so that the
// shipped renderer is what gets judged: the same three moments as the
// quality tool's sheet (one sprinting player, one kick, one turn on the
// spot), every 20 Hz frame of one second, each cell the page's close-up
// camera on that player, paused on that frame.
//
// The moments come from `matchcast-anim-quality --contact-sheet` on the
// bundled game (its printed line names each row's first frame and player),
// the frames from the page as a static site playing the same game from the
// log (web/wasm/: the same animation, byte for byte). The sheet is
// test-output/anim/contact-sheet-page.png, beside the tool's
// contact-sheet.png; a person compares the two.
//
// Checked: each cell shows the frame asked for, with the player on screen
// and no page error, and the body visibly moves from cell to cell (a frozen
// picture or a camera that lost the player fails).
//
// Needs web/wasm/ (scripts/build-wasm.sh); without it the test is skipped
// (exit 77, ctest's SKIP_RETURN_CODE).
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { launchBrowser, RCG, REPO, staticServer, waitFor, WEB_DIR } from './harness.mjs';

if (!existsSync(path.join(WEB_DIR, 'wasm', 'matchcast-log.wasm'))) {
  console.log('SKIPPED: web/wasm/ not built (scripts/build-wasm.sh)');
  process.exit(77);
}
const QUALITY = process.env.MATCHCAST_ANIM_QUALITY ?? path.join(REPO, 'build', 'anim', 'tools', 'matchcast-anim-quality');
const SHEET_DIR = process.env.MATCHCAST_SHEET_DIR ?? path.join(REPO, 'test-output', 'anim');
const CELLS = 20;          // one second of 20 Hz frames
const VIEW_PX = 640;       // the page's viewport (square: the close-up's 38 deg)
const CELL_W = 240, CELL_H = 420;  // each cell: the part of the picture around the player, at full size

// The tool's rows: "sprint from seq 8905, right 10; kick from seq 44, left 6,
// contact in cell 10; turn from seq 100, right 10" -> [{ name, seq, side, unum }].
function parseRows(line) {
  const rows = [];
  for (const name of ['sprint', 'kick', 'turn']) {
    const m = new RegExp(`${name} from seq (\\d+), (left|right) (\\d+)`).exec(line);
    if (m) rows.push({ name, seq: Number(m[1]), side: m[2] === 'left' ? 1 : -1, unum: Number(m[3]) });
  }
  return rows;
}

// A clip of the page's picture. Headless Chromium's compositor now and then
// answers a capture with "Unable to capture screenshot" (stop 44's CI, on a
// 4800 px page); that is the harness, not the page, so a cell is asked for
// again, twice at most, a frame later.
async function shoot(page, clip) {
  for (let attempt = 1; ; attempt++) {
    try {
      return await page.screenshot({ type: 'png', clip });
    } catch (e) {
      if (attempt >= 3 || !/Unable to capture screenshot/.test(String(e?.message))) throw e;
      console.log(`screenshot attempt ${attempt} failed (${e.message.split('\n')[0]}); again`);
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
    }
  }
}

describe('the page draws the close-up contact sheet', { timeout: 600000 }, () => {
  let server, browser, page, errors = [], rows = [];

  before(async () => {
    assert.ok(existsSync(QUALITY), `matchcast-anim-quality not found (MATCHCAST_ANIM_QUALITY=${QUALITY})`);
    mkdirSync(SHEET_DIR, { recursive: true });
    // It exits 1 while some of issue 23's targets fail: that is its report, not an error here.
    const run = spawnSync(QUALITY, ['--contact-sheet', path.join(SHEET_DIR, 'contact-sheet.png'), RCG],
      { encoding: 'utf8', maxBuffer: 64 << 20, timeout: 120000 });
    assert.ok(run.status === 0 || run.status === 1, `matchcast-anim-quality: ${run.status} ${run.error ?? ''} ${run.stderr}`);
    const line = run.stdout.split('\n').find((l) => l.startsWith('contact sheet:')) ?? '';
    rows = parseRows(line);
    assert.equal(rows.length, 3, `the tool's contact-sheet line: ${line}`);
    server = await staticServer(WEB_DIR);
    browser = await launchBrowser();
    const ctx = await browser.newContext({ viewport: { width: VIEW_PX, height: VIEW_PX } });
    await ctx.route('**/games/**', (route) =>
      route.fulfill({ status: 200, contentType: 'application/gzip', body: readFileSync(RCG) }));
    page = await ctx.newPage();
    page.setDefaultTimeout(20000);
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`${server.url}?fixed-quality&log=games/${path.basename(RCG)}`);
  });

  after(async () => {
    await browser?.close().catch(() => {});
    server?.stop();
  });

  test('every frame of the three moments, the player in the middle of the picture', async () => {
    const done = await waitFor(page, async () => {
      const l = (await page.evaluate(() => window.matchcast?.stats().local)) ?? null;
      return l && (l.phase === 'done' || l.phase === 'failed') ? l : null;
    }, 'the whole game animated in the page', 180000, 500);
    assert.equal(done.phase, 'done', JSON.stringify(done));
    // Only the 3D picture: the HUD, the bar and the labels are hidden.
    await page.evaluate(() => {
      const canvas = document.querySelector('canvas');
      for (const el of document.body.querySelectorAll('*'))
        if (el !== canvas && !el.contains(canvas)) el.style.visibility = 'hidden';
    });
    await page.evaluate(() => window.matchcast.setCamera('closeup'));
    // The hook refuses what is not a stream position.
    for (const bad of ['12', NaN, Infinity, null, {}])
      assert.equal(await page.evaluate((b) => window.matchcast.pauseAt(b), bad), false, String(bad));

    const cells = [];   // per row: data URLs
    for (const row of rows) {
      const key = `${row.side}:${row.unum}`;
      await page.evaluate((k) => window.matchcast.select(k), key);
      const shots = [];
      let last = null;
      let moved = 0;
      for (let i = 0; i < CELLS; i++) {
        const seq = row.seq + i;
        assert.ok(await page.evaluate((s) => window.matchcast.pauseAt(s), seq), `pause at ${seq}`);
        // Two of the page's frames: the paused frame sampled, then drawn.
        const shown = await waitFor(page, () => page.evaluate(async (s) => {
          await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
          const st = window.matchcast.stats();
          return st.seq === s ? st : null;
        }, seq), `frame ${seq} on screen`, 10000, 50);
        assert.equal(shown.camera, 'closeup');
        const at = await page.evaluate((k) => window.matchcast.screenOf(k), key);
        assert.ok(at, `${row.name}: ${key} on screen at ${seq}`);
        assert.ok(at.x > VIEW_PX * 0.2 && at.x < VIEW_PX * 0.8 && at.y > VIEW_PX * 0.1 && at.y < VIEW_PX * 0.9,
          `${row.name}: ${key} in the middle of the picture at ${seq}: ${JSON.stringify(at)}`);
        // The player's chest 0.3 of the way down the cell: head, feet and the ball at them.
        const clip = {
          x: Math.max(0, Math.min(VIEW_PX - CELL_W, Math.round(at.x - CELL_W / 2))),
          y: Math.max(0, Math.min(VIEW_PX - CELL_H, Math.round(at.y - CELL_H * 0.3))),
          width: CELL_W, height: CELL_H,
        };
        const png = await shoot(page, clip);
        if (last && !png.equals(last)) moved++;
        last = png;
        shots.push(`data:image/png;base64,${png.toString('base64')}`);
      }
      // A body that runs, kicks or turns changes in (nearly) every frame.
      assert.ok(moved >= CELLS - 3, `${row.name}: the picture changed in ${moved} of ${CELLS - 1} frames`);
      cells.push({ row, shots });
    }
    assert.deepEqual(errors, []);

    // The sheet: one row per moment, 20 cells, put together on a 2D canvas in
    // a blank page and read back as a PNG. Not a full-page screenshot: a
    // 4800 px wide capture is what failed in CI ("Unable to capture
    // screenshot"), while a canvas read-back does not go through the
    // compositor at all.
    const LABEL_H = 18;
    const sheet = await browser.newPage();
    const labels = cells.map(({ row }) => `${row.name} from seq ${row.seq}, ${row.side > 0 ? 'left' : 'right'} ${row.unum}` +
      `${row.name === 'kick' ? ', contact in cell 10' : ''}`);
    const dataUrl = await sheet.evaluate(async ({ rowsOfShots, labels, W, H, L }) => {
      const canvas = document.createElement('canvas');
      canvas.width = Math.max(...rowsOfShots.map((r) => r.length)) * W;
      canvas.height = rowsOfShots.length * (H + L);
      const g = canvas.getContext('2d');
      g.fillStyle = '#fff';
      g.fillRect(0, 0, canvas.width, canvas.height);
      g.font = '12px sans-serif';
      g.textBaseline = 'middle';
      for (let r = 0; r < rowsOfShots.length; r++) {
        const top = r * (H + L);
        g.fillStyle = '#000';
        g.fillText(labels[r], 4, top + L / 2);
        for (let i = 0; i < rowsOfShots[r].length; i++) {
          const img = new Image();
          img.src = rowsOfShots[r][i];
          await img.decode();
          g.drawImage(img, i * W, top + L, W, H);
        }
      }
      return canvas.toDataURL('image/png');
    }, { rowsOfShots: cells.map((c) => c.shots), labels, W: CELL_W, H: CELL_H, L: LABEL_H });
    await sheet.close();
    const prefix = 'data:image/png;base64,';
    assert.ok(dataUrl.startsWith(prefix), `the sheet canvas read back as a PNG: ${dataUrl.slice(0, 40)}`);
    const sheetPng = Buffer.from(dataUrl.slice(prefix.length), 'base64');
    // A PNG's IHDR holds its size: room for every cell (a sheet cut short fails).
    assert.equal(sheetPng.readUInt32BE(16), CELLS * CELL_W, 'sheet width');
    assert.equal(sheetPng.readUInt32BE(20), cells.length * (CELL_H + LABEL_H), 'sheet height');
    const file = path.join(SHEET_DIR, 'contact-sheet-page.png');
    writeFileSync(file, sheetPng);
    console.log(`contact sheet drawn by the page: ${file} (${rows.map((r) => `${r.name} from seq ${r.seq}`).join('; ')})`);
  });
});
