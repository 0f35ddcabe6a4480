// The page of the browser speed benchmark (tools/browser/speed-suite.mjs writes the job next to it and
// names it in ?job=): one kernel per pixel of a size x size framebuffer in WebGL2 (job.api 'webgl2'),
// or per element of size x size in WebGPU compute (job.api 'webgpu'), timed in interleaved rounds,
// and the outputs compared with the same kernel in JavaScript doubles.
// Job: {api, size, rounds, draws (0: per contender, enough for targetMs), targetMs, seed,
//       kernels: [{name, contenders: [{name, flavour: 'fp32'|'doublet'|'luma', code, blocks}]}]};
//       WebGPU contenders also carry bindings: [{binding, role: 'input'|'output'|'uniforms'|'luma',
//       members (role 'uniforms' of doublet's: the manifest's df_uniforms members), values (role 'luma')}].
// Reports window.doubletResult = {renderer, kernels: [{name, contenders: [{name, draws, ms: [per
// round], best_ms, median_ms, bits_min, bits_median, values}]}]} (WebGPU: renderer is the adapter,
// draws are dispatches) or throws with the error.

// Deterministic inputs (mulberry32): every run measures the same numbers.
function random(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// A double as the host hands it to float-float code: hi = the nearest float, lo = the rest, rounded.
const hi = (x) => Math.fround(x);
const lo = (x) => Math.fround(x - Math.fround(x));
const joined = (x) => hi(x) + lo(x);  // what the shader's (hi, lo) pair denotes, as a double

// Each kernel: its per-pixel input words (texel 2x and 2x + 1 of row y, as the shaders read them; the
// compute shaders read the first `doubles` (hi, lo) pairs of each pixel's 8 words), its double uniforms (GLSL order; `luma` the order of the luma.gl kernel's vec2 array when it differs),
// the number of double components it writes (two per output), and the JavaScript reference.
const kernels = {
  // Relative to eye: an eye 6,378 km from the origin, positions within 2 km of it, a dense matrix of
  // full 53-bit entries. Offsets and entries are positive so no output cancels (bits measure the
  // arithmetic, not an ill-conditioned sum).
  straight: (rand, size) => {
    const eye = [6378137.0 + rand(), 1234567.0 + rand(), 3456789.0 + rand()].map(joined);
    const m = [];  // m[row][col]
    for (let r = 0; r < 4; ++r) m.push([0, 1, 2, 3].map(() => joined(0.25 + rand())));
    const words = new Float32Array(size * size * 8);
    const positions = new Float64Array(size * size * 3);
    for (let i = 0; i < size * size; ++i) {
      const p = eye.map((e) => joined(e + 100 + 1900 * rand()));
      positions.set(p, 3 * i);
      words.set([hi(p[0]), lo(p[0]), hi(p[1]), lo(p[1]), hi(p[2]), lo(p[2]), 0, 0], 8 * i);
    }
    return {
      words, doubles: 3, components: 4,
      uniforms: {
        eye: { values: eye },
        mvp: { values: [0, 1, 2, 3].flatMap((c) => m.map((row) => row[c])), luma: m.flat() },  // GLSL: column after column
      },
      reference(i) {
        const d = [0, 1, 2].map((k) => positions[3 * i + k] - eye[k]);
        return m.map((row) => row[0] * d[0] + row[1] * d[1] + row[2] * d[2] + row[3]);
      },
    };
  },
  // A low Earth orbit in km and km/s (mu = 398600.4418 km^3/s^2), each pixel's state perturbed, 32
  // leapfrog steps of 10 s: the same operations in the same order as loop.frag.
  loop: (rand, size) => {
    const mu = joined(398600.4418), dt = joined(10.0 + rand() * 1e-3);
    const words = new Float32Array(size * size * 8);
    const states = new Float64Array(size * size * 4);
    for (let i = 0; i < size * size; ++i) {
      const px = joined(7000 + 100 * rand()), py = joined(100 * rand());
      const s = [px, py, joined(0.1 * rand()), joined(Math.sqrt(mu / px) + 0.1 * rand())];
      states.set(s, 4 * i);
      words.set(s.flatMap((x) => [hi(x), lo(x)]), 8 * i);
    }
    return {
      words, doubles: 4, components: 2,
      uniforms: { mu: { values: [mu] }, dt: { values: [dt] } },
      reference(i) {
        let [px, py, vx, vy] = states.subarray(4 * i, 4 * i + 4);
        for (let k = 0; k < 32; ++k) {
          let r2 = px * px + py * py, r = Math.sqrt(r2), f = -mu / (r2 * r), h = 0.5 * dt * f;
          vx += h * px; vy += h * py;
          px += dt * vx; py += dt * vy;
          r2 = px * px + py * py; r = Math.sqrt(r2); f = -mu / (r2 * r); h = 0.5 * dt * f;
          vx += h * px; vy += h * py;
        }
        return [px, py];
      },
    };
  },
  // The transcendental kernels (transcendental.frag): four doubles per pixel drawn from the function's
  // domain of docs/transcendentals.md's luma.gl comparison, no uniforms.
  ...Object.fromEntries(Object.entries({
    exp: [Math.exp, (rand) => -60 + 148 * rand()],  // from -60: at -70 the fragment stage flushes lo
    log: [Math.log, (rand) => 2 ** (-60 + 120 * rand())],
    sin: [Math.sin, (rand) => Math.PI * (2 * rand() - 1)],
    cos: [Math.cos, (rand) => Math.PI * (2 * rand() - 1)],
    tan: [Math.tan, (rand) => Math.PI * (2 * rand() - 1)],
  }).map(([name, [f, draw]]) => [name, (rand, size) => {
    const words = new Float32Array(size * size * 8);
    const x = new Float64Array(size * size * 4);
    for (let i = 0; i < size * size; ++i) {
      const xs = [0, 1, 2, 3].map(() => joined(draw(rand)));
      x.set(xs, 4 * i);
      words.set(xs.flatMap((v) => [hi(v), lo(v)]), 8 * i);
    }
    return { words, doubles: 4, components: 4, uniforms: {}, reference: (i) => [...x.subarray(4 * i, 4 * i + 4)].map(f),
             input: (value) => x[value] };
  }])),
};

// The uniform values one flavour of the kernel takes: doublet's NAME_hi/NAME_lo, the float twin's
// NAME (the double rounded to float), luma.gl's NAME64 (hi, lo pairs). Sabotage drop-lo feeds doublet
// zeros for the low words (speed-suite.mjs --sabotage: the bits floor must catch it).
function uniformValues(flavour, uniforms, sabotage) {
  const out = {};
  for (const [name, u] of Object.entries(uniforms)) {
    if (flavour === 'doublet') {
      out[`${name}_hi`] = u.values.map(hi);
      out[`${name}_lo`] = u.values.map((x) => (sabotage === 'drop-lo' ? 0 : lo(x)));
    } else if (flavour === 'fp32') {
      out[name] = u.values.map(Math.fround);
    } else {
      out[`${name}64`] = (u.luma || u.values).flatMap((x) => [hi(x), lo(x)]);
    }
  }
  return out;
}

const vertexShader = `#version 300 es
// one triangle that covers the viewport
void main() {
  gl_Position = vec4(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0, 0.0, 1.0);
}
`;

function compile(gl, type, text) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, text);
  gl.compileShader(shader);
  return shader;
}

// Links one contender and sets everything it reads; throws when the program reads a uniform or a
// block the job does not feed (a wiring mistake would otherwise read zeros).
function setUp(gl, contender, kernel) {
  const program = gl.createProgram();
  const vs = compile(gl, gl.VERTEX_SHADER, vertexShader);
  const fs = compile(gl, gl.FRAGMENT_SHADER, contender.code);
  gl.attachShader(program, vs);
  gl.attachShader(program, fs);
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS))
    throw new Error(`${contender.name}: compile/link failed:\n${gl.getShaderInfoLog(fs)}\n${gl.getProgramInfoLog(program)}`);
  gl.useProgram(program);
  const values = uniformValues(contender.flavour, kernel.uniforms, contender.sabotage);
  const used = new Set();
  for (let i = 0; i < gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS); ++i) {
    const info = gl.getActiveUniform(program, i);
    const name = info.name.replace(/\[0\]$/, '');
    if (name.includes('.')) continue;  // a block member: below
    const location = gl.getUniformLocation(program, name);
    if (info.type === gl.SAMPLER_2D) { gl.uniform1i(location, 0); continue; }
    if (name === 'df_guard') continue;  // doublet's guard: left at the 0 GL gives it (docs/web.md)
    const data = values[name];
    if (!data) throw new Error(`${contender.name}: uniform ${name} is not fed`);
    used.add(name);
    const f = new Float32Array(data);
    switch (info.type) {
      case gl.FLOAT: gl.uniform1fv(location, f); break;
      case gl.FLOAT_VEC2: gl.uniform2fv(location, f); break;
      case gl.FLOAT_VEC3: gl.uniform3fv(location, f); break;
      case gl.FLOAT_VEC4: gl.uniform4fv(location, f); break;
      case gl.FLOAT_MAT4: gl.uniformMatrix4fv(location, false, f); break;
      default: throw new Error(`${contender.name}: uniform ${name} of type 0x${info.type.toString(16)}`);
    }
  }
  for (const name of Object.keys(values))
    if (!used.has(name)) throw new Error(`${contender.name}: uniform ${name} is not in the program`);
  // Uniform blocks (luma.gl's fp64arithmeticUniforms: ONE and SPLIT, uploaded as luma.gl does).
  const buffers = [];
  for (let b = 0; b < gl.getProgramParameter(program, gl.ACTIVE_UNIFORM_BLOCKS); ++b) {
    const blockName = gl.getActiveUniformBlockName(program, b);
    const members = (contender.blocks || {})[blockName];
    if (!members) throw new Error(`${contender.name}: uniform block ${blockName} is not fed`);
    const data = new Float32Array(gl.getActiveUniformBlockParameter(program, b, gl.UNIFORM_BLOCK_DATA_SIZE) / 4);
    const names = Object.keys(members);
    const indices = gl.getUniformIndices(program, names.map((n) => `${blockName}.${n}`));
    if (indices.some((k) => k === gl.INVALID_INDEX)) throw new Error(`${contender.name}: block ${blockName} lacks one of ${names}`);
    const offsets = gl.getActiveUniforms(program, indices, gl.UNIFORM_OFFSET);
    names.forEach((n, k) => { data[offsets[k] / 4] = members[n]; });
    const buffer = gl.createBuffer();
    gl.bindBuffer(gl.UNIFORM_BUFFER, buffer);
    gl.bufferData(gl.UNIFORM_BUFFER, data, gl.STATIC_DRAW);
    gl.uniformBlockBinding(program, b, b);
    buffers.push([b, buffer]);
  }
  return () => {
    gl.useProgram(program);
    for (const [b, buffer] of buffers) gl.bindBufferBase(gl.UNIFORM_BUFFER, b, buffer);
  };
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

function run(job) {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = 1;
  const gl = canvas.getContext('webgl2', { antialias: false, depth: false, stencil: false });
  if (!gl) throw new Error('no WebGL2 context');
  if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('no EXT_color_buffer_float (float render targets)');
  const size = job.size;
  const info = gl.getExtension('WEBGL_debug_renderer_info');  // ANGLE's back end, not just "WebKit WebGL"
  const result = { renderer: gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER), kernels: [] };
  gl.bindVertexArray(gl.createVertexArray());
  for (const k of job.kernels) {
    const kernel = kernels[k.name](random(job.seed), size);
    const outputs = kernel.components / 2;
    // Inputs: an RGBA32F texture read with texelFetch (NEAREST: a float texture is not filterable).
    const wordTexture = (data) => {
      const texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, 2 * size, size);
      gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, 2 * size, size, gl.RGBA, gl.FLOAT, data);
      return texture;
    };
    gl.activeTexture(gl.TEXTURE0);
    const words = wordTexture(kernel.words);
    // Sabotage drop-lo of a kernel without double uniforms (the transcendentals): doublet's contenders
    // read the input words with every low word zeroed instead.
    const wordsNoLo = !Object.keys(kernel.uniforms).length && k.contenders.some((c) => c.sabotage === 'drop-lo')
      ? wordTexture(kernel.words.map((w, i) => (i % 2 ? 0 : w))) : null;
    // Outputs: one RGBA32F attachment per vec4 output.
    const framebuffer = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    for (let o = 0; o < outputs; ++o) {
      const t = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, size, size);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + o, gl.TEXTURE_2D, t, 0);
    }
    gl.bindTexture(gl.TEXTURE_2D, words);
    gl.drawBuffers([...Array(outputs).keys()].map((o) => gl.COLOR_ATTACHMENT0 + o));
    if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) throw new Error('framebuffer incomplete');
    gl.viewport(0, 0, size, size);
    gl.readBuffer(gl.COLOR_ATTACHMENT0);
    const pixel = new Float32Array(4);
    const timeDraws = (n) => {
      const start = performance.now();
      for (let d = 0; d < n; ++d) gl.drawArrays(gl.TRIANGLES, 0, 3);
      gl.finish();
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, pixel);
      return (performance.now() - start) / n;
    };

    const reference = new Float64Array(size * size * kernel.components);
    for (let i = 0; i < size * size; ++i) reference.set(kernel.reference(i), kernel.components * i);

    // Compile, the first draw (ANGLE and SwiftShader build the pipeline there), then, unless the job
    // fixes the draws, doubling them until one measurement takes targetMs.
    const contenders = k.contenders.map((c) => {
      const program = setUp(gl, c, kernel);
      const texture = c.sabotage === 'drop-lo' && wordsNoLo ? wordsNoLo : words;
      const bind = () => { program(); gl.bindTexture(gl.TEXTURE_2D, texture); };
      bind();
      timeDraws(1);
      let draws = job.draws;
      if (!draws)
        for (draws = 1; draws < 4096 && draws * timeDraws(draws) < job.targetMs;) draws *= 2;
      const error = gl.getError();
      if (error !== gl.NO_ERROR) throw new Error(`${c.name}: WebGL error 0x${error.toString(16)}`);
      return { ...c, bind, draws, ms: [] };
    });
    // Interleaved rounds: round r starts at contender r (mod n), so none always runs first or last.
    for (let r = 0; r < job.rounds; ++r)
      for (let j = 0; j < contenders.length; ++j) {
        const c = contenders[(r + j) % contenders.length];
        c.bind();
        c.ms.push(timeDraws(c.draws));
      }
    // Bits: one draw read back whole; got = hi + lo in doubles against the JavaScript reference.
    const rows = [];
    for (const c of contenders) {
      c.bind();
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      const bits = new Float64Array(size * size * kernel.components);
      const texels = new Float32Array(size * size * 4);
      let worst = null;  // the value with the fewest bits: where a kernel loses them
      for (let o = 0; o < outputs; ++o) {
        gl.readBuffer(gl.COLOR_ATTACHMENT0 + o);
        gl.readPixels(0, 0, size, size, gl.RGBA, gl.FLOAT, texels);
        for (let i = 0; i < size * size; ++i)
          for (let h = 0; h < 2; ++h) {
            const got = texels[4 * i + h] + texels[4 * i + 2 + h];
            const ref = reference[kernel.components * i + 2 * o + h];
            const error = Math.abs(got - ref) / Math.abs(ref);
            // NaN (a broken kernel) counts as 0 bits; an exact result as 53.
            const at = kernel.components * i + 2 * o + h;
            bits[at] = error === 0 ? 53 : Number.isNaN(error) ? 0 : Math.min(53, Math.max(0, -Math.log2(error)));
            if (!worst || bits[at] < worst.bits)
              worst = { bits: bits[at], pixel: i, value: at, want: ref, got, ...(kernel.input ? { input: kernel.input(at) } : {}) };
          }
      }
      gl.readBuffer(gl.COLOR_ATTACHMENT0);
      const error = gl.getError();
      if (error !== gl.NO_ERROR) throw new Error(`${c.name}: WebGL error 0x${error.toString(16)}`);
      if (gl.isContextLost()) throw new Error('the WebGL context was lost');
      rows.push({ name: c.name, draws: c.draws, ms: c.ms.map((x) => +x.toFixed(4)), best_ms: Math.min(...c.ms),
                  median_ms: median(c.ms), bits_min: bits.reduce((a, b) => Math.min(a, b), 53), bits_median: median(bits),
                  values: bits.length, worst });
    }
    result.kernels.push({ name: k.name, size, contenders: rows });
  }
  return result;
}

// WebGPU: the kernels as compute shaders (tests/browser-speed/*.comp lowered --target wgsl, and
// *.luma.wgsl assembled by luma.gl), one invocation per element, doubles as (hi, lo) f32 pairs in
// storage buffers (doublet's df_double, luma.gl's vec2f: the same bytes). Uniform buffers: doublet's
// df_uniforms packed at the manifest's offsets (the guard left at 0, docs/web.md); luma.gl's Params
// one vec4f (hi, lo, -, -) per double in declaration order, then count (tests/browser-speed/*.luma.wgsl);
// luma.gl's fp64arithmetic uniforms (ONE, SPLIT: f32, f32) with the values luma.gl uploads.
function doubletUniforms(contender, members, values) {
  const end = Math.max(...members.map((m) => m.offset + m.size));
  const bytes = new ArrayBuffer(Math.ceil(end / 16) * 16);
  const f32 = new Float32Array(bytes), u32 = new Uint32Array(bytes);
  const used = new Set();
  for (const m of members) {
    if (m.name === 'df_guard') continue;  // doublet's guard: 0, as a fresh buffer holds (docs/web.md)
    const data = values[m.name];
    if (!data) throw new Error(`${contender.name}: uniform ${m.name} is not fed`);
    used.add(m.name);
    if (m.lowered_type === 'u32') u32[m.offset / 4] = data[0];
    else if (/^(f32|vec[234]<f32>|mat4x4<f32>)$/.test(m.lowered_type)) {
      if (data.length * 4 !== m.size) throw new Error(`${contender.name}: uniform ${m.name}: ${data.length} values for ${m.size} bytes`);
      f32.set(data, m.offset / 4);  // mat4x4<f32>: columns 16 bytes apart, as GLSL's column order gives them
    } else throw new Error(`${contender.name}: uniform ${m.name} of type ${m.lowered_type}`);
  }
  for (const name of Object.keys(values))
    if (!used.has(name)) throw new Error(`${contender.name}: uniform ${name} is not in df_uniforms`);
  return bytes;
}

function lumaParams(values) {
  const doubles = Object.entries(values).filter(([name]) => name !== 'count').flatMap(([, pairs]) => pairs);
  const bytes = new ArrayBuffer(Math.ceil((8 * doubles.length + 4) / 16) * 16);
  const f32 = new Float32Array(bytes);
  for (let k = 0; k < doubles.length / 2; ++k) f32.set(doubles.slice(2 * k, 2 * k + 2), 4 * k);
  new Uint32Array(bytes)[doubles.length * 2] = values.count[0];
  return bytes;
}

async function runWebGPU(job) {
  if (!navigator.gpu) throw new Error('navigator.gpu is missing: no WebGPU in this browser');
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) throw new Error('no WebGPU adapter');
  const device = await adapter.requestDevice();
  let lost = null;
  device.lost.then((info) => { lost = info.message || info.reason; });
  const uncaptured = [];
  device.addEventListener('uncapturederror', (e) => uncaptured.push(e.error.message));
  const info = adapter.info || {};
  const result = { renderer: [info.vendor, info.architecture, info.device, info.description].filter((x) => x).join(' / '), kernels: [] };
  const size = job.size;
  const count = size * size;
  const groups = Math.ceil(count / 64);  // every kernel: @workgroup_size(64)
  const check = async (what) => {
    if (lost) throw new Error(`${what}: the WebGPU device was lost: ${lost}`);
    if (uncaptured.length) throw new Error(`${what}: WebGPU error: ${uncaptured.join('; ')}`);
  };
  const buffer = (bytes, usage) => {
    const b = device.createBuffer({ size: Math.max(16, Math.ceil(bytes.byteLength / 16) * 16), usage: usage | GPUBufferUsage.COPY_DST });
    device.queue.writeBuffer(b, 0, bytes);
    return b;
  };
  for (const k of job.kernels) {
    const kernel = kernels[k.name](random(job.seed), size);
    // Inputs: each element's doubles as (hi, lo) pairs, the words the fragment shaders read less the padding.
    const inputs = new Float32Array(count * 2 * kernel.doubles);
    for (let i = 0; i < count; ++i) inputs.set(kernel.words.subarray(8 * i, 8 * i + 2 * kernel.doubles), 2 * kernel.doubles * i);
    const input = buffer(inputs, GPUBufferUsage.STORAGE);
    const outputBytes = count * kernel.components * 8;
    const output = device.createBuffer({ size: outputBytes, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST });
    const readBack = device.createBuffer({ size: outputBytes, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });

    const dispatch = async (c, n) => {
      const start = performance.now();
      const encoder = device.createCommandEncoder();
      const pass = encoder.beginComputePass();
      pass.setPipeline(c.pipeline);
      pass.setBindGroup(0, c.group);
      for (let d = 0; d < n; ++d) pass.dispatchWorkgroups(groups);
      pass.end();
      device.queue.submit([encoder.finish()]);
      await device.queue.onSubmittedWorkDone();
      return (performance.now() - start) / n;
    };

    const reference = new Float64Array(count * kernel.components);
    for (let i = 0; i < count; ++i) reference.set(kernel.reference(i), kernel.components * i);

    // Pipeline (awaited), the first dispatch, then, unless the job fixes them, dispatches doubled
    // until one measurement takes targetMs.
    const contenders = [];
    for (const c of k.contenders) {
      device.pushErrorScope('validation');
      const module = device.createShaderModule({ code: c.code });
      const messages = (await module.getCompilationInfo()).messages.filter((m) => m.type === 'error')
        .map((m) => `${m.lineNum}:${m.linePos}: ${m.message}`);
      if (messages.length) throw new Error(`${c.name}: WGSL errors:\n${messages.join('\n')}`);
      const pipeline = await device.createComputePipelineAsync({ layout: 'auto', compute: { module, entryPoint: 'main' } });
      const values = { ...uniformValues(c.flavour, kernel.uniforms, c.sabotage), count: [count] };
      const entries = c.bindings.map((b) => {
        let resource;
        if (b.role === 'input') resource = input;
        else if (b.role === 'output') resource = output;
        else if (b.role === 'uniforms') resource = buffer(c.flavour === 'luma' ? lumaParams(values) : doubletUniforms(c, b.members, values), GPUBufferUsage.UNIFORM);
        else if (b.role === 'luma') resource = buffer(new Float32Array(b.values), GPUBufferUsage.UNIFORM);
        else throw new Error(`${c.name}: binding ${b.binding} of role ${b.role}`);
        return { binding: b.binding, resource: { buffer: resource } };
      });
      const group = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries });
      const error = await device.popErrorScope();
      if (error) throw new Error(`${c.name}: WebGPU validation: ${error.message}`);
      const contender = { ...c, pipeline, group, ms: [] };
      await dispatch(contender, 1);
      let draws = job.draws;
      if (!draws)
        for (draws = 1; draws < 4096 && draws * (await dispatch(contender, draws)) < job.targetMs;) draws *= 2;
      await check(c.name);
      contenders.push({ ...contender, draws });
    }
    // Interleaved rounds: round r starts at contender r (mod n), so none always runs first or last.
    for (let r = 0; r < job.rounds; ++r)
      for (let j = 0; j < contenders.length; ++j) {
        const c = contenders[(r + j) % contenders.length];
        c.ms.push(await dispatch(c, c.draws));
      }
    // Bits: one dispatch into a cleared output, read back whole; got = hi + lo in doubles.
    const rows = [];
    for (const c of contenders) {
      const encoder = device.createCommandEncoder();
      encoder.clearBuffer(output);
      const pass = encoder.beginComputePass();
      pass.setPipeline(c.pipeline);
      pass.setBindGroup(0, c.group);
      pass.dispatchWorkgroups(groups);
      pass.end();
      encoder.copyBufferToBuffer(output, 0, readBack, 0, outputBytes);
      device.queue.submit([encoder.finish()]);
      await readBack.mapAsync(GPUMapMode.READ);
      const words = new Float32Array(readBack.getMappedRange().slice(0));
      readBack.unmap();
      await check(c.name);
      const bits = new Float64Array(count * kernel.components);
      for (let v = 0; v < bits.length; ++v) {
        const got = words[2 * v] + words[2 * v + 1];
        const error = Math.abs(got - reference[v]) / Math.abs(reference[v]);
        // NaN (a broken kernel) counts as 0 bits; an exact result as 53.
        bits[v] = error === 0 ? 53 : Number.isNaN(error) ? 0 : Math.min(53, Math.max(0, -Math.log2(error)));
      }
      rows.push({ name: c.name, draws: c.draws, ms: c.ms.map((x) => +x.toFixed(4)), best_ms: Math.min(...c.ms),
                  median_ms: median(c.ms), bits_min: bits.reduce((a, b) => Math.min(a, b), 53), bits_median: median(bits),
                  values: bits.length });
    }
    result.kernels.push({ name: k.name, size, contenders: rows });
  }
  device.destroy();
  return result;
}

window.doubletResult = (async () => {
  const job = await (await fetch(new URLSearchParams(location.search).get('job'))).json();
  return job.api === 'webgpu' ? runWebGPU(job) : run(job);
})();
