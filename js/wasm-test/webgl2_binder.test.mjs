// The WebGL2 binder (createWebGL2Binder, webgl2Attributes; js/src/index.mjs, docs/web.md "Host
// package") in headless Chromium's WebGL2: a vertex shader lowered by the native CLI (DOUBLET_CLI)
// with --target webgl2 gets a dvec3 attribute, a dmat3 and a double[2] uniform only through the
// package, and its flat dvec3 output is captured by transform feedback. Mode exact must give the bits
// of JavaScript's doubles, df64 within 2^-44 of them. No browser: skipped, unless
// DOUBLET_REQUIRE_BROWSER=1.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { exactWords, join as joinPair } from '../src/index.mjs';
import { jsDir, lowerNative, nativeCli, runPage } from './support.mjs';

const shader = `#version 300 es
in dvec3 p;
uniform dmat3 m;
uniform double d[2];
flat out dvec3 r;
void main() {
  r = dvec3(m[0][0] * p.x + d[1], m[1][2] - p.y, m[2][1] / p.z);
  gl_Position = vec4(0.0);
}
`;
const p = [42164137.25, 1 / 3, 1.1, -6378137.5, 0.1, -7e-3, 1e-9, 2.5, 3];
const m = [1 / 7, 2, 3, 4, 5, 6.000001, 7, 1e10 / 3, 9];
const d = [0.5, Math.PI];
const expected = [];
for (let i = 0; i < 3; ++i) expected.push(m[0] * p[3 * i] + d[1], m[5] - p[3 * i + 1], m[7] / p[3 * i + 2]);

for (const mode of ['exact', 'df64', 'df64-int']) {
  test(`Chromium WebGL2, mode ${mode}: attributes and uniforms through the binder give the expected doubles`,
       { skip: !nativeCli && 'DOUBLET_CLI is not set' }, (t) => {
    const { output: vertex, manifest } = lowerNative({ 's.vert': shader }, 's.vert', ['--target', 'webgl2', '--mode', mode]);
    const page = runPage(t, jsDir, 'wasm-test/browser/webgl2-binder.html',
                         { vertex, manifest, attributes: { p }, uniforms: { d }, matrices: { m }, output: 'r' });
    if (!page) return;
    const { captured, count } = page;
    assert.equal(count, 3);
    for (let i = 0; i < 3; ++i)
      for (let c = 0; c < 3; ++c) {
        const want = expected[3 * i + c];
        if (mode === 'exact') {
          // r_xy holds x and y's words (4 per vertex), r_z z's (2 per vertex).
          const words = c < 2 ? captured[0].slice(4 * i + 2 * c, 4 * i + 2 * c + 2) : captured[1].slice(2 * i, 2 * i + 2);
          assert.deepEqual(words, Array.from(exactWords(want)), `vertex ${i} component ${c}`);
        } else {
          const f = (k) => new Float32Array(new Uint32Array(captured[k].slice(3 * i + c, 3 * i + c + 1)).buffer)[0];
          const got = joinPair(f(0), f(1));
          assert.ok(Math.abs(got - want) <= Math.abs(want) * 2 ** -44, `vertex ${i} component ${c}: ${got} vs ${want}`);
        }
      }
  });
}

// The guard is `float df_guard[2]` on webgl2 (read at a non-constant index, docs/accuracy.md): a host
// that sets either element must be refused, element 1 (the index) as much as element 0. df64-int
// has no guard in its rules but reads the double uniforms' words through it (docs/modes.md).
for (const [mode, element] of [['df64', 'df_guard[0]'], ['df64', 'df_guard[1]'], ['df64-int', 'df_guard[0]']]) {
  test(`Chromium WebGL2, mode ${mode}: the binder refuses a program whose ${element} was set`,
       { skip: !nativeCli && 'DOUBLET_CLI is not set' }, (t) => {
    const { output: vertex, manifest } = lowerNative({ 's.vert': shader }, 's.vert', ['--target', 'webgl2', '--mode', mode]);
    assert.equal(manifest.guard.type, 'float[2]');
    const page = runPage(t, jsDir, 'wasm-test/browser/webgl2-binder.html',
                         { vertex, manifest, attributes: { p }, uniforms: { d }, matrices: { m }, output: 'r', setGuard: element });
    if (!page) return;
    assert.match(page.refused ?? '', new RegExp(`guard uniform '${element.replace(/[[\]]/g, '\\$&')}' must stay 0`));
  });
}
