// The bundler plugin (js/src/bundler-plugin.mjs, docs/web.md "Bundler plugin") in a real Rollup build
// (npm --prefix js ci installs the pinned rollup): `import shader from './orbit.vert?doublet&target=...'`
// bundles the text and manifest the native CLI (DOUBLET_CLI) writes; a broken shader fails the build
// with the CLI's diagnostic; the #included file is watched.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import doublet from '../src/bundler-plugin.mjs';
import { lowerNative, nativeCli } from './support.mjs';

const skip = !nativeCli && 'DOUBLET_CLI is not set';

async function rollupModule() {
  try {
    return await import('rollup');
  } catch {
    assert.fail('rollup is not installed: npm --prefix js ci');
  }
}

const orbit = `#version 450
#extension GL_GOOGLE_include_directive : require
#include "kepler.glsl"
uniform dvec3 eye;
in dvec3 position;
void main() { gl_Position = vec4(vec3(position - eye) * float(mean_motion(4.2164e7lf)), 1.0); }
`;
const kepler = 'double mean_motion(double a) { return sqrt(3.986004418e14lf / (a * a * a)); }\n';

async function bundle(dir, entry) {
  const { rollup } = await rollupModule();
  writeFileSync(join(dir, 'main.js'), entry);
  const build = await rollup({ input: join(dir, 'main.js'), plugins: [doublet({ includeDirs: [join(dir, 'shaders/lib')] })] });
  const { output } = await build.generate({ format: 'es' });
  await build.close();
  return { code: output[0].code, watched: build.watchFiles };
}

test('rollup bundles what the native CLI writes', { skip }, async () => {
  const dir = mkdtempSync(join(tmpdir(), 'doublet-plugin-'));
  try {
    mkdirSync(join(dir, 'shaders/lib'), { recursive: true });
    writeFileSync(join(dir, 'shaders/orbit.vert'), orbit);
    writeFileSync(join(dir, 'shaders/lib/kepler.glsl'), kepler);
    const { code, watched } = await bundle(dir, `import webgl from './shaders/orbit.vert?doublet&target=webgl2';
import exact from './shaders/orbit.vert?doublet&target=es310&mode=exact';
export { webgl, exact };\n`);
    const bundled = await import(`data:text/javascript;base64,${Buffer.from(code).toString('base64')}`);
    for (const [shader, target, mode] of [[bundled.webgl, 'webgl2', 'df64'], [bundled.exact, 'es310', 'exact']]) {
      const want = lowerNative({ 'shaders/orbit.vert': orbit, 'shaders/lib/kepler.glsl': kepler }, 'shaders/orbit.vert',
                               ['-I', 'shaders/lib', '--target', target, '--mode', mode]);
      assert.equal(shader.code, want.output, `${target} ${mode}: text`);
      assert.deepEqual(shader.manifest, want.manifest, `${target} ${mode}: manifest`);
      assert.equal(shader.target, target);
      assert.equal(shader.mode, mode);
    }
    assert.ok(watched.some((f) => f.endsWith('shaders/lib/kepler.glsl')), `watched: ${watched}`);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('a shader that does not lower fails the build with its diagnostic', { skip }, async () => {
  const dir = mkdtempSync(join(tmpdir(), 'doublet-plugin-'));
  try {
    mkdirSync(join(dir, 'shaders/lib'), { recursive: true });
    writeFileSync(join(dir, 'shaders/broken.frag'), '#version 450\nout vec4 c;\nvoid main() { c = vec4(float(missing)); }\n');
    await assert.rejects(bundle(dir, `import s from './shaders/broken.frag?doublet&target=es300';\nexport default s;\n`),
                         /broken\.frag:3:\d+: error: undeclared identifier 'missing'/);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
