// A clone of the repository is all a user needs: no tracked file may refer to
// a path outside it (the folder of shared data beside our own checkouts, a home
// folder, or a relative path that climbs above the repository's root).
// Runs with node's test runner; MATCHCAST_REPO_ROOT is the checkout.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync, readdirSync, statSync, lstatSync, readlinkSync } from 'node:fs';
import path from 'node:path';

const root = path.resolve(process.env.MATCHCAST_REPO_ROOT ?? path.join(import.meta.dirname, '..', '..'));

// Tracked files from git; a tarball without .git is walked instead.
function trackedFiles() {
  try {
    const out = execFileSync('git', ['-C', root, 'ls-files', '-z'], { encoding: 'utf8', maxBuffer: 64 << 20 });
    return out.split('\0').filter(Boolean);
  } catch {
    const files = [];
    const walk = (rel) => {
      for (const name of readdirSync(path.join(root, rel))) {
        if (/^(\.git|node_modules|build.*|test-output|recordings|mocap-cache)$/.test(name)) continue;
        const r = rel ? `${rel}/${name}` : name;
        if (lstatSync(path.join(root, r)).isDirectory()) walk(r); else files.push(r);
      }
    };
    walk('');
    return files;
  }
}

// Where a reference goes wrong, and why. Each rule returns the offending text.
const rules = [
  // The data and references beside our checkouts: a user's clone has none.
  { why: 'refers to the shared folder outside the repository', re: /(?:\.\.\/)+shared\b|\bshared\/(?:data|reference|hooks)\b/g },
  // The repository's root followed by "..": a path beside the checkout.
  { why: 'climbs above the repository root', re: /(?:PROJECT_SOURCE_DIR|CMAKE_SOURCE_DIR|MATCHCAST_SOURCE_DIR|MATCHCAST_REPO_ROOT|source_dir|repo_root|REPO_ROOT)\W{0,6}\/\.\.(?:\/|\b)/g },
  // Machine-specific absolute paths: ours are not a user's.
  { why: 'names a machine-specific absolute path', re: /(?<![\w.])\/(?:work|home|root|Users)\/[\w.-]+/g },
];

// A "../../x" written in a file resolves from that file's folder: it must stay inside.
const relative = /(?<![\w.\/])((?:\.\.\/)+)/g;

function isText(buf) {
  return !buf.subarray(0, 8000).includes(0);
}

test('no tracked file refers to a path outside the repository', () => {
  const files = trackedFiles();
  assert.ok(files.length > 100, `only ${files.length} files found under ${root}`);
  const problems = [];
  for (const rel of files) {
    const abs = path.join(root, rel);
    const st = lstatSync(abs, { throwIfNoEntry: false });
    if (!st) continue;
    if (st.isSymbolicLink()) {
      const target = path.resolve(path.dirname(abs), readlinkSync(abs));
      if (!target.startsWith(root + path.sep)) problems.push(`${rel}: symlink leaves the repository (${readlinkSync(abs)})`);
      continue;
    }
    if (st.size > 4 << 20) continue;
    const buf = readFileSync(abs);
    if (!isText(buf)) continue;
    const lines = buf.toString('utf8').split('\n');
    lines.forEach((line, i) => {
      for (const { why, re } of rules) {
        for (const m of line.matchAll(re)) problems.push(`${rel}:${i + 1}: ${why}: ${m[0]}`);
      }
      for (const m of line.matchAll(relative)) {
        const depth = m[1].length / 3;
        const from = path.dirname(rel).split('/').filter((p) => p && p !== '.').length;
        if (depth > from) problems.push(`${rel}:${i + 1}: climbs ${depth} folders from a file ${from} deep: ${line.trim().slice(0, 120)}`);
      }
    });
  }
  assert.deepEqual(problems, [], `\n${problems.join('\n')}`);
});

test('the checker sees what it must refuse', () => {
  // The rules themselves, on lines that must fail and lines that must pass.
  // Built from pieces, so that this file does not refuse itself.
  const up = '..' + '/';
  const bad = [`dir = "\${PROJECT_SOURCE_DIR}/${up}sha` + 'red/data/mocap"', 'see /' + 'work/main/x', `source_dir + "/${up}other"`];
  for (const line of bad) {
    assert.ok(rules.some(({ re }) => [...line.matchAll(re)].length > 0), `not refused: ${line}`);
  }
  const good = ['dir = "${PROJECT_SOURCE_DIR}/data/mocap"', '#include "../proto/x.hpp"', 'a shared frame'];
  for (const line of good) {
    assert.ok(!rules.some(({ re }) => [...line.matchAll(re)].length > 0), `refused: ${line}`);
  }
});
