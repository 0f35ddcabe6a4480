// The web module of the WebAssembly compiler (js/dist/doublet-web.mjs, docs/web.md "The compiler as
// WebAssembly") in headless Chromium: a page (browser/lower.html) lowers a shader at run time with
// #include answered from memory and compiles the result with WebGL2; the text and manifest must be
// what the native CLI (DOUBLET_CLI) writes. No browser here: skipped, unless DOUBLET_REQUIRE_BROWSER=1.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve as resolvePath } from 'node:path';
import { fileURLToPath } from 'node:url';

// Absolute: the tests run it from temporary folders (npm test may be given a relative path).
const nativeCli = process.env.DOUBLET_CLI && resolvePath(process.env.DOUBLET_CLI);
const jsDir = fileURLToPath(new URL('../', import.meta.url));
const runPage = fileURLToPath(new URL('../../tools/browser/run-page.mjs', import.meta.url));

const header = 'dvec3 to_eye(dvec3 p, dvec3 eye) { return p - eye; }\n';
const shader = `#version 450
#extension GL_GOOGLE_include_directive : require
#include "eye.glsl"
uniform dvec3 eye;
uniform mat4 view_projection;
in dvec3 position;
void main() { gl_Position = view_projection * vec4(vec3(to_eye(position, eye)), 1.0); }
`;

test('doublet-web.mjs lowers in Chromium what the native CLI writes, and WebGL2 compiles it',
     { skip: !nativeCli && 'DOUBLET_CLI is not set' }, (t) => {
  const query = new URLSearchParams({ source: shader, headers: JSON.stringify({ 'eye.glsl': header }) });
  const page = spawnSync(process.execPath, [runPage, jsDir, '--page', `wasm-test/browser/lower.html?${query}`,
                                            '--timeout-ms', '120000'], { maxBuffer: 1 << 26 });
  if (page.status === 2 && process.env.DOUBLET_REQUIRE_BROWSER !== '1') {
    t.skip(`no browser: ${page.stderr}`);
    return;
  }
  assert.equal(page.status, 0, `run-page failed:\n${page.stderr}`);
  const result = JSON.parse(page.stdout.toString());
  const dir = mkdtempSync(join(tmpdir(), 'doublet-web-'));
  try {
    mkdirSync(join(dir, 'inc'));
    writeFileSync(join(dir, 'inc/eye.glsl'), header);
    writeFileSync(join(dir, 'orbit.vert'), shader);
    const r = spawnSync(nativeCli, ['lower', 'orbit.vert', '-I', 'inc', '--target', 'webgl2', '-o', 'out.glsl', '--manifest', 'out.json'], { cwd: dir });
    assert.equal(r.status, 0, r.stderr.toString());
    assert.equal(result.ok, true);
    assert.equal(result.output, readFileSync(join(dir, 'out.glsl'), 'utf8'));
    assert.deepEqual(result.manifest, JSON.parse(readFileSync(join(dir, 'out.json'), 'utf8')));
    assert.deepEqual(result.requested, [['eye.glsl', 'orbit.vert']]);
    assert.equal(result.compiled, true, `WebGL2 did not compile the lowered shader: ${result.log}`);
    console.log(`lowered in Chromium in ${result.seconds.toFixed(3)} s (first call: instantiation included)`);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
