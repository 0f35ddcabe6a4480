// Times how long the browser takes to turn one shader into something it can run (tools/browser/
// compile-time.mjs writes the job next to this page and names it in ?job=: {api: 'webgl2'|'webgpu', stage, code}).
// WebGL2: compile + link + the first draw and a read-back (ANGLE creates the Vulkan pipeline, and
// SwiftShader compiles it, only when a draw needs it). WebGPU: createShaderModule + an awaited
// pipeline creation (Dawn compiles there; compute, fragment and vertex entry points). The partner
// stage is generated here from the shader's own interface and consumes or feeds every varying, so
// nothing of the measured shader is dead code.
// Reports window.doubletResult = {api, stage, ms, compile_ms, draw_ms} or throws with the error.

const glslBase = (type) => (type.startsWith('u') ? 'u' : type.startsWith('i') ? 'i' : 'f');
const glslWidth = (type) => (/\d$/.test(type) ? Number(type.slice(-1)) : 1);

// `[flat] in highp vec2 name;` (or out): the interface of a GLSL ES 3.00 stage.
function varyings(code, direction) {
  const re = new RegExp(String.raw`^\s*((?:(?:flat|smooth|centroid|highp|mediump|lowp)\s+)*)${direction}\s+((?:highp|mediump|lowp)\s+)?(\w+)\s+(\w+)\s*;`, 'gm');
  return [...code.matchAll(re)].map((m) => ({ qualifiers: m[1], type: m[3], name: m[4] }));
}

function compileGl(gl, type, text) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, text);
  gl.compileShader(shader);
  return shader;
}

function webgl2(job) {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = 1;
  const gl = canvas.getContext('webgl2', { antialias: false });
  if (!gl) throw new Error('no WebGL2 context');
  gl.getExtension('EXT_color_buffer_float');
  let vertex, fragment;
  if (job.stage === 'frag') {
    const inputs = varyings(job.code, 'in');
    vertex = '#version 300 es\nprecision highp float;\nprecision highp int;\n' +
      inputs.map((v) => `${v.qualifiers.includes('flat') ? 'flat ' : ''}out highp ${v.type} ${v.name};\n`).join('') +
      'void main() {\n  float k = float(gl_VertexID) + 1.0;\n' +
      inputs.map((v) => `  ${v.name} = ${v.type}(${glslBase(v.type) === 'f' ? 'k' : 'gl_VertexID'});\n`).join('') +
      '  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);\n  gl_PointSize = 1.0;\n}\n';
    fragment = job.code;
  } else {
    const outputs = varyings(job.code, 'out');
    vertex = job.code;
    fragment = '#version 300 es\nprecision highp float;\nprecision highp int;\n' +
      outputs.map((v) => `${v.qualifiers.includes('flat') || glslBase(v.type) !== 'f' ? 'flat ' : ''}in highp ${v.type} ${v.name};\n`).join('') +
      'layout(location = 0) out vec4 doublet_color;\nvoid main() {\n  vec4 acc = vec4(0.0);\n' +
      outputs.map((v) => {
        const n = glslWidth(v.type);
        return `  acc.${'xyzw'.slice(0, n)} += ${n === 1 ? 'float' : 'vec' + n}(${v.name});\n`;
      }).join('') + '  doublet_color = acc;\n}\n';
  }
  // One 1x1 attachment per fragment output, of the output's base type (WebGL2 refuses a draw otherwise).
  // (a single output without a location is at 0)
  const outputs = [...fragment.matchAll(/^\s*(?:layout\s*\(\s*location\s*=\s*(\d+)\s*\)\s*)?out\s+(?:highp\s+|mediump\s+|lowp\s+)?(\w+)\s+\w+\s*;/gm)]
    .map((m) => ({ location: Number(m[1] || 0), type: m[2] }));
  const framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  const drawBuffers = [];
  for (const o of outputs) {
    const texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, texture);
    const format = { f: gl.RGBA32F, i: gl.RGBA32I, u: gl.RGBA32UI }[glslBase(o.type)];
    gl.texStorage2D(gl.TEXTURE_2D, 1, format, 1, 1);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + o.location, gl.TEXTURE_2D, texture, 0);
    drawBuffers[o.location] = gl.COLOR_ATTACHMENT0 + o.location;
  }
  for (let i = 0; i < drawBuffers.length; ++i) if (!drawBuffers[i]) drawBuffers[i] = gl.NONE;
  gl.drawBuffers(drawBuffers);

  const start = performance.now();
  const program = gl.createProgram();
  const vs = compileGl(gl, gl.VERTEX_SHADER, vertex);
  const fs = compileGl(gl, gl.FRAGMENT_SHADER, fragment);
  gl.attachShader(program, vs);
  gl.attachShader(program, fs);
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    const log = [vs, fs].map((s) => gl.getShaderInfoLog(s)).join('\n') + gl.getProgramInfoLog(program);
    throw new Error(`WebGL2 compile/link failed:\n${log}\n--- vertex ---\n${vertex}`);
  }
  const linked = performance.now();
  gl.useProgram(program);
  // Every uniform block bound to a zero-filled buffer of its size (an unbound block fails the draw).
  for (let i = 0; i < gl.getProgramParameter(program, gl.ACTIVE_UNIFORM_BLOCKS); ++i) {
    const buffer = gl.createBuffer();
    gl.bindBuffer(gl.UNIFORM_BUFFER, buffer);
    gl.bufferData(gl.UNIFORM_BUFFER, gl.getActiveUniformBlockParameter(program, i, gl.UNIFORM_BLOCK_DATA_SIZE), gl.STATIC_DRAW);
    gl.uniformBlockBinding(program, i, i);
    gl.bindBufferBase(gl.UNIFORM_BUFFER, i, buffer);
  }
  // Each sampler on its own texture unit (two sampler types on one unit fail the draw); the units
  // stay empty, which samples as zero.
  const samplers = ['SAMPLER_2D', 'SAMPLER_3D', 'SAMPLER_CUBE', 'SAMPLER_2D_SHADOW', 'SAMPLER_2D_ARRAY',
                    'SAMPLER_2D_ARRAY_SHADOW', 'SAMPLER_CUBE_SHADOW', 'INT_SAMPLER_2D', 'INT_SAMPLER_3D', 'INT_SAMPLER_CUBE',
                    'INT_SAMPLER_2D_ARRAY', 'UNSIGNED_INT_SAMPLER_2D', 'UNSIGNED_INT_SAMPLER_3D', 'UNSIGNED_INT_SAMPLER_CUBE',
                    'UNSIGNED_INT_SAMPLER_2D_ARRAY'].map((k) => gl[k]);
  let unit = 0;
  for (let i = 0; i < gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS); ++i) {
    const info = gl.getActiveUniform(program, i);
    if (samplers.includes(info.type))
      for (let k = 0; k < info.size; ++k) gl.uniform1i(gl.getUniformLocation(program, info.name.replace(/\[0\]$/, '') + (info.size > 1 ? `[${k}]` : '')), unit++);
  }
  // Integer attributes need integer current values (WebGL2 checks the type at the draw).
  for (let i = 0; i < gl.getProgramParameter(program, gl.ACTIVE_ATTRIBUTES); ++i) {
    const info = gl.getActiveAttrib(program, i);
    const location = gl.getAttribLocation(program, info.name);
    if (location < 0) continue;
    const t = info.type;
    if ([gl.INT, gl.INT_VEC2, gl.INT_VEC3, gl.INT_VEC4].includes(t)) gl.vertexAttribI4i(location, 1, 1, 1, 1);
    else if ([gl.UNSIGNED_INT, gl.UNSIGNED_INT_VEC2, gl.UNSIGNED_INT_VEC3, gl.UNSIGNED_INT_VEC4].includes(t)) gl.vertexAttribI4ui(location, 1, 1, 1, 1);
    else gl.vertexAttrib4f(location, 1, 1, 1, 1);
  }
  gl.drawArrays(gl.POINTS, 0, 1);
  if (outputs.length) {
    gl.readBuffer(gl.COLOR_ATTACHMENT0 + outputs[0].location);
    const base = glslBase(outputs[0].type);
    const pixel = base === 'f' ? new Float32Array(4) : base === 'i' ? new Int32Array(4) : new Uint32Array(4);
    gl.readPixels(0, 0, 1, 1, base === 'f' ? gl.RGBA : gl.RGBA_INTEGER, base === 'f' ? gl.FLOAT : base === 'i' ? gl.INT : gl.UNSIGNED_INT, pixel);
  } else {
    gl.finish();
  }
  const end = performance.now();
  const error = gl.getError();
  if (error !== gl.NO_ERROR) throw new Error(`WebGL2 error 0x${error.toString(16)} at the first draw`);
  return { api: 'webgl2', stage: job.stage, ms: end - start, compile_ms: linked - start, draw_ms: end - linked,
           renderer: gl.getParameter(gl.RENDERER) };
}

async function webgpu(job) {
  if (!navigator.gpu) throw new Error('navigator.gpu is missing: no WebGPU in this browser');
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) throw new Error('no WebGPU adapter');
  const device = await adapter.requestDevice();
  device.pushErrorScope('validation');
  const start = performance.now();
  const module = device.createShaderModule({ code: job.code });
  const info = await module.getCompilationInfo();
  const errors = info.messages.filter((m) => m.type === 'error').map((m) => `${m.lineNum}:${m.linePos}: ${m.message}`);
  if (errors.length) throw new Error(`WGSL compile failed:\n${errors.join('\n')}`);
  const compiled = performance.now();
  if (job.stage === 'comp') {
    await device.createComputePipelineAsync({ layout: 'auto', compute: { module, entryPoint: 'main' } });
  } else if (job.stage === 'frag') {
    // The fragment entry point's @location inputs, fed by a generated vertex stage.
    const params = /fn main\(([\s\S]*?)\)\s*->/.exec(job.code)[1];
    const inputs = [...params.matchAll(/@location\((\d+)\)\s*(@interpolate\(flat\))?\s*(\w+)\s*:\s*((?:vec\d<)?[fui]32>?)/g)]
      .map((m) => ({ location: Number(m[1]), flat: Boolean(m[2]), type: m[4] }));
    const vertexCode = 'struct V {\n  @builtin(position) position: vec4<f32>,\n' +
      inputs.map((v) => `  @location(${v.location}) ${v.flat ? '@interpolate(flat) ' : ''}v${v.location}: ${v.type},\n`).join('') +
      '};\n@vertex fn main(@builtin(vertex_index) i: u32) -> V {\n  var out: V;\n  out.position = vec4<f32>(0.0, 0.0, 0.0, 1.0);\n' +
      inputs.map((v) => `  out.v${v.location} = ${v.type}(${v.type.includes('f32') ? 'f32(i) + 1.0' : v.type.includes('u32') ? 'i' : 'i32(i)'});\n`).join('') +
      '  return out;\n}\n';
    const outputs = [...job.code.matchAll(/@location\((\d+)\)\s*\w+\s*:\s*vec4<([fui])32>/g)].map((m) => ({ location: Number(m[1]), base: m[2] }));
    const targets = [];
    for (const o of outputs) targets[o.location] = { format: { f: 'rgba32float', i: 'rgba32sint', u: 'rgba32uint' }[o.base] };
    const vertex = device.createShaderModule({ code: vertexCode });
    await device.createRenderPipelineAsync({ layout: 'auto', vertex: { module: vertex, entryPoint: 'main' },
                                             fragment: { module, entryPoint: 'main', targets }, primitive: { topology: 'point-list' } });
  } else {
    // One vertex buffer per @location input of the entry point; a fragment stage that reads nothing.
    const params = /fn main\(([\s\S]*?)\)\s*->/.exec(job.code)[1];
    const buffers = [...params.matchAll(/@location\((\d+)\)\s*\w+\s*:\s*(?:vec(\d)<([fui])32>|([fui])32)/g)].map((m) => {
      const kind = { f: 'float32', u: 'uint32', i: 'sint32' }[m[3] || m[4]];
      return { arrayStride: 16, attributes: [{ shaderLocation: Number(m[1]), offset: 0, format: m[2] ? `${kind}x${m[2]}` : kind }] };
    });
    const fragment = device.createShaderModule({ code: '@fragment fn main() -> @location(0) vec4<f32> { return vec4<f32>(0.0); }' });
    await device.createRenderPipelineAsync({ layout: 'auto', vertex: { module, entryPoint: 'main', buffers },
                                             fragment: { module: fragment, entryPoint: 'main', targets: [{ format: 'rgba32float' }] },
                                             primitive: { topology: 'point-list' } });
  }
  const end = performance.now();
  const error = await device.popErrorScope();
  if (error) throw new Error(`WebGPU validation: ${error.message}`);
  return { api: 'webgpu', stage: job.stage, ms: end - start, compile_ms: compiled - start, draw_ms: end - compiled,
           adapter: [adapter.info?.vendor, adapter.info?.architecture].filter((x) => x).join(' / ') };
}

window.doubletResult = (async () => {
  const job = await (await fetch(new URLSearchParams(location.search).get('job'))).json();
  return job.api === 'webgpu' ? webgpu(job) : webgl2(job);
})();
