// The browser run-time benchmark against luma.gl (issue 23; docs/performance.md, "Speed in the browser
// against luma.gl"): issue 23's straight-line and loop kernels (tests/browser-speed/*.frag) lowered by
// the doublet CLI for webgl2 in each mode, the same kernels written by hand on luma.gl's fp64 module
// (tests/browser-speed/*.luma.frag, the library from npm via tools/peers/luma-fp64.mjs) and the float
// twin (doublet --mode fp32), each run per pixel of a size x size framebuffer in headless chromium's
// WebGL2, timed in interleaved rounds (speed-page.mjs), and their outputs compared with the kernels in
// JavaScript doubles. With --apis ...,webgpu the same in Chromium's WebGPU: the kernels as compute
// shaders (tests/browser-speed/*.comp lowered --target wgsl, one invocation per element of size x
// size, doubles in storage buffers), luma.gl's peer written on its WGSL fp64 arithmetic
// (tests/browser-speed/*.luma.wgsl, assembled by luma.gl's own WGSL assembler from the npm package).
// Prints ms per draw or dispatch (best and median of the rounds), the speed against luma.gl (the
// median over rounds of luma.gl's ms / the contender's ms in the same round: on a shared machine a
// round's neighbours see the same load, while the best of each may come from different moments) and
// the bits. --kernels exp,log,sin,cos,tan (or transcendentals): tests/browser-speed/transcendental.frag
// with the function put in, against luma.gl's exp_fp64 ... tan_fp64 (transcendental.luma.frag).
//   node speed-suite.mjs --doublet build/bin/doublet [--apis webgl2,webgpu] [--modes df64,df64-fast,df64-int]
//        [--size 256] [--draws N] [--target-ms 100] [--rounds 5] [--kernels straight,loop,exp,..] [--json FILE]
//        [--sabotage drop-lo] [--timeout-ms 3600000]
// --apis: webgl2 (default), webgpu or both (one page each, one table each). --draws 0 (default): per
// contender, as many draws (WebGPU: dispatches) as take --target-ms. --sabotage drop-lo feeds
// doublet's NAME_lo uniforms (WebGPU: df_uniforms' NAME_lo members; the transcendental kernels,
// which have no double uniforms: the low words of their inputs) zeros (a check that the bits
// floor catches broken wiring). --timeout-ms: how long each page may take in all.
// Exit 0 when everything ran (speed is reported, never judged), 1 on a lowering, compile, link or
// run-time error or bits below the sanity floor (median: df64, df64-int < 40; df64-fast, luma.gl < 35), 2 when
// there is no browser or no luma.gl here; with DOUBLET_REQUIRE_BROWSER=1 a missing one is 1.
import { spawnSync } from 'child_process';
import fs from 'fs';
import os from 'os';
import path from 'path';
import { pathToFileURL } from 'url';
import { findChromium, launch, pageOutcome, serve, takeOption } from './session.mjs';

const here = path.dirname(new URL(import.meta.url).pathname);
const root = path.resolve(here, '..', '..');
const args = process.argv.slice(2);
const option = (name, fallback) => takeOption(args, name, fallback);
const doublet = option('--doublet', '');
const apis = option('--apis', 'webgl2').split(',').filter((x) => x);
const modes = option('--modes', 'df64,df64-fast,df64-int').split(',').filter((x) => x);
const size = Number(option('--size', '256'));
const draws = Number(option('--draws', '0'));
const targetMs = Number(option('--target-ms', '100'));
const rounds = Number(option('--rounds', '5'));
// --kernels transcendentals: exp,log,sin,cos,tan (transcendental.frag with the function put in; WebGL2
// only: luma.gl 9.4.2 has no WGSL fp64 functions).
const transcendentals = ['exp', 'log', 'sin', 'cos', 'tan'];
const kernelNames = option('--kernels', 'straight,loop').split(',').filter((x) => x)
  .flatMap((k) => (k === 'transcendentals' ? transcendentals : [k]));
const isTranscendental = (k) => transcendentals.includes(k);
const jsonFile = option('--json', '');
const sabotage = option('--sabotage', '');
const timeoutMs = Number(option('--timeout-ms', '3600000'));
// Sanity floors on the median bits: well below what each gives here (df64-fast: its sloppy sum loses
// bits in the eye subtraction), well above what broken wiring gives (a lost low word: about 24).
// luma.gl's transcendentals have 27-37 bits at worst on Mesa (docs/transcendentals.md): floor 25.
const floors = { df64: 40, 'df64-int': 40, 'df64-fast': 35, luma: 35 };
const floorOf = (kernel, flavour, name) => (flavour === 'luma' ? (isTranscendental(kernel) ? 25 : floors.luma) : floors[name]);
if (!doublet || args.length || !(size > 0) || !(rounds > 0) || !['', 'drop-lo'].includes(sabotage) ||
    kernelNames.some((k) => !['straight', 'loop', ...transcendentals].includes(k)) || !apis.length ||
    apis.some((a) => !['webgl2', 'webgpu'].includes(a)) || (apis.includes('webgpu') && kernelNames.some(isTranscendental))) {
  console.error('usage: node speed-suite.mjs --doublet PATH [--apis webgl2,webgpu] [--modes M,..] [--size N] [--draws N] [--target-ms N] [--rounds N] [--kernels straight,loop,exp,log,sin,cos,tan|transcendentals (webgl2 only)] [--json FILE] [--sabotage drop-lo] [--timeout-ms N]');
  process.exit(1);
}
const missing = (why) => {
  console.error(`speed-suite: ${why}`);
  process.exit(process.env.DOUBLET_REQUIRE_BROWSER === '1' ? 1 : 2);
};

// luma.gl's fp64 module as a luma.gl application gets it (tools/peers/luma-fp64.mjs; never stored here).
const peers = process.env.DOUBLET_PEER_TOOLS || path.join(root, 'tools', 'peers');
if (!fs.existsSync(path.join(peers, 'node_modules', '@luma.gl', 'shadertools')))
  missing(`@luma.gl/shadertools is not installed (cd ${peers} && npm ci)`);
const printed = spawnSync(process.execPath, [path.join(peers, 'luma-fp64.mjs')], { encoding: 'utf8', maxBuffer: 1 << 24 });
if (printed.status !== 0) {
  console.error(`speed-suite: luma-fp64.mjs failed: ${printed.stderr}`);
  process.exit(1);
}
const luma = JSON.parse(printed.stdout);
if (!/uniform\s+fp64arithmeticUniforms\s*\{/.test(luma.glsl)) {
  console.error(`speed-suite: @luma.gl/shadertools ${luma.version}: no fp64arithmeticUniforms block (the module changed)`);
  process.exit(1);
}
// The library is assembled for a vertex shader (luma.gl's fp64 functions are a vertex-stage module);
// the text is the same GLSL in a fragment shader.
const lumaLibrary = luma.glsl.replace('#define SHADER_TYPE_VERTEX', '#define SHADER_TYPE_FRAGMENT');
// WebGPU: luma.gl's WGSL fp64 arithmetic (the fp64arithmetic module; luma.gl 9.4.2 has no WGSL
// fp64 functions module) put before the kernel by luma.gl's own WGSL assembler, for the platform
// luma.gl's WebGPU device reports here (a GPU it does not know: its classic float-float path, not the
// integer one it picks for Apple GPUs). Its uniforms ONE and SPLIT get luma.gl's defaults.
let lumaWgsl = null;
if (apis.includes('webgpu')) {
  const shadertools = await import(pathToFileURL(path.join(peers, 'node_modules', '@luma.gl', 'shadertools', 'dist', 'index.js')).href);
  const { fp64arithmetic, WGSLShaderAssembler } = shadertools;
  if (!fp64arithmetic || typeof fp64arithmetic.source !== 'string' || !/fn\s+sum_fp64\s*\(/.test(fp64arithmetic.source) || !WGSLShaderAssembler) {
    console.error(`speed-suite: @luma.gl/shadertools ${luma.version}: no WGSL fp64arithmetic module (the package changed)`);
    process.exit(1);
  }
  const platformInfo = { type: 'webgpu', gpu: 'unknown', gpuType: 'cpu', shaderLanguage: 'wgsl', shaderLanguageVersion: 100, features: new Set() };
  const assembler = new WGSLShaderAssembler();
  lumaWgsl = (source) => assembler.assembleWGSLShader({ platformInfo, source, modules: [fp64arithmetic] });
  lumaWgsl.uniforms = Object.keys(fp64arithmetic.uniformTypes).map((name) => fp64arithmetic.defaultUniforms[name]);
}

const chromium = await findChromium('speed-suite');
if (!chromium) missing('no browser');

const kernelDir = path.join(root, 'tests', 'browser-speed');
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'doublet-speed-'));
let failed = false;
const lower = (source, mode, target = 'webgl2') => {
  const out = path.join(work, `${path.basename(source)}.${mode}.${target}`);
  const manifest = `${out}.json`;
  const r = spawnSync(doublet, ['lower', source, '--target', target, '--mode', mode, '-o', out, '--manifest', manifest], { encoding: 'utf8' });
  if (r.status !== 0) {
    console.error(`speed-suite: doublet lower ${source} --target ${target} --mode ${mode} failed:\n${r.stderr}`);
    failed = true;
    return null;
  }
  return target === 'wgsl' ? { code: fs.readFileSync(out, 'utf8'), manifest: JSON.parse(fs.readFileSync(manifest, 'utf8')) }
                           : fs.readFileSync(out, 'utf8');
};
const marker = '// luma.gl fp64 library: inserted here by speed-suite.mjs';
const jobs = {};
if (apis.includes('webgl2'))
  jobs.webgl2 = kernelNames.map((name) => {
    let source = path.join(kernelDir, `${name}.frag`);
    let lumaText;
    if (isTranscendental(name)) {
      const withFunction = (file) => fs.readFileSync(path.join(kernelDir, file), 'utf8').replace(/\bFUNCTION(?=(_fp64)?\()/g, name);
      source = path.join(work, `${name}.frag`);
      fs.writeFileSync(source, withFunction('transcendental.frag'));
      lumaText = withFunction('transcendental.luma.frag');
    } else {
      lumaText = fs.readFileSync(path.join(kernelDir, `${name}.luma.frag`), 'utf8');
    }
    if (!lumaText.includes(marker)) throw new Error(`${name}.luma.frag has no line '${marker}'`);
    const contenders = [
      { name: 'fp32', flavour: 'fp32', code: lower(source, 'fp32') },
      { name: `luma.gl ${luma.version}`, flavour: 'luma', luma: true, code: lumaText.replace(marker, lumaLibrary),
        blocks: { fp64arithmeticUniforms: luma.uniforms } },
      ...modes.map((mode) => ({ name: mode, flavour: 'doublet', doublet: true, code: lower(source, mode) })),
    ];
    return { name, contenders };
  });
// WebGPU: which storage buffer of each kernel is its input and which its output (the blocks of the
// .comp, the arrays of the .luma.wgsl); the loose uniforms are doublet's df_uniforms, luma.gl's params.
const wgslRoles = {
  straight: { Positions: 'input', Clip: 'output', positions: 'input', clip: 'output', params: 'uniforms' },
  loop: { States: 'input', Positions: 'output', states: 'input', positions: 'output', params: 'uniforms' },
};
const doubletBindings = (kernel, lowered) => lowered && lowered.manifest.variables.filter((v) => v.binding !== undefined).map((v) => {
  if (v.name === 'df_uniforms') return { binding: v.binding, role: 'uniforms', members: v.members };
  if (!wgslRoles[kernel][v.name]) throw new Error(`${kernel}.comp: unexpected buffer ${v.name}`);
  return { binding: v.binding, role: wgslRoles[kernel][v.name] };
});
if (apis.includes('webgpu'))
  jobs.webgpu = kernelNames.map((name) => {
    const source = path.join(kernelDir, `${name}.comp`);
    const assembled = lumaWgsl(fs.readFileSync(path.join(kernelDir, `${name}.luma.wgsl`), 'utf8'));
    const lumaBindings = assembled.shaderLayout.bindings.map((b) => {
      if (b.group !== 0) throw new Error(`${name}.luma.wgsl: binding ${b.name} in group ${b.group}`);
      if (b.name === 'fp64arithmetic') return { binding: b.location, role: 'luma', values: lumaWgsl.uniforms };
      if (!wgslRoles[name][b.name]) throw new Error(`${name}.luma.wgsl: unexpected binding ${b.name}`);
      return { binding: b.location, role: wgslRoles[name][b.name] };
    });
    const doubletContender = (contenderName, flavour, mode) => {
      const lowered = lower(source, mode, 'wgsl');
      return { name: contenderName, flavour, doublet: flavour === 'doublet', code: lowered && lowered.code, bindings: doubletBindings(name, lowered) };
    };
    const contenders = [
      doubletContender('fp32', 'fp32', 'fp32'),
      { name: `luma.gl ${luma.version}`, flavour: 'luma', luma: true, code: assembled.source, bindings: lumaBindings },
      ...modes.map((mode) => doubletContender(mode, 'doublet', mode)),
    ];
    return { name, contenders };
  });
if (failed) {
  fs.rmSync(work, { recursive: true, force: true });
  process.exit(1);
}
if (sabotage === 'drop-lo')
  for (const api of Object.keys(jobs)) for (const k of jobs[api]) for (const c of k.contenders) if (c.doublet) c.sabotage = 'drop-lo';

for (const f of ['speed.html', 'speed-page.mjs']) fs.copyFileSync(path.join(here, f), path.join(work, f));
for (const api of Object.keys(jobs))
  fs.writeFileSync(path.join(work, `job-${api}.json`), JSON.stringify({ api, size, rounds, draws, targetMs, seed: 23, kernels: jobs[api] }));
const server = await serve(work);
let browser;
const outcomes = {};
try {
  browser = await launch(chromium);
  for (const api of Object.keys(jobs)) {
    const page = await browser.newPage();
    // (ANGLE's "GPU stall due to ReadPixels" is the point of the read-back here: not shown)
    page.on('console', (message) => { if (!/GPU stall due to ReadPixels/.test(message.text())) console.error(`[page ${message.type()}] ${message.text()}`); });
    try {
      await page.goto(`http://127.0.0.1:${server.address().port}/speed.html?job=job-${api}.json`, { timeout: 60000 });
      outcomes[api] = await pageOutcome(page, timeoutMs);
    } catch (e) {
      outcomes[api] = { error: e.message };
    }
    await page.close().catch(() => {});
    if (outcomes[api].error !== undefined) break;
  }
} catch (e) {
  outcomes.browser = { error: e.message };
}
if (browser) await browser.close().catch(() => {});
server.close();
fs.rmSync(work, { recursive: true, force: true });
for (const [api, outcome] of Object.entries(outcomes))
  if (outcome.error !== undefined) {
    console.error(`speed-suite: the ${api === 'browser' ? 'browser' : `${api} page`} failed: ${outcome.error}`);
    process.exit(1);
  }

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};
const vsLuma = (peer, c) => median(peer.ms.map((m, r) => m / c.ms[r]));  // > 1: faster than luma.gl
const fixed = (x, n) => (x === null || x === undefined ? 'n/a' : x.toFixed(n));
const verdicts = [];
const rows = [];
const devices = {};
for (const api of Object.keys(jobs)) {
  const { renderer } = outcomes[api].result;
  devices[api] = renderer;
  const unit = api === 'webgpu' ? 'dispatch' : 'draw';
  const tag = Object.keys(jobs).length > 1 ? `${api} ` : '';  // the verdicts of two APIs
  if (api === 'webgl2')
    console.log(`WebGL2 renderer: ${renderer}; ${size}x${size} pixels, ${rounds} interleaved round(s)${sabotage ? `; SABOTAGE ${sabotage}` : ''}`);
  else
    console.log(`WebGPU adapter: ${renderer}; ${size * size} elements (${size}x${size}), compute, ${rounds} interleaved round(s)${sabotage ? `; SABOTAGE ${sabotage}` : ''}`);
  console.log(`| kernel | contender | ms/${unit} (best) | ms/${unit} (median) | ${unit === 'draw' ? 'draws' : 'dispatches'} | speed vs luma.gl | bits min | bits median |\n|---|---|---|---|---|---|---|---|`);
  for (const k of outcomes[api].result.kernels) {
    const peer = k.contenders.find((c) => c.name.startsWith('luma.gl'));
    for (const c of k.contenders) {
      const flavour = jobs[api].find((x) => x.name === k.name).contenders.find((x) => x.name === c.name).flavour;
      const ratio = vsLuma(peer, c);
      const floor = floorOf(k.name, flavour, c.name);
      const low = floor !== undefined && !(c.bits_median >= floor);
      if (low) failed = true;
      rows.push({ api, kernel: k.name, ...c, vs_luma: +ratio.toFixed(3), bits_floor: floor ?? null, below_floor: low });
      console.log(`| ${k.name} | ${c.name} | ${fixed(c.best_ms, 2)} | ${fixed(c.median_ms, 2)} | ${c.draws} | ${fixed(ratio, 2)}x | ${fixed(c.bits_min, 1)} | ${fixed(c.bits_median, 1)}${low ? ` BELOW THE FLOOR (${floor})` : ''} |`);
    }
    const df = k.contenders.find((c) => c.name === 'df64');
    if (df) {
      const ratio = vsLuma(peer, df);
      const bitsOk = df.bits_min >= peer.bits_min && df.bits_median >= peer.bits_median;
      // Issue 23: arithmetic kernels >= 1.3x luma.gl's speed, every transcendental faster than luma.gl's.
      const goal = isTranscendental(k.name) ? 1.0 : 1.3;
      verdicts.push(`${tag}${k.name}: df64 ${ratio.toFixed(2)}x luma.gl's speed at ${fixed(df.bits_min, 1)}/${fixed(df.bits_median, 1)} bits ` +
                    `against ${fixed(peer.bits_min, 1)}/${fixed(peer.bits_median, 1)} (min/median): ` +
                    (ratio >= goal && bitsOk ? 'met' : `not met (${ratio >= goal ? '' : `speed < ${goal.toFixed(1)}x`}${ratio >= goal || bitsOk ? '' : ', '}${bitsOk ? '' : 'fewer bits'})`));
    }
  }
}
if (jsonFile) fs.writeFileSync(jsonFile, JSON.stringify({ renderer: devices.webgl2 ?? null, adapter: devices.webgpu ?? null, size, rounds, luma: luma.version, sabotage: sabotage || null, rows }, null, 1));
console.log(`goal (df64 >= 1.3x luma.gl at >= its bits; transcendentals: faster than luma.gl): ${verdicts.join('; ') || 'no df64 row'}`);
process.exit(failed ? 1 : 0);
