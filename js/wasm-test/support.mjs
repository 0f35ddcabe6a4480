// Shared by the tests of this folder: the native CLI to compare with (and a lowering by it), and
// pages in headless Chromium through tools/browser/run-page.mjs.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

// Absolute: the tests run it from temporary folders (npm test may be given a relative path).
export const nativeCli = process.env.DOUBLET_CLI && resolve(process.env.DOUBLET_CLI);
export const jsDir = fileURLToPath(new URL('../', import.meta.url));
const runPageScript = fileURLToPath(new URL('../../tools/browser/run-page.mjs', import.meta.url));

/**
 * Opens `page` of `dir` in headless Chromium and returns what it reports (window.doubletResult).
 * `payload`, if given, is written as JSON next to the pages of js/wasm-test/browser/ (too long for a
 * URL) and its name appended as ?payload=NAME. Without a browser the test `t` is skipped (null is
 * returned), unless DOUBLET_REQUIRE_BROWSER=1.
 */
export function runPage(t, dir, page, payload = undefined) {
  let name = null, path = null;
  if (payload !== undefined) {
    name = `.payload-${process.pid}-${Math.random().toString(36).slice(2)}.json`;
    path = join(jsDir, 'wasm-test/browser', name);
    writeFileSync(path, JSON.stringify(payload));
  }
  let r;
  try {
    const url = name ? `${page}${page.includes('?') ? '&' : '?'}payload=${name}` : page;
    r = spawnSync(process.execPath, [runPageScript, dir, '--page', url], { maxBuffer: 1 << 26 });
  } finally {
    if (path) rmSync(path, { force: true });
  }
  if (r.status === 2 && process.env.DOUBLET_REQUIRE_BROWSER !== '1') {
    t.skip(`no browser: ${r.stderr}`);
    return null;
  }
  assert.equal(r.status, 0, `run-page failed:\n${r.stderr}`);
  return JSON.parse(r.stdout.toString());
}

/**
 * Lowers `input` with the native CLI in a temporary folder holding `files` ({relative path: text}),
 * with `args` (e.g. ['--target', 'wgsl', '-I', 'inc']); asserts it succeeds and returns the lowered
 * text and the manifest it wrote.
 */
export function lowerNative(files, input, args) {
  const dir = mkdtempSync(join(tmpdir(), 'doublet-native-'));
  try {
    for (const [name, text] of Object.entries(files)) {
      mkdirSync(dirname(join(dir, name)), { recursive: true });
      writeFileSync(join(dir, name), text);
    }
    const r = spawnSync(nativeCli, ['lower', input, ...args, '-o', 'out.lowered', '--manifest', 'out.json'], { cwd: dir });
    assert.equal(r.status, 0, `doublet lower ${input} ${args.join(' ')}:\n${r.stderr}`);
    return { output: readFileSync(join(dir, 'out.lowered'), 'utf8'), manifest: JSON.parse(readFileSync(join(dir, 'out.json'), 'utf8')) };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}
