// Tests of @doublet/host (docs/web.md, "Host package (js/)"). The vectors come from
// tests/js/host_vectors.cpp, i.e. from the C++ helpers themselves; ctest -L js passes their path in
// DOUBLET_HOST_VECTORS (default: ../build/tests/js/host_vectors.json, written by ctest).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join as joinPath } from 'node:path';
import { fileURLToPath } from 'node:url';
import {
  split, splitArray, join, exactWords, exactWordsArray, fromExactWords, writeDouble, writeBlockMember,
  setUniformsFromManifest,
} from '../src/index.mjs';

const here = fileURLToPath(new URL('.', import.meta.url));
const vectorsPath = process.env.DOUBLET_HOST_VECTORS || joinPath(here, '../../build/tests/js/host_vectors.json');
const fixture = (name) => JSON.parse(readFileSync(joinPath(here, 'fixtures', name), 'utf8'));

// Bit patterns, so -0 differs from +0 and NaN equals NaN.
const f32 = new Float32Array(1);
const f32u = new Uint32Array(f32.buffer);
const f32bits = (x) => ((f32[0] = x), f32u[0]);
const bitsView = new DataView(new ArrayBuffer(8));
// The double with words [lo, hi], read without the module under test.
function fromWords([lo, hi]) {
  bitsView.setUint32(0, lo, true);
  bitsView.setUint32(4, hi, true);
  return bitsView.getFloat64(0, true);
}
const hex = (u) => '0x' + (u >>> 0).toString(16).padStart(8, '0');

test('split, splitArray, exactWords and join match the C++ helpers bit for bit', (t) => {
  if (!existsSync(vectorsPath)) {
    t.skip(`no vectors at ${vectorsPath}: run ctest -L js (or set DOUBLET_HOST_VECTORS)`);
    return;
  }
  const vectors = JSON.parse(readFileSync(vectorsPath, 'utf8')).vectors;
  assert.ok(vectors.length >= 400, `only ${vectors.length} vectors`);
  const xs = vectors.map((v) => fromWords(v.words));
  // The file must still hold the special cases this test is about.
  assert.ok(xs.some((x) => Object.is(x, -0)), 'no -0');
  assert.ok(xs.some(Number.isNaN), 'no NaN');
  assert.ok(xs.some((x) => x === -Infinity), 'no -Inf');
  assert.ok(vectors.some((v, i) => Number.isFinite(xs[i]) && v.hi === 0x7f800000), 'no finite x with hi = +Inf');
  assert.ok(vectors.some((v) => v.lo >>> 31 === 1 && (v.hi >>> 31) === 0), 'no split rounding up (lo < 0)');

  vectors.forEach((v, i) => {
    const x = xs[i];
    const what = `x = ${v.text} (words ${v.words.map(hex)})`;
    // The decimal text and the words agree (checks the vector file and fromWords).
    const parsed = { nan: NaN, inf: Infinity, '-inf': -Infinity }[v.text] ?? Number(v.text);
    assert.ok(Object.is(parsed, x), `${what}: text and words differ`);
    const p = split(x);
    assert.equal(hex(f32bits(p.hi)), hex(v.hi), `${what}: hi`);
    assert.equal(hex(f32bits(p.lo)), hex(v.lo), `${what}: lo`);
    assert.deepEqual(Array.from(exactWords(x)), v.words, `${what}: exactWords`);
    assert.deepEqual(Array.from(exactWords(fromExactWords(v.words))), v.words, `${what}: fromExactWords`);
    assert.deepEqual(Array.from(exactWords(join(p.hi, p.lo))), v.join, `${what}: join`);
  });

  const bulk = splitArray(Float64Array.from(xs));
  const bulkHi = new Uint32Array(bulk.hi.buffer);
  const bulkLo = new Uint32Array(bulk.lo.buffer);
  vectors.forEach((v, i) => {
    assert.equal(hex(bulkHi[i]), hex(v.bulk_hi), `splitArray hi of ${v.text}`);
    assert.equal(hex(bulkLo[i]), hex(v.bulk_lo), `splitArray lo of ${v.text}`);
  });
  const words = exactWordsArray(Float64Array.from(xs));
  assert.deepEqual(Array.from(words), vectors.flatMap((v) => v.words), 'exactWordsArray');
  vectors.forEach((v, i) => assert.deepEqual(Array.from(exactWords(fromExactWords(words, 2 * i))), v.words));
});

test('split and join on values known by hand', () => {
  const x = 1 + 2 ** -30; // hi = 1, lo = 2^-30, both exact
  assert.deepEqual(split(x), { hi: 1, lo: 2 ** -30 });
  assert.deepEqual(split(1 + 2 ** -24 + 2 ** -40), { hi: 1 + 2 ** -23, lo: -(2 ** -24) + 2 ** -40 });
  assert.equal(join(1, 2 ** -30), x);
  assert.ok(Object.is(join(-0, 0), -0), '(-0, +0) joins to -0');
  assert.ok(Object.is(join(0, 0), 0));
  assert.equal(join(Infinity, 0), Infinity);
  assert.deepEqual(Array.from(exactWords(1)), [0, 0x3ff00000]);
  assert.equal(fromExactWords([0, 0, 0, 0x40000000], 2), 2);
});

test('writeDouble: df_double is hi at the offset, lo 4 bytes after; exact is the words', () => {
  const x = 1 + 2 ** -30;
  const view = new DataView(new ArrayBuffer(24));
  writeDouble(view, 8, x, 'df64');
  assert.equal(view.getFloat32(8, true), 1);
  assert.equal(view.getFloat32(12, true), 2 ** -30);
  assert.equal(view.getUint32(4, true), 0, 'wrote before the offset');
  assert.equal(view.getUint32(16, true), 0, 'wrote past the pair');
  writeDouble(view, 16, x, 'exact');
  assert.equal(view.getUint32(16, true), 0x00400000, 'low word first');
  assert.equal(view.getUint32(20, true), 0x3ff00000);
  assert.equal(view.getFloat64(16, true), x);
  assert.throws(() => writeDouble(view, 0, x, 'df32'), /mode/);
});

test('writeBlockMember at the std140 offsets of a real manifest (df64 and exact)', () => {
  const x = 1 + 2 ** -30;
  const g = [x, -3 - 2 ** -40, 2 ** 100];
  // df64: `layout(std140) uniform Params { float s; df_double h; df_dvec3 g; }`, h at 16, g at 32.
  const params = fixture('uniforms.df64.json').variables.find((v) => v.name === 'Params');
  const member = (name) => params.members.find((m) => m.name === name);
  const view = new DataView(new ArrayBuffer(64));
  writeBlockMember(view, member('h'), x);
  assert.deepEqual([view.getFloat32(16, true), view.getFloat32(20, true)], [1, 2 ** -30]);
  writeBlockMember(view, member('g'), g);
  assert.deepEqual([0, 1, 2].map((c) => view.getFloat32(32 + 4 * c, true)), [1, -3, 2 ** 100], 'g hi');
  assert.deepEqual([0, 1, 2].map((c) => view.getFloat32(48 + 4 * c, true)), [2 ** -30, -(2 ** -40), 0], 'g lo');
  assert.equal(view.getUint32(0, true), 0, 's untouched');
  assert.throws(() => writeBlockMember(view, member('g'), [1, 2]), /expected 3/);
  assert.throws(() => writeBlockMember(view, member('s'), 1), /only double/);

  // exact: the original offsets (h at 8, g at 32), the doubles' words as they are.
  const exact = fixture('uniforms.exact.json').variables.find((v) => v.name === 'Params');
  const words = new DataView(new ArrayBuffer(64));
  writeBlockMember(words, exact.members.find((m) => m.name === 'h'), x, 0);
  writeBlockMember(words, exact.members.find((m) => m.name === 'g'), g, 0);
  assert.equal(words.getFloat64(8, true), x);
  assert.deepEqual([0, 1, 2].map((c) => words.getFloat64(32 + 8 * c, true)), g);
  // blockOffset moves the whole block (one buffer holding several blocks).
  const shifted = new DataView(new ArrayBuffer(320));
  writeBlockMember(shifted, exact.members.find((m) => m.name === 'h'), x, 256);
  assert.equal(shifted.getFloat64(264, true), x);
});

test('setUniformsFromManifest: df64 gives NAME_hi/NAME_lo floats, never the guard', () => {
  const m = fixture('uniforms.df64.json');
  const x = 1 + 2 ** -30;
  const u = setUniformsFromManifest(m, { scale: x, eye: [x, 2, -x], weights: [x, 0.5], zoom: 2 });
  const byName = Object.fromEntries(u.map((e) => [e.name, e]));
  // steps is listed at its initializer's value (the manifest's default); zoom's default is overridden.
  assert.deepEqual(u.map((e) => e.name), ['steps', 'scale_hi', 'scale_lo', 'eye_hi', 'eye_lo', 'weights_hi',
    'weights_lo', 'zoom_hi', 'zoom_lo']);
  assert.deepEqual(Array.from(byName.zoom_hi.data), [2]);
  assert.deepEqual(Array.from(byName.scale_hi.data), [1]);
  assert.deepEqual(Array.from(byName.scale_lo.data), [2 ** -30]);
  assert.equal(byName.scale_hi.setter, 'uniform1fv');
  assert.ok(byName.eye_hi.data instanceof Float32Array);
  assert.deepEqual(Array.from(byName.eye_hi.data), [1, 2, -1]);
  assert.deepEqual(Array.from(byName.eye_lo.data), [2 ** -30, 0, -(2 ** -30)]);
  assert.deepEqual([byName.eye_lo.type, byName.eye_lo.setter], ['vec3', 'uniform3fv']);
  assert.deepEqual([byName.weights_hi.type, byName.weights_hi.setter], ['float[2]', 'uniform1fv']);
  assert.deepEqual(Array.from(byName.weights_lo.data), [2 ** -30, 0]);
  assert.equal(m.guard.uniform, 'df_guard');
  assert.ok(!u.some((e) => e.name === 'df_guard'));
  assert.throws(() => setUniformsFromManifest(m, { eye: [1, 2] }), /expected 3/);
  assert.throws(() => setUniformsFromManifest(m, { color: [1, 2, 3, 4] }), /not a double/);
  assert.throws(() => setUniformsFromManifest(m, { nosuch: 1 }), /not a double/);
});

test('setUniformsFromManifest: uniforms declared with an initializer get the manifest default', () => {
  for (const file of ['uniforms.df64.json', 'uniforms.exact.json']) {
    const m = fixture(file);
    const u = setUniformsFromManifest(m, {});
    const byName = Object.fromEntries(u.map((e) => [e.name, e]));
    assert.deepEqual([byName.steps.setter, Array.from(byName.steps.data)], ['uniform1iv', [3]]);
    assert.ok(byName.steps.data instanceof Int32Array);
    if (file.includes('exact')) {
      assert.deepEqual(Array.from(byName.zoom.data), [0x00400000, 0x3ff00000]);  // 1 + 2^-30's words
    } else {
      assert.deepEqual(Array.from(byName.zoom_hi.data), [1]);
      assert.deepEqual(Array.from(byName.zoom_lo.data), [2 ** -30]);
    }
    assert.equal(u.length, file.includes('exact') ? 2 : 3);
  }
});

test('setUniformsFromManifest: mode exact gives the words, dvec3 as NAME_xy + NAME_z', () => {
  const m = fixture('uniforms.exact.json');
  const x = 1 + 2 ** -30;
  const u = setUniformsFromManifest(m, { scale: x, eye: [1, 2, 3], weights: [4, x] });
  const byName = Object.fromEntries(u.map((e) => [e.name, e]));
  assert.deepEqual(u.map((e) => e.name), ['steps', 'scale', 'eye_xy', 'eye_z', 'weights', 'zoom']);
  assert.deepEqual(Array.from(byName.scale.data), [0x00400000, 0x3ff00000]);
  assert.equal(byName.scale.setter, 'uniform2uiv');
  assert.ok(byName.eye_xy.data instanceof Uint32Array);
  assert.deepEqual(Array.from(byName.eye_xy.data), [0, 0x3ff00000, 0, 0x40000000]);
  assert.deepEqual([byName.eye_xy.setter, byName.eye_z.setter], ['uniform4uiv', 'uniform2uiv']);
  assert.deepEqual(Array.from(byName.eye_z.data), [0, 0x40080000]);
  assert.deepEqual(Array.from(byName.weights.data), [0, 0x40100000, 0x00400000, 0x3ff00000]);
});

test('the manifest fixtures are what the CLI writes today', (t) => {
  const cli = process.env.DOUBLET_CLI;
  if (!cli || !existsSync(cli)) {
    t.skip('DOUBLET_CLI not set (ctest -L js sets it)');
    return;
  }
  const dir = mkdtempSync(joinPath(tmpdir(), 'doublet-host-'));
  for (const [file, mode] of [['uniforms.df64.json', []], ['uniforms.exact.json', ['--mode', 'exact']]]) {
    const manifest = joinPath(dir, file);
    execFileSync(cli, ['lower', joinPath(here, 'fixtures/uniforms.frag'), '--target', 'webgl2', ...mode,
      '--manifest', manifest, '-o', joinPath(dir, 'out.frag')]);
    assert.deepEqual(JSON.parse(readFileSync(manifest, 'utf8')), fixture(file), `${file} is stale`);
  }
});
