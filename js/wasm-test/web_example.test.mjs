// The example web project (examples/web/, docs/web.md "Example project"): built offline with Rollup
// and the bundler plugin (npm ci there, which scripts/install-deps runs), it renders the jitter scene
// in headless Chromium's WebGL2 through @doublet/host only; the largest frame-to-frame wobble of a
// vertex must be ≤ 0.001 px, as the native demo's. The same project built with mode fp32 (what a
// user has without doublet) must wobble by pixels: the measurement can fail. No browser: skipped,
// unless DOUBLET_REQUIRE_BROWSER=1.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { runPage } from './support.mjs';

const example = fileURLToPath(new URL('../../examples/web/', import.meta.url));

function buildAndRun(mode, t) {
  const dir = mkdtempSync(join(tmpdir(), `doublet-example-${mode}-`));
  try {
    const build = spawnSync(process.execPath, [join(example, 'node_modules/rollup/dist/bin/rollup'), '-c'],
                            { cwd: example, env: { ...process.env, DOUBLET_MODE: mode, DOUBLET_EXAMPLE_OUT: join(dir, 'dist') } });
    assert.equal(build.status, 0, `rollup -c (${mode}):\n${build.stderr}`);
    copyFileSync(join(example, 'index.html'), join(dir, 'index.html'));
    return runPage(t, dir, 'index.html');
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

test('the example project renders the jitter scene with df64 wobble ≤ 0.001 px, fp32 by pixels', (t) => {
  assert.ok(existsSync(join(example, 'node_modules/rollup')), 'examples/web has no node_modules: npm --prefix examples/web ci');
  const df64 = buildAndRun('df64', t);
  if (!df64) return;
  const fp32 = buildAndRun('fp32', t);
  assert.equal(df64.vertices, 72);
  assert.equal(df64.frames, 48);
  assert.ok(df64.wobble_px <= 0.001, `df64 wobble ${df64.wobble_px} px`);
  assert.ok(fp32.wobble_px > 1, `fp32 wobble ${fp32.wobble_px} px: the measurement would not see float jitter`);
  console.log(`wobble: df64 ${df64.wobble_px} px (largest error ${df64.max_error_px} px), fp32 ${fp32.wobble_px} px`);
});
