// A server started before `npm ci` in web/ (no three.js in node_modules):
// the server says at start-up what the page lacks and how to get it, and the
// page shows that message instead of a blank screen.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { cpSync, mkdtempSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { WEB_DIR, launchBrowser, openPage, shot, startServer, waitFor } from './harness.mjs';

let web, server, browser;

before(async () => {
  // The page's own files, without node_modules: what a clone has before install-deps.
  web = mkdtempSync(path.join(os.tmpdir(), 'mc-web-no-three-'));
  cpSync(WEB_DIR, web, { recursive: true, filter: (src) => !src.includes(`${path.sep}node_modules`) });
  server = await startServer({ web, args: ['--record-dir', ''] });
  browser = await launchBrowser();
});

after(async () => {
  await browser?.close().catch(() => {});
  await server?.stop();
  if (web) rmSync(web, { recursive: true, force: true });
});

test('the server logs what the page is missing and how to get it', () => {
  const log = server.stderr();
  assert.match(log, /"web_page_incomplete"/);
  assert.match(log, /node_modules\/three\/build\/three\.module\.js is missing/);
  assert.match(log, /scripts\/install-deps\.sh/);
});

test('the page says why it cannot start instead of staying blank', async () => {
  const { page } = await openPage(browser, server.url);
  try {
    await waitFor(page, () => page.isVisible('#status'), 'a message on the page', 15000);
    const text = await page.textContent('#status');
    assert.match(text, /three\.js is missing/);
    assert.match(text, /install-deps/);
    await page.screenshot({ path: shot('missing-three') });
  } finally {
    await page.context().close().catch(() => {});
  }
});
