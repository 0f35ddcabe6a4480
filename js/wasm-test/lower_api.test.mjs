// lower(source, options) of js/src/compiler.mjs (docs/web.md, "The compiler as WebAssembly") against
// the native CLI (DOUBLET_CLI): the same text and manifest for a shader with an #include answered
// by the host's callback, the same diagnostics for a broken one, and option errors as diagnostics.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { lower } from '../src/compiler.mjs';
import { lowerNative, nativeCli } from './support.mjs';

const skip = !nativeCli && 'DOUBLET_CLI is not set';

const header = `double scaled(double x) { return x * 3.0lf + 1.0lf / 3.0lf; }\n`;
const shader = `#version 450
#extension GL_GOOGLE_include_directive : require
#include "scaled.glsl"
uniform dvec3 eye;
in dvec3 position;
void main() {
  dvec3 p = position - eye;
  gl_Position = vec4(vec3(scaled(p.x), p.yz), 1.0);
}
`;

function native(dir, args) {
  const r = spawnSync(nativeCli, args, { cwd: dir, env: { ...process.env, NO_COLOR: '1' } });
  return { status: r.status, stdout: r.stdout.toString(), stderr: r.stderr.toString() };
}

test('lower() gives the native output and manifest, #include through the callback', { skip }, async () => {
  for (const [target, mode] of [['webgl2', 'df64'], ['es310', 'exact'], ['wgsl', 'df64-int']]) {
    const want = lowerNative({ 'orbit.vert': shader, 'inc/scaled.glsl': header }, 'orbit.vert',
                             ['-I', 'inc', '--target', target, '--mode', mode]);
    const requested = [];
    const result = await lower(shader, {
      fileName: 'orbit.vert', target, mode,
      include: (name, includer) => {
        requested.push([name, includer]);
        return name === 'scaled.glsl' ? { path: 'inc/scaled.glsl', contents: header } : null;
      },
    });
    assert.equal(result.ok, true, JSON.stringify(result.diagnostics));
    assert.equal(result.output, want.output, `${target} ${mode}: text`);
    assert.deepEqual(result.manifest, want.manifest, `${target} ${mode}: manifest`);
    assert.deepEqual(requested, [['scaled.glsl', 'orbit.vert']]);
    assert.deepEqual(result.includedFiles, ['inc/scaled.glsl']);
  }
});

test('lower() reports the diagnostics the CLI prints', { skip }, async () => {
  const dir = mkdtempSync(join(tmpdir(), 'doublet-api-'));
  try {
    const broken = '#version 450\nuniform double d;\nout vec4 c;\nvoid main() { c = vec4(float(d + undefinedThing)); }\n';
    writeFileSync(join(dir, 'broken.frag'), broken);
    const r = native(dir, ['lower', 'broken.frag', '--target', 'es300']);
    assert.equal(r.status, 2);
    const result = await lower(broken, { fileName: 'broken.frag', target: 'es300' });
    assert.equal(result.ok, false);
    assert.equal(result.output, '');
    assert.equal(result.diagnostics.map((d) => `${d.text}\n`).join(''), r.stderr);
    assert.ok(result.diagnostics.every((d) => d.file === 'broken.frag' && d.line === 4 && d.severity === 'error'));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('lower() refuses unknown options with a diagnostic', { skip }, async () => {
  for (const [options, message] of [[{ stage: 'vert', target: 'es999' }, /unknown target 'es999'/],
                                    [{ stage: 'vert', mode: 'df128' }, /unknown mode 'df128'/],
                                    [{ target: 'es300' }, /no stage/]]) {
    const result = await lower('#version 450\nvoid main() {}\n', options);
    assert.equal(result.ok, false);
    assert.match(result.diagnostics[0].message, message);
  }
});
