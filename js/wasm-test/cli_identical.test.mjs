// The WebAssembly compiler against the native one (docs/web.md, "The compiler as WebAssembly"):
// `node js/bin/doublet.mjs lower` and the native `doublet lower` (DOUBLET_CLI) run on the same
// inputs with the same arguments must print the same bytes to stdout and stderr, exit with the same
// status and write byte-identical outputs, manifests and depfiles. Inputs: every golden case in the
// targets and modes its header names (tests/golden), the WGSL golden cases among them, the corpus
// (tests/corpus, -I include/) for every target and in modes df64, df64-int and exact, and the hostile
// cases (tests/hostile: diagnostics, include cycles, bad encodings). Cases are lowered in batches
// (`--out-dir`), one per target and option set, so that each side starts once per batch.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { nativeCli } from './support.mjs';

const root = fileURLToPath(new URL('../../', import.meta.url));
const wasmCli = join(root, 'js/bin/doublet.mjs');
const targets = ['es100', 'es300', 'es310', 'es320', 'glsl330', 'glsl450', 'webgl2', 'wgsl'];
const goldenDefaultTargets = ['es300', 'es310', 'es320', 'glsl450', 'webgl2'];

// batches: key -> { args, files: [{ name, text }] }
function goldenBatches() {
  const batches = new Map();
  const dir = join(root, 'tests/golden/cases');
  for (const file of readdirSync(dir).filter((f) => /\.(vert|frag|comp|geom|tesc|tese)$/.test(f)).sort()) {
    const lines = readFileSync(join(dir, file), 'utf8').split('\n');
    let caseTargets = goldenDefaultTargets;
    let options = [];
    // The header lines the golden harness reads (tests/golden/golden_test.cpp), then removes.
    while (lines.length > 0) {
      const t = lines[0].match(/^\s*\/\/\s*targets\s*:(.*)$/);
      const o = lines[0].match(/^\s*\/\/\s*options\s*:(.*)$/);
      if (t) caseTargets = t[1].trim().split(/\s+/);
      else if (o) options = o[1].trim().split(/\s+/);
      else break;
      lines.shift();
    }
    for (const target of caseTargets) {
      const args = ['--target', target, ...options, '-I', join(dir, 'include')];
      // A case the target refuses (its expected file is the errors) goes to a batch of its own.
      const refused = existsSync(join(root, 'tests/golden/expected', `${file}.${target}.errors`));
      const key = `${refused ? 'refused golden' : 'golden'} ${args.join(' ')}`;
      if (!batches.has(key)) batches.set(key, { args, files: [] });
      batches.get(key).files.push({ name: file, text: lines.join('\n') });
    }
  }
  return batches;
}

function folderBatch(batches, key, dir, args, filter = () => true) {
  const files = readdirSync(dir).filter((f) => /\.(vert|frag|comp)$/.test(f) && filter(f)).sort()
    .map((name) => ({ name, text: readFileSync(join(dir, name)) }));
  batches.set(key, { args, files });
}

function allBatches() {
  const batches = goldenBatches();
  const corpus = join(root, 'tests/corpus');
  const include = ['-I', join(corpus, 'include')];
  for (const target of targets) folderBatch(batches, `corpus ${target}`, corpus, ['--target', target, ...include]);
  for (const mode of ['exact', 'df64-int'])
    folderBatch(batches, `corpus es310 ${mode}`, corpus, ['--target', 'es310', '--mode', mode, ...include]);
  const hostile = join(root, 'tests/hostile/cases');
  folderBatch(batches, 'hostile', hostile, ['--target', 'es300', '-I', hostile]);
  return batches;
}

function run(command, args, cwd) {
  const r = spawnSync(command, args, { cwd, env: { ...process.env, NO_COLOR: '1' }, maxBuffer: 1 << 28 });
  return { status: r.status, signal: r.signal, stdout: r.stdout, stderr: r.stderr, error: r.error };
}

function listTree(dir) {
  const out = new Map();
  for (const entry of readdirSync(dir, { withFileTypes: true, recursive: true })) {
    if (!entry.isFile()) continue;
    const path = join(entry.parentPath ?? entry.path, entry.name);
    out.set(path.slice(dir.length + 1), readFileSync(path));
  }
  return out;
}

test('the WebAssembly CLI writes what the native CLI writes', { skip: !nativeCli && 'DOUBLET_CLI is not set' }, () => {
  assert.ok(existsSync(join(root, 'js/dist/doublet-node.cjs')), 'js/dist/ is empty: run bash scripts/build-wasm');
  const work = mkdtempSync(join(tmpdir(), 'doublet-wasm-'));
  let compared = 0, outputs = 0;
  const failingGolden = [];
  try {
    let index = 0;
    for (const [key, batch] of allBatches()) {
      // Inputs under a relative path, the same for both sides, so depfiles and diagnostics match.
      const inputs = `in${index}`;
      mkdirSync(join(work, inputs));
      for (const f of batch.files) writeFileSync(join(work, inputs, f.name), f.text);
      const names = batch.files.map((f) => `${inputs}/${f.name}`);
      const sides = {};
      for (const [side, command, prefix] of [['native', nativeCli, []], ['wasm', process.execPath, [wasmCli]]]) {
        const out = `out${index}-${side}`;
        const r = run(command, [...prefix, 'lower', ...names, '--out-dir', out, '-MD', ...batch.args], work);
        assert.equal(r.error, undefined, `${key}: ${side} did not start: ${r.error}`);
        sides[side] = { ...r, files: listTree(join(work, out)) };
      }
      const { native, wasm } = sides;
      const what = `batch "${key}" (${batch.files.length} inputs)`;
      assert.equal(wasm.signal, null, `${what}: the WebAssembly CLI was killed: ${wasm.stderr}`);
      assert.equal(wasm.status, native.status, `${what}: exit status; wasm stderr:\n${wasm.stderr}`);
      assert.equal(wasm.stdout.toString(), native.stdout.toString(), `${what}: stdout`);
      assert.equal(wasm.stderr.toString().replaceAll(`out${index}-wasm`, `out${index}-native`),
                   native.stderr.toString(), `${what}: stderr`);
      assert.deepEqual([...wasm.files.keys()].sort(), [...native.files.keys()].sort(), `${what}: files written`);
      for (const [name, bytes] of native.files) {
        const depfile = name.endsWith('.d');
        const other = depfile ? Buffer.from(wasm.files.get(name).toString().replaceAll(`out${index}-wasm`, `out${index}-native`))
                              : wasm.files.get(name);
        assert.ok(bytes.equals(other), `${what}: ${name} differs`);
        if (!name.endsWith('.json') && !depfile) outputs++;
      }
      if (key.startsWith('golden') && native.status !== 0) failingGolden.push(key);
      compared += native.files.size;
      index++;
    }
  } finally {
    rmSync(work, { recursive: true, force: true });
  }
  // The comparison means something only if the native side lowered the cases: every golden case
  // lowers but those with an expected .errors file (the corpus and hostile batches hold inputs some
  // targets refuse).
  assert.deepEqual(failingGolden, [], 'golden batches the native CLI failed');
  assert.ok(outputs >= 300, `only ${outputs} lowered shaders were compared`);
  console.log(`compared ${compared} files (${outputs} lowered shaders) across both compilers`);
});
