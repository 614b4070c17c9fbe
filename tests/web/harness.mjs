// Shared helpers for the browser tests: start and stop matchcast-server,
// launch headless Debian Chromium through playwright-core, and wait for
// conditions with bounded timeouts. Every wait has a limit, every process
// started here is killed by its own handle.
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
export const REPO = process.env.MATCHCAST_REPO_ROOT ?? path.resolve(here, '../..');
export const WEB_DIR = process.env.MATCHCAST_WEB_DIR ?? path.join(REPO, 'web');
export const OUT_DIR = process.env.MATCHCAST_OUTPUT_DIR ?? path.join(REPO, 'test-output', 'web');
export const RCG = process.env.MATCHCAST_RCG ??
  path.join(REPO, 'data', '20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz');
export const SERVER = process.env.MATCHCAST_SERVER ??
  [path.join(REPO, 'build', 'server', 'app', 'matchcast-server'),
    path.join(REPO, 'build', 'server', 'matchcast-server')].find((p) => existsSync(p));
export const CHROMIUM = process.env.MATCHCAST_CHROMIUM ?? '/usr/bin/chromium';

// playwright-core is web/'s dev dependency (npm ci in web/).
const require = createRequire(path.join(WEB_DIR, 'package.json'));
export const { chromium } = require('playwright-core');

mkdirSync(OUT_DIR, { recursive: true });
export const shot = (name) => path.join(OUT_DIR, `${name}.png`);

// Starts the server; resolves { url, port, proc, stop() } once it prints its URL.
export function startServer({ port = 0, args = [], timeoutMs = 20000, web = WEB_DIR } = {}) {
  if (!SERVER || !existsSync(SERVER)) throw new Error(`matchcast-server not found (MATCHCAST_SERVER=${SERVER})`);
  const proc = spawn(SERVER, ['--rcg', RCG, '--port', String(port), '--web', web, ...args],
    // Run in the output folder: whatever the server writes (recordings) lands there.
    { stdio: ['ignore', 'pipe', 'pipe'], cwd: OUT_DIR });
  let out = '', err = '';
  proc.stderr.on('data', (d) => { err = (err + d).slice(-4000); });
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => { proc.kill('SIGKILL'); reject(new Error(`server did not start in ${timeoutMs} ms\n${err}`)); }, timeoutMs);
    proc.on('exit', (code) => { clearTimeout(timer); reject(new Error(`server exited (${code}) before it was ready\n${err}`)); });
    proc.stdout.on('data', (d) => {
      out += d;
      const m = /Matchcast: open (http:\/\/[^\s/]+:(\d+)\/)/.exec(out);
      if (!m) return;
      clearTimeout(timer);
      proc.removeAllListeners('exit');
      resolve({ url: m[1], port: Number(m[2]), proc, stop: () => stopServer(proc), stderr: () => err });
    });
  });
}

export function stopServer(proc, timeoutMs = 5000) {
  if (proc.exitCode !== null || proc.signalCode !== null) return Promise.resolve();
  return new Promise((resolve) => {
    const timer = setTimeout(() => { proc.kill('SIGKILL'); }, timeoutMs);
    proc.once('exit', () => { clearTimeout(timer); resolve(); });
    proc.kill('SIGTERM');
  });
}

// `dir` served as a static site (python3 -m http.server, no Matchcast
// server) on a free loopback port: resolves { url, stop() }.
export function staticServer(dir) {
  const proc = spawn('python3', ['-u', '-m', 'http.server', '--bind', '127.0.0.1', '-d', dir, '0'],
    { stdio: ['ignore', 'pipe', 'pipe'] });
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => { proc.kill('SIGKILL'); reject(new Error('http.server did not start')); }, 15000);
    let out = '';
    proc.stdout.on('data', (d) => {
      out += d;
      const m = /port (\d+)/.exec(out);
      if (!m) return;
      clearTimeout(timer);
      resolve({ url: `http://127.0.0.1:${m[1]}/`, stop: () => proc.kill('SIGTERM') });
    });
    proc.on('exit', (code) => { clearTimeout(timer); reject(new Error(`http.server exited ${code}`)); });
  });
}

export async function launchBrowser() {
  return chromium.launch({
    executablePath: CHROMIUM,
    timeout: 30000,
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox',
      '--disable-background-networking', '--disable-gpu-sandbox', '--autoplay-policy=no-user-gesture-required'],
  });
}

// Opens the page; collects page errors so a test can assert there were none.
export async function openPage(browser, url, { width = 1280, height = 720, query = 'fixed-quality&stats' } = {}) {
  const page = await browser.newPage({ viewport: { width, height } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.setDefaultTimeout(20000);
  await page.goto(`${url}${query ? `?${query}` : ''}`, { timeout: 20000 });
  return { page, errors };
}

export const stats = (page) => page.evaluate(() => window.matchcast?.stats() ?? null);

// Polls fn(page) until it returns a truthy value; throws after timeoutMs.
export async function waitFor(page, fn, what, timeoutMs = 20000, everyMs = 250) {
  const until = Date.now() + timeoutMs;
  let last;
  while (Date.now() < until) {
    last = await fn(page);
    if (last) return last;
    await new Promise((r) => setTimeout(r, everyMs));
  }
  throw new Error(`timed out after ${timeoutMs} ms waiting for ${what}; last stats: ${JSON.stringify(await stats(page))}`);
}
