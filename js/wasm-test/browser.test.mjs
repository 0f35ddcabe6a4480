// The web module of the WebAssembly compiler (js/dist/doublet-web.mjs, docs/web.md "The compiler as
// WebAssembly") in headless Chromium: a page (browser/lower.html) lowers a shader at run time with
// #include answered from memory and compiles the result with WebGL2; the text and manifest must be
// what the native CLI (DOUBLET_CLI) writes. No browser here: skipped, unless DOUBLET_REQUIRE_BROWSER=1.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { jsDir, lowerNative, nativeCli, runPage } from './support.mjs';

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
  const result = runPage(t, jsDir, `wasm-test/browser/lower.html?${query}`);
  if (!result) return;
  const native = lowerNative({ 'orbit.vert': shader, 'inc/eye.glsl': header }, 'orbit.vert', ['-I', 'inc', '--target', 'webgl2']);
  assert.equal(result.ok, true);
  assert.equal(result.output, native.output);
  assert.deepEqual(result.manifest, native.manifest);
  assert.deepEqual(result.requested, [['eye.glsl', 'orbit.vert']]);
  assert.equal(result.compiled, true, `WebGL2 did not compile the lowered shader: ${result.log}`);
  console.log(`lowered in Chromium in ${result.seconds.toFixed(3)} s (first call: instantiation included)`);
});
