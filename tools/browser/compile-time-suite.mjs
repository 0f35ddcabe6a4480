// The browser compile-time benchmark (docs/performance.md, "Compile time in the browser"): lowers the
// loop-scaling series and the corpus with the doublet CLI for webgl2 (fragment/vertex) and wgsl, in
// each mode, times each shader's compile in headless chromium (compile-time.mjs) next to the same
// shader with float in place of double, and prints a table: ms, and the ratio to the float shader.
//   node compile-time-suite.mjs --doublet build/bin/doublet [--modes df64,df64-fast,df64-int]
//        [--ops 1,2,4,8,16,32,64] [--corpus DIR,...] [--apis webgl2,webgpu] [--limit-ms 10000] [--rounds 1]
//        [--json FILE]
// Exit 0 when every shader compiled within the limit, 1 when one did not (the table says which),
// 2 when there is no browser here; with DOUBLET_REQUIRE_BROWSER=1 a missing browser is 1.
import { spawnSync } from 'child_process';
import fs from 'fs';
import os from 'os';
import path from 'path';
import { takeOption } from './session.mjs';

const here = path.dirname(new URL(import.meta.url).pathname);
const args = process.argv.slice(2);
const option = (name, fallback) => takeOption(args, name, fallback);
const doublet = option('--doublet', '');
const modes = option('--modes', 'df64,df64-fast,df64-int').split(',');
const ops = option('--ops', '1,2,4,8,16,32,64').split(',').filter((x) => x).map(Number);
const corpora = option('--corpus', '').split(',').filter((x) => x);
const apis = option('--apis', 'webgl2,webgpu').split(',');
const limitMs = option('--limit-ms', '10000');
const rounds = option('--rounds', '1');
const jsonFile = option('--json', '');
if (!doublet || args.length) {
  console.error('usage: node compile-time-suite.mjs --doublet PATH [--modes M,..] [--ops N,..] [--corpus DIR,..] [--apis webgl2,webgpu] [--limit-ms N] [--rounds N] [--json FILE]');
  process.exit(1);
}

// The loop of issue 23: N double operations (alternately s * b and s + a) in the body of a loop
// the compiler cannot unroll (its bound is a uniform).
function loopShader(n, type) {
  const body = [];
  for (let k = 0; k < n; ++k) body.push(k % 2 === 0 ? '    s = s * b;' : '    s = s + a;');
  const d = type === 'double';
  return `#version 450
// loop-scaling series: ${n} ${type} operation(s) per iteration
flat in ${d ? 'dvec2' : 'vec2'} v_ab;
uniform int steps;
layout(location = 0) out vec4 o;
void main() {
  ${type} a = v_ab.x, b = v_ab.y, s = a;
  for (int k = 0; k < steps; ++k) {
${body.join('\n')}
  }
  o = vec4(float(s), float(s - ${type}(float(s))), 0.0, 1.0);
}
`;
}

// The float shader a double shader is compared with: every double type and literal made float
// (null when that does not lower: packDouble2x32 and friends have no float twin).
const toFloat = (text) => text.replace(/\bdvec([234])\b/g, 'vec$1').replace(/\bdmat([234](x[234])?)\b/g, 'mat$1')
  .replace(/\bdouble\b/g, 'float').replace(/(\d\.?\d*(?:[eE][+-]?\d+)?)(lf|LF)\b/g, '$1');

const work = fs.mkdtempSync(path.join(os.tmpdir(), 'doublet-compile-suite-'));
const lowerErrors = new Map();  // output file -> the CLI's first error line
const lower = (source, stage, target, mode, out, includeDir) => {
  const include = includeDir ? ['-I', includeDir] : [];
  const r = spawnSync(doublet, ['lower', source, '-S', stage, '--target', target, '--mode', mode, ...include, '-o', out], { encoding: 'utf8' });
  if (r.status !== 0) lowerErrors.set(out, (r.stderr || '').split('\n').find((l) => / error: /.test(l)) || 'does not lower');
  return r.status === 0 ? out : null;
};

// Each case: a name, its stage, and the GLSL 4.50 source with doubles (and its float twin).
const cases = ops.map((n) => ({ name: `loop${n}`, stage: 'frag', source: loopShader(n, 'double'), float: loopShader(n, 'float') }));
for (const [index, corpus] of corpora.entries()) {
  // Headers of the corpus (-I corpus/include), and their float twins for the float shaders.
  const include = path.join(corpus, 'include');
  const floatInclude = path.join(work, `include${index}.float`);
  fs.mkdirSync(floatInclude);
  if (fs.existsSync(include))
    for (const h of fs.readdirSync(include))
      fs.writeFileSync(path.join(floatInclude, h), toFloat(fs.readFileSync(path.join(include, h), 'utf8')));
  for (const f of fs.readdirSync(corpus).sort()) {
    const stage = path.extname(f).slice(1);
    if (!['vert', 'frag', 'comp'].includes(stage)) continue;
    const source = fs.readFileSync(path.join(corpus, f), 'utf8');
    cases.push({ name: f, stage, source, float: toFloat(source), include, floatInclude });
  }
}

const jobs = [];  // {case, api, mode, file, floatFile}
for (const c of cases) {
  const src = path.join(work, `${c.name}.glsl`);
  const fsrc = path.join(work, `${c.name}.float.glsl`);
  fs.writeFileSync(src, c.source);
  fs.writeFileSync(fsrc, c.float);
  for (const api of apis) {
    if (api === 'webgl2' && c.stage === 'comp') continue;  // WebGL2 has no compute stage
    const target = api === 'webgl2' ? 'webgl2' : 'wgsl';
    const ext = api === 'webgl2' ? c.stage : 'wgsl';
    const floatFile = lower(fsrc, c.stage, target, 'df64', path.join(work, `${c.name}.float.${api}.${ext}`), c.floatInclude);
    for (const mode of modes) {
      const out = path.join(work, `${c.name}.${mode}.${api}.${ext}`);
      const file = lower(src, c.stage, target, mode, out, c.include);
      jobs.push({ name: c.name, api, mode, file, floatFile, lowerError: lowerErrors.get(out) });
    }
  }
}

const files = [...new Set(jobs.flatMap((j) => [j.floatFile, j.file]).filter((f) => f))];
const timed = spawnSync(process.execPath, [path.join(here, 'compile-time.mjs'), '--limit-ms', limitMs, '--rounds', rounds, ...files],
                        { encoding: 'utf8', maxBuffer: 1 << 26 });
if (timed.status === 2) {
  process.stderr.write(timed.stderr);
  process.exit(process.env.DOUBLET_REQUIRE_BROWSER === '1' ? 1 : 2);
}
const byFile = new Map();
for (const line of timed.stdout.split('\n').filter((l) => l.startsWith('{'))) {
  const r = JSON.parse(line);
  const best = byFile.get(r.file);
  // Several rounds: the fastest successful one (the usual estimate of a cost under noise).
  if (!best || (r.ok && (!best.ok || r.ms < best.ms))) byFile.set(r.file, r);
}

// A shader doublet refuses for a target (a construct the target lacks) is listed, not timed, and not
// a failure: the corpus tests check what lowers where.
let failed = 0, refused = 0;
const rows = [];
for (const j of jobs) {
  const r = j.file ? byFile.get(j.file) : { ok: false, refused: true, error: `refused: ${j.lowerError}` };
  const f = j.floatFile ? byFile.get(j.floatFile) : null;
  const ratio = r && r.ok && f && f.ok ? r.ms / f.ms : null;
  if (r.refused) ++refused;
  else if (!r.ok) ++failed;
  rows.push({ shader: j.name, api: j.api, mode: j.mode, ok: Boolean(r && r.ok), refused: Boolean(r.refused), ms: r && r.ms,
              float_ms: f && f.ok ? f.ms : null, ratio: ratio && +ratio.toFixed(2), error: r && !r.ok ? r.error : undefined });
}
console.log(`| shader | api | mode | ms | float ms | ratio |\n|---|---|---|---|---|---|`);
for (const r of rows)
  console.log(`| ${r.shader} | ${r.api} | ${r.mode} | ${r.ok ? r.ms.toFixed(0) : (r.refused ? '' : 'FAIL: ') + String(r.error).split('\n')[0].replace(work + '/', '')} | ${r.float_ms === null ? 'n/a' : r.float_ms.toFixed(0)} | ${r.ratio === null ? 'n/a' : r.ratio.toFixed(2) + 'x'} |`);
const worst = rows.filter((r) => r.ratio !== null).sort((a, b) => b.ratio - a.ratio)[0];
console.log(`shaders: ${rows.length}, refused by the target: ${refused}, compiled within ${limitMs} ms: ${rows.length - failed - refused}, failed: ${failed}, slowest: ${Math.max(...rows.filter((r) => r.ok).map((r) => r.ms)).toFixed(0)} ms` +
            (worst ? `, largest ratio to float: ${worst.ratio}x (${worst.shader}, ${worst.api}, ${worst.mode})` : ''));
if (jsonFile) fs.writeFileSync(jsonFile, JSON.stringify(rows, null, 1));
fs.rmSync(work, { recursive: true, force: true });
process.exit(failed ? 1 : 0);
