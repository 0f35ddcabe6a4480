// Browser probe (docs/web.md): which WebGL2 / WebGPU stack headless Chromium has here, and what
// it does to float-float arithmetic.
//   node tools/browser/probe.mjs GUARDED.frag UNGUARDED.frag   (scripts/web-probe/run does it all)
// GUARDED.frag is probe.frag lowered by `doublet lower --target es300`; UNGUARDED.frag the same
// text with the uniform guard removed (the sabotage). Each runs add/sub/mul/div/sqrt on 4096
// float-float inputs in a WebGL2 fragment shader; a hand-written WGSL compute kernel (TwoSum,
// Veltkamp/Dekker TwoProd; Dekker 1971, Knuth TAOCP 4.2.2) does add and mul on WebGPU, with and
// without an opaque runtime zero. Correct bits = -log2(max relative error) against JS doubles.
import { chromium } from 'playwright-core';
import fs from 'fs';
import http from 'http';

const [guardedPath, unguardedPath] = process.argv.slice(2);
if (!guardedPath || !unguardedPath) {
  console.error('usage: node probe.mjs GUARDED.frag UNGUARDED.frag');
  process.exit(2);
}
// WebGPU needs a secure context: serve an empty page on loopback.
const server = http.createServer((_, res) => res.end('<!doctype html><title>probe</title>'));
await new Promise(resolve => server.listen(0, '127.0.0.1', resolve));
const url = `http://127.0.0.1:${server.address().port}/`;

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync',
         '--enable-unsafe-swiftshader', '--enable-unsafe-webgpu'],
});
const page = await browser.newPage();
await page.goto(url);

// Same deterministic inputs in every run: a and b with low words, log-uniform over 2^-20..2^20.
const makeInputs = () => {
  const N = 4096, f = Math.fround, data = new Float32Array(4 * N), ref = [];
  let seed = 12345;
  const rnd = () => { seed = (seed * 1103515245 + 12345) >>> 0; return seed / 4294967296; };
  const mk = () => { const m = (rnd() < 0.5 ? -1 : 1) * 2 ** ((rnd() - 0.5) * 40) * (1 + rnd()); const hi = f(m); return [hi, f(m - hi)]; };
  for (let i = 0; i < N; ++i) { const [ah, al] = mk(), [bh, bl] = mk(); data.set([ah, al, bh, bl], 4 * i); ref.push([ah + al, bh + bl]); }
  return { N, data: Array.from(data), ref };
};

async function webgl2(fragSource) {
  return page.evaluate(async ({ fragSource, inputs }) => {
    const out = {};
    const gl = document.createElement('canvas').getContext('webgl2');
    if (!gl) return { error: 'no WebGL2 context' };
    const dbg = gl.getExtension('WEBGL_debug_renderer_info');
    out.renderer = dbg ? gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
    out.version = gl.getParameter(gl.VERSION);
    if (!gl.getExtension('EXT_color_buffer_float')) return { ...out, error: 'no EXT_color_buffer_float' };
    const compile = (type, src) => {
      const s = gl.createShader(type); gl.shaderSource(s, src); gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
      return s;
    };
    const prog = gl.createProgram();
    try {
      gl.attachShader(prog, compile(gl.VERTEX_SHADER, '#version 300 es\nin vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }'));
      gl.attachShader(prog, compile(gl.FRAGMENT_SHADER, fragSource));
    } catch (e) { return { ...out, error: String(e) }; }
    gl.bindAttribLocation(prog, 0, 'p'); gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) return { ...out, error: gl.getProgramInfoLog(prog) };
    gl.useProgram(prog);
    gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0); gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    const W = 64, H = inputs.N / W;
    const texture = (pixels) => {
      const t = gl.createTexture(); gl.bindTexture(gl.TEXTURE_2D, t);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, W, H, 0, gl.RGBA, gl.FLOAT, pixels);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      return t;
    };
    const target = texture(null);
    gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
    gl.activeTexture(gl.TEXTURE0); texture(new Float32Array(inputs.data));
    gl.uniform1i(gl.getUniformLocation(prog, 'u_in'), 0);
    gl.viewport(0, 0, W, H);
    const exact = { add: (a, b) => a + b, sub: (a, b) => a - b, mul: (a, b) => a * b, div: (a, b) => a / b, sqrt: a => Math.sqrt(Math.abs(a)) };
    out.bits = {};
    Object.entries(exact).forEach(([name, fn], op) => {
      gl.uniform1i(gl.getUniformLocation(prog, 'u_op'), op);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      const px = new Float32Array(4 * inputs.N);
      gl.readPixels(0, 0, W, H, gl.RGBA, gl.FLOAT, px);
      let worst = 0;
      for (let i = 0; i < inputs.N; ++i) {
        const want = fn(inputs.ref[i][0], inputs.ref[i][1]);
        const rel = Math.abs(px[4 * i] + px[4 * i + 1] - want) / Math.abs(want);
        if (!(rel <= worst)) worst = rel;  // NaN counts as the worst
      }
      out.bits[name] = worst === 0 ? 60 : Math.round(-Math.log2(worst) * 100) / 100;
    });
    return out;
  }, { fragSource, inputs: makeInputs() });
}

const wgslKernel = (guarded) => `
struct Params { guard: f32, n: u32 }
@group(0) @binding(0) var<storage, read> inputs: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> outputs: array<vec4<f32>>;
@group(0) @binding(2) var<uniform> params: Params;
fn g(x: f32) -> f32 { return ${guarded ? 'x - params.guard' : 'x'}; }
fn two_sum(a: f32, b: f32) -> vec2<f32> { let s = g(a + b); let bb = g(s - a); return vec2<f32>(s, (a - (s - bb)) + (b - bb)); }
fn split(a: f32) -> vec2<f32> { let t = g(a * 4097.0); let hi = g(t - g(t - a)); return vec2<f32>(hi, a - hi); }
fn two_prod(a: f32, b: f32) -> vec2<f32> {
  let p = g(a * b); let x = split(a); let y = split(b);
  return vec2<f32>(p, g(g(g(g(x.x * y.x - p) + x.x * y.y) + x.y * y.x) + x.y * y.y));
}
fn df_add(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
  let s = two_sum(a.x, b.x); let t = two_sum(a.y, b.y); let v = two_sum(s.x, g(s.y + t.x));
  return two_sum(v.x, g(t.y + v.y));
}
fn df_mul(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
  let p = two_prod(a.x, b.x); return two_sum(p.x, g(p.y + g(a.x * b.y + a.y * b.x)));
}
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
  if (id.x >= params.n) { return; }
  let v = inputs[id.x];
  outputs[id.x] = vec4<f32>(df_add(v.xy, v.zw), df_mul(v.xy, v.zw));
}`;

async function webgpu(code) {
  return page.evaluate(async ({ code, inputs }) => {
    if (!navigator.gpu) return { error: 'navigator.gpu missing' };
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) return { error: 'no WebGPU adapter' };
    const device = await adapter.requestDevice();
    const module = device.createShaderModule({ code });
    const errors = (await module.getCompilationInfo()).messages.filter(m => m.type === 'error');
    if (errors.length) return { error: errors.map(m => m.message).join('\n') };
    const data = new Float32Array(inputs.data), bytes = data.byteLength;
    const buffer = (size, usage) => device.createBuffer({ size, usage });
    const inb = buffer(bytes, GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST);
    const outb = buffer(bytes, GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC);
    const params = buffer(16, GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST);
    const readback = buffer(bytes, GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST);
    device.queue.writeBuffer(inb, 0, data);
    device.queue.writeBuffer(params, 0, new Uint32Array([0, inputs.N, 0, 0]));  // guard = +0.0
    const pipeline = device.createComputePipeline({ layout: 'auto', compute: { module, entryPoint: 'main' } });
    const bind = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries: [
      { binding: 0, resource: { buffer: inb } }, { binding: 1, resource: { buffer: outb } },
      { binding: 2, resource: { buffer: params } }] });
    const encoder = device.createCommandEncoder(), pass = encoder.beginComputePass();
    pass.setPipeline(pipeline); pass.setBindGroup(0, bind); pass.dispatchWorkgroups(inputs.N / 64); pass.end();
    encoder.copyBufferToBuffer(outb, 0, readback, 0, bytes);
    device.queue.submit([encoder.finish()]);
    await readback.mapAsync(GPUMapMode.READ);
    const out = new Float32Array(readback.getMappedRange().slice(0));
    const bits = (k, fn) => {
      let worst = 0;
      for (let i = 0; i < inputs.N; ++i) {
        const want = fn(inputs.ref[i][0], inputs.ref[i][1]);
        const rel = Math.abs(out[4 * i + k] + out[4 * i + k + 1] - want) / Math.abs(want);
        if (!(rel <= worst)) worst = rel;
      }
      return worst === 0 ? 60 : Math.round(-Math.log2(worst) * 100) / 100;
    };
    const info = adapter.info || {};
    return { adapter: `${info.vendor} ${info.architecture}`.trim(), bits: { add: bits(0, (a, b) => a + b), mul: bits(2, (a, b) => a * b) } };
  }, { code, inputs: makeInputs() });
}

const report = {
  chromium: browser.version(),
  webgl2: { guarded: await webgl2(fs.readFileSync(guardedPath, 'utf8')), unguarded: await webgl2(fs.readFileSync(unguardedPath, 'utf8')) },
  webgpu: { guarded: await webgpu(wgslKernel(true)), unguarded: await webgpu(wgslKernel(false)) },
};
console.log(JSON.stringify(report, null, 1));
await browser.close();
server.close();
