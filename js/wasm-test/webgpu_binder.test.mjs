// The WebGPU binder (js/src/webgpu.mjs, docs/web.md "WebGPU binder"). In headless Chromium (WebGPU
// on SwiftShader): a compute shader lowered by the native CLI (DOUBLET_CLI) with --target wgsl gets
// its uniforms only through wgslUniformBuffer; in mode exact the results must be the bits JavaScript's
// doubles give, in df64 within 2^-44 of them (hi/lo swapped or lo dropped is off by ~2^-24). In Node:
// the vertex layout and packed vertices follow the manifest's locations and the words/pairs of
// the C++ helpers' definitions. No browser: the Chromium test is skipped, unless
// DOUBLET_REQUIRE_BROWSER=1.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { exactWords, fromExactWords, join as joinPair, readBlockMember, split, writeBlockMember } from '../src/index.mjs';
import { packVertices, wgslUniformBuffer, wgslVertexLayout } from '../src/webgpu.mjs';
import { jsDir, lowerNative as lowerWith, nativeCli, runPage } from './support.mjs';

const skip = !nativeCli && 'DOUBLET_CLI is not set';

function lowerNative(source, stage, args) {
  const { output: wgsl, manifest } = lowerWith({ [`s.${stage}`]: source }, `s.${stage}`, ['--target', 'wgsl', ...args]);
  return { wgsl, manifest };
}
const kernel = `#version 450
layout(local_size_x = 1) in;
uniform double a;
uniform dvec3 v;
uniform float scale;
uniform double offset_ = 0.1lf;
uniform mat2 m;
layout(std430, binding = 0) buffer Out { double r[]; };
void main() {
  r[0] = a * v.x + v.y / v.z;
  r[1] = sqrt(a) * double(scale) + offset_;
  r[2] = v.z - a;
  r[3] = double(m[1][0]) * a;
}
`;
const values = { a: 1.0 / 3.0, v: [42164137.25, -7.0e-3, 1.1], scale: 0.75, m: [1, 2, 3.5, 4] };
// In JavaScript's doubles, as the shader computes them (float inputs widened exactly).
const expected = [values.a * values.v[0] + values.v[1] / values.v[2],
                  Math.sqrt(values.a) * Math.fround(values.scale) + 0.1,
                  values.v[2] - values.a,
                  Math.fround(values.m[2]) * values.a];

// Runs webgpu-binder.html on a lowered kernel; the storage buffer's words, or null (no browser: skipped).
function runKernel(t, data) {
  return runPage(t, jsDir, 'wasm-test/browser/webgpu-binder.html', data)?.words ?? null;
}

for (const mode of ['exact', 'df64']) {
  test(`Chromium WebGPU, mode ${mode}: uniforms through wgslUniformBuffer give the expected doubles`, { skip }, (t) => {
    const { wgsl, manifest } = lowerNative(kernel, 'comp', ['--mode', mode]);
    const words = runKernel(t, { wgsl, manifest, values, outBytes: 8 * expected.length });
    if (!words) return;
    const member = manifest.variables.find((v) => v.name === 'Out').members[0];
    expected.forEach((want, i) => {
      if (mode === 'exact') {
        assert.deepEqual([words[2 * i], words[2 * i + 1]], Array.from(exactWords(want)), `r[${i}]: ${fromExactWords(words, 2 * i)} vs ${want}`);
      } else {
        const f = new Float32Array(new Uint32Array(words).buffer);
        const base = (member.offset + i * member.array_stride) / 4;
        const got = joinPair(f[base + member.hi_offset / 4], f[base + member.lo_offset / 4]);
        assert.ok(Math.abs(got - want) <= Math.abs(want) * 2 ** -44, `r[${i}]: ${got} vs ${want}`);
      }
    });
  });
}

// Loose uniform arrays: WGSL pads an array of scalars or 2-vectors to vec4 elements (the manifest's
// array_stride 16); wgslUniformBuffer writes each element's values at its stride.
const arrayKernel = `#version 450
layout(local_size_x = 1) in;
uniform double d[3];
uniform dvec2 w[2];
uniform float f[2];
layout(std430, binding = 0) buffer Out { double r[]; };
void main() {
  for (int k = 0; k < 3; ++k) r[k] = d[k] * w[k % 2].y + double(f[k % 2]);
  r[3] = w[1].x - d[2];
}
`;
const arrayValues = { d: [1.0 / 3.0, 42164137.25, -7.0e-3], w: [0.1, 1.1, 2.0 / 7.0, -5.5], f: [0.75, -2.5] };
const arrayExpected = [0, 1, 2].map((k) => arrayValues.d[k] * arrayValues.w[2 * (k % 2) + 1] + Math.fround(arrayValues.f[k % 2]))
  .concat([arrayValues.w[2] - arrayValues.d[2]]);

for (const mode of ['exact', 'df64']) {
  test(`Chromium WebGPU, mode ${mode}: uniform arrays padded to vec4 elements give the expected doubles`, { skip }, (t) => {
    const { wgsl, manifest } = lowerNative(arrayKernel, 'comp', ['--mode', mode]);
    const block = manifest.variables.find((v) => v.layout === 'wgsl-uniform');
    const padded = block.members.find((m) => m.name === (mode === 'exact' ? 'd' : 'd_hi'));
    assert.equal(padded.array_stride, 16, JSON.stringify(padded));
    const words = runKernel(t, { wgsl, manifest, values: arrayValues, outBytes: 8 * arrayExpected.length });
    if (!words) return;
    const member = manifest.variables.find((v) => v.name === 'Out').members[0];
    arrayExpected.forEach((want, i) => {
      if (mode === 'exact') {
        assert.deepEqual([words[2 * i], words[2 * i + 1]], Array.from(exactWords(want)), `r[${i}]: ${fromExactWords(words, 2 * i)} vs ${want}`);
      } else {
        const f = new Float32Array(new Uint32Array(words).buffer);
        const base = (member.offset + i * member.array_stride) / 4;
        const got = joinPair(f[base + member.hi_offset / 4], f[base + member.lo_offset / 4]);
        assert.ok(Math.abs(got - want) <= Math.abs(want) * 2 ** -44, `r[${i}]: ${got} vs ${want}`);
      }
    });
  });
}

test('vertex layout and packed vertices follow the manifest', { skip }, () => {
  const shader = `#version 450
in float size;
layout(location = 0) in vec2 uv;
in dvec3 position;
out vec2 v_uv;
uniform dvec3 eye;
void main() { v_uv = uv * size; gl_Position = vec4(vec3(position - eye), 1.0); }
`;
  const positions = [42164137.25, 1.0 / 3.0, -2.5e-9, 6378137.0, 0.1, 7.0];
  for (const mode of ['df64', 'exact']) {
    const { wgsl, manifest } = lowerNative(shader, 'vert', ['--mode', mode]);
    const layout = wgslVertexLayout(manifest, ['position', 'uv', 'size']);
    // The locations are the ones the WGSL entry point declares.
    for (const v of manifest.variables.filter((e) => e.storage === 'in'))
      v.lowered_names.forEach((name, k) =>
        assert.match(wgsl, new RegExp(`@location\\(${v.locations[k]}\\)( @interpolate\\(flat\\))? df_in_${name}:`)));
    const formats = layout.attributes.map((a) => a.format);
    assert.deepEqual(formats, mode === 'df64' ? ['float32x3', 'float32x3', 'float32x2', 'float32']
                                              : ['uint32x4', 'uint32x2', 'float32x2', 'float32']);
    assert.deepEqual(layout.attributes.map((a) => a.offset), mode === 'df64' ? [0, 12, 24, 32] : [0, 16, 24, 32]);
    assert.equal(layout.arrayStride, 36);
    const data = packVertices(layout, { position: positions, uv: [0.5, 0.25, 1, 0], size: [2, 3] }, 2);
    const view = new DataView(data);
    for (let i = 0; i < 2; ++i) {
      const at = i * layout.arrayStride;
      for (let c = 0; c < 3; ++c) {
        const x = positions[3 * i + c];
        if (mode === 'df64') {
          assert.equal(view.getFloat32(at + 4 * c, true), split(x).hi);
          assert.equal(view.getFloat32(at + 12 + 4 * c, true), split(x).lo);
        } else {
          const w = exactWords(x);
          assert.deepEqual([view.getUint32(at + 8 * c, true), view.getUint32(at + 8 * c + 4, true)], Array.from(w));
        }
      }
      assert.equal(view.getFloat32(at + 32, true), [2, 3][i]);
    }
  }
});

test('the uniform buffer leaves the guard at 0 and refuses unknown names', { skip }, () => {
  const { manifest } = lowerNative(kernel, 'comp', ['--mode', 'df64']);
  const buffer = wgslUniformBuffer(manifest, values);
  const block = manifest.variables.find((v) => v.layout === 'wgsl-uniform');
  const guard = block.members.find((m) => m.name === 'df_guard');
  assert.equal(new DataView(buffer.data).getFloat32(guard.offset, true), 0);
  const lo = block.members.find((m) => m.name === manifest.variables.find((v) => v.name === 'offset_').lowered_names[1]);
  assert.equal(new DataView(buffer.data).getFloat32(lo.offset, true), split(0.1).lo, 'the default of offset_');
  assert.throws(() => wgslUniformBuffer(manifest, { nope: 1 }), /'nope' is not a uniform/);
});

// Storage-block members of every shape, written by writeBlockMember and read back by readBlockMember
// around a GPU that reads and writes them at the offsets it uses.
const blockKernel = `#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { dmat3 m; double arr[3]; dvec3 v[2]; dmat2x3 n; double r[]; };
void main() {
  r[0] = m[1][2] * arr[2];
  r[1] = v[1].z - n[1][0];
  r[2] = m[2][0] / v[0].y + arr[0];
  r[3] = n[0][2] - m[0][1];
}
`;
const blockValues = { m: [1 / 3, 2.5, -7, 1e-3, 5, 1 / 9, 42164137.25, 8, 9], arr: [0.1, 0.2, 1 / 7],
                      v: [1, 3.5, -2, 4, 5, 6.125], n: [1, 2, 1 / 11, -4, 5, 6] };
const blockExpected = [blockValues.m[5] * blockValues.arr[2], blockValues.v[5] - blockValues.n[3],
                       blockValues.m[6] / blockValues.v[1] + blockValues.arr[0], blockValues.n[2] - blockValues.m[1]];

for (const mode of ['exact', 'df64']) {
  test(`Chromium WebGPU, mode ${mode}: matrices and arrays of a storage block through writeBlockMember/readBlockMember`, { skip }, (t) => {
    const { wgsl, manifest } = lowerNative(blockKernel, 'comp', ['--mode', mode]);
    const members = manifest.variables.find((v) => v.name === 'B').members;
    const r = members.find((m) => m.name === 'r');
    const bytes = r.offset + 4 * r.array_stride;
    const view = new DataView(new ArrayBuffer(bytes));
    for (const [name, value] of Object.entries(blockValues)) writeBlockMember(view, members.find((m) => m.name === name), value);
    const words = runKernel(t, { wgsl, manifest, values: {}, outBytes: bytes,
                                                  storageWords: Array.from(new Uint32Array(view.buffer)) });
    if (!words) return;
    const result = new DataView(new Uint32Array(words).buffer);
    const got = readBlockMember(result, r, 0, 4);
    // The inputs come back unchanged through readBlockMember, too.
    for (const [name, value] of Object.entries(blockValues)) {
      const back = Array.from(readBlockMember(result, members.find((m) => m.name === name)));
      if (mode === 'exact') assert.deepEqual(back, value, name);
      else back.forEach((x, k) => assert.ok(Math.abs(x - value[k]) <= Math.abs(value[k]) * 2 ** -46, `${name}[${k}]`));
    }
    blockExpected.forEach((want, i) => {
      if (mode === 'exact') assert.ok(Object.is(got[i], want), `r[${i}]: ${got[i]} vs ${want}`);
      else assert.ok(Math.abs(got[i] - want) <= Math.abs(want) * 2 ** -44, `r[${i}]: ${got[i]} vs ${want}`);
    });
  });
}
