// The reach map end to end: matchcast-server --reach-overlay all, the page in
// headless Chromium; the page receives and paints reach maps, and a top-down
// screenshot with the layer on is saved (test-output/web/reach-map.png).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const harness = await import(pathToFileURL(path.resolve(import.meta.dirname, '../web/harness.mjs')).href);
const { startServer, launchBrowser, openPage, waitFor, stats, shot } = harness;

test('reach maps arrive and are drawn', { timeout: 120000 }, async () => {
  const server = await startServer({
    args: ['--reach-overlay', 'all', '--mocap-dir', process.env.MATCHCAST_MOCAP_DIR, '--mocap-cache',
      process.env.MATCHCAST_MOCAP_CACHE, '--record-dir', ''],
    timeoutMs: 60000,
  });
  const browser = await launchBrowser();
  try {
    const { page, errors } = await openPage(browser, server.url);
    await waitFor(page, async (p) => (await stats(p))?.reachMaps >= 3, 'three reach maps', 30000);
    await page.evaluate(() => { window.matchcast.setCamera('top'); window.matchcast.toggle('reachmap'); });
    await new Promise((r) => setTimeout(r, 1500));
    await page.screenshot({ path: shot('reach-map') });
    assert.deepEqual(errors, []);
  } finally {
    await browser.close();
    await server.stop();
  }
});
