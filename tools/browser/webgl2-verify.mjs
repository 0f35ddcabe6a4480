// The WebGL2 page of doublet's graphics runner (src/runner/webgl2.hpp describes the transport).
// Reads jobs.json: { textures: {size, 2d, 3d, cube}, programs: [{ stage, count, input_words,
// output_words, passes: [{vertex, fragment, varyings, first_slot, slots}], jobs: [{inputs, uniforms,
// blocks}] }] }; every array of numbers is base64 of little-endian bytes (input words: uint32,
// uniform values: float64, texels: float32, blocks: bytes). Reports window.doubletResult =
// { renderer, version, programs: [{ jobs: [base64 uint32 output words] } | { error }] }.
// A program that fails (compile, link, GL error) reports its error; the others still run.
const GRID = 64;  // samples per row of the input texture and of the fragment framebuffer

const bytesOf = (b64) => Uint8Array.from(atob(b64), c => c.charCodeAt(0));
const toBase64 = (bytes) => {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s);
};
const typed = (Type, b64) => { const b = bytesOf(b64); return new Type(b.buffer, b.byteOffset, b.byteLength / Type.BYTES_PER_ELEMENT); };

function compile(gl, type, text, what) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, text);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS))
    throw new Error(`GLSL compile failed (${what} shader):\n${gl.getShaderInfoLog(shader)}`);
  return shader;
}

function link(gl, pass) {
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, pass.vertex, 'vertex'));
  gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, pass.fragment, 'fragment'));
  if (pass.varyings.length) gl.transformFeedbackVaryings(program, pass.varyings, gl.INTERLEAVED_ATTRIBS);
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`GLSL link failed:\n${gl.getProgramInfoLog(program)}`);
  return program;
}

function checkError(gl, where) {
  const e = gl.getError();
  if (e !== gl.NO_ERROR) throw new Error(`GL error 0x${e.toString(16)} ${where}`);
}

// The runner's test texture (runner.hpp: RGBA32F, NEAREST, REPEAT; cube maps clamp) on `unit`.
function bindTestTexture(gl, data, type, unit) {
  const n = data.textures.size;
  const kind = type === gl.SAMPLER_3D ? '3d' : type === gl.SAMPLER_CUBE ? 'cube' : '2d';
  const target = kind === '3d' ? gl.TEXTURE_3D : kind === 'cube' ? gl.TEXTURE_CUBE_MAP : gl.TEXTURE_2D;
  const texels = typed(Float32Array, data.textures[kind]);
  const texture = gl.createTexture();
  gl.activeTexture(gl.TEXTURE0 + unit);
  gl.bindTexture(target, texture);
  if (kind === '3d') gl.texImage3D(target, 0, gl.RGBA32F, n, n, n, 0, gl.RGBA, gl.FLOAT, texels);
  else if (kind === 'cube')
    for (let face = 0; face < 6; ++face)
      gl.texImage2D(gl.TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, gl.RGBA32F, n, n, 0, gl.RGBA, gl.FLOAT,
                    texels.subarray(face * n * n * 4, (face + 1) * n * n * 4));
  else gl.texImage2D(target, 0, gl.RGBA32F, n, n, 0, gl.RGBA, gl.FLOAT, texels);
  const wrap = kind === 'cube' ? gl.CLAMP_TO_EDGE : gl.REPEAT;
  gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  for (const p of [gl.TEXTURE_WRAP_S, gl.TEXTURE_WRAP_T, gl.TEXTURE_WRAP_R]) gl.texParameteri(target, p, wrap);
  return texture;
}

// Sets a loose uniform from its float64 values as the GLES runner does (gles_context.cpp): floats,
// float matrices (column-major), int/uint/bool scalars and vectors; an inactive name is ignored.
function setUniform(gl, program, name, values) {
  const [index] = gl.getUniformIndices(program, [name]);
  if (index === gl.INVALID_INDEX || index === null) return;
  const info = gl.getActiveUniform(program, index);
  const location = gl.getUniformLocation(program, name);
  const f = Float32Array.from(values);
  const floats = { [gl.FLOAT]: 1, [gl.FLOAT_VEC2]: 2, [gl.FLOAT_VEC3]: 3, [gl.FLOAT_VEC4]: 4 };
  const matrices = { [gl.FLOAT_MAT2]: ['uniformMatrix2fv', 4], [gl.FLOAT_MAT3]: ['uniformMatrix3fv', 9],
    [gl.FLOAT_MAT4]: ['uniformMatrix4fv', 16], [gl.FLOAT_MAT2x3]: ['uniformMatrix2x3fv', 6],
    [gl.FLOAT_MAT2x4]: ['uniformMatrix2x4fv', 8], [gl.FLOAT_MAT3x2]: ['uniformMatrix3x2fv', 6],
    [gl.FLOAT_MAT3x4]: ['uniformMatrix3x4fv', 12], [gl.FLOAT_MAT4x2]: ['uniformMatrix4x2fv', 8],
    [gl.FLOAT_MAT4x3]: ['uniformMatrix4x3fv', 12] };
  const ints = { [gl.INT]: 1, [gl.INT_VEC2]: 2, [gl.INT_VEC3]: 3, [gl.INT_VEC4]: 4, [gl.BOOL]: 1, [gl.BOOL_VEC2]: 2,
    [gl.BOOL_VEC3]: 3, [gl.BOOL_VEC4]: 4 };
  const uints = { [gl.UNSIGNED_INT]: 1, [gl.UNSIGNED_INT_VEC2]: 2, [gl.UNSIGNED_INT_VEC3]: 3, [gl.UNSIGNED_INT_VEC4]: 4 };
  // An array uniform takes its first elements from the values, as glUniform*v does on the other
  // backends (runner.hpp): a whole number of elements, at most the array's size.
  const wrongCount = (n) => new Error(`uniform '${name}' has ${n} component(s)${info.size > 1 ? ` per element, ${info.size} elements` : ''}, job gives ${values.length}`);
  const fits = (n) => values.length > 0 && values.length % n === 0 && values.length <= n * info.size;
  if (floats[info.type]) {
    const n = floats[info.type];
    if (!fits(n)) throw wrongCount(n);
    gl[`uniform${n}fv`](location, f);
  } else if (matrices[info.type]) {
    const [setter, n] = matrices[info.type];
    if (!fits(n)) throw wrongCount(n);
    gl[setter](location, false, f);
  } else if (ints[info.type]) {
    const n = ints[info.type], isBool = info.type >= gl.BOOL && info.type <= gl.BOOL_VEC4;
    if (!fits(n)) throw wrongCount(n);
    gl[`uniform${n}iv`](location, Int32Array.from(values, v => isBool ? (v !== 0 ? 1 : 0) : Math.trunc(v)));
  } else if (uints[info.type]) {
    const n = uints[info.type];
    if (!fits(n)) throw wrongCount(n);
    gl[`uniform${n}uiv`](location, Uint32Array.from(values, v => Math.trunc(v)));
  } else {
    throw new Error(`uniform '${name}' is not a float scalar, vector or matrix`);
  }
}

// One pass of a program over every job; output words land in outputs[job] (count × output_words).
function runPass(gl, data, p, pass, outputs) {
  const program = link(gl, pass);
  gl.useProgram(program);
  const rows = Math.ceil(p.count / GRID), texelsPerSample = p.input_words / 4;
  const made = { textures: [], buffers: [], framebuffers: [], feedbacks: [] };
  try {
    const inputTexture = gl.createTexture();
    made.textures.push(inputTexture);
    const vertex = p.stage === 'vertex';
    const slots = pass.slots, wordsPerSample = p.output_words;
    let framebuffer = null, attachments = [], feedback = null, captured = null;
    if (vertex) {
      feedback = gl.createTransformFeedback();
      made.feedbacks.push(feedback);
      captured = gl.createBuffer();
      made.buffers.push(captured);
      gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, captured);
      gl.bufferData(gl.TRANSFORM_FEEDBACK_BUFFER, p.count * slots * 16, gl.STREAM_READ);
      gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, null);
    } else {
      gl.activeTexture(gl.TEXTURE0);  // the attachments must not replace a sampler's texture
      framebuffer = gl.createFramebuffer();
      made.framebuffers.push(framebuffer);
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      for (let a = 0; a < slots; ++a) {
        const t = gl.createTexture();
        made.textures.push(t);
        gl.bindTexture(gl.TEXTURE_2D, t);
        gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32UI, GRID, rows);
        gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + a, gl.TEXTURE_2D, t, 0);
        attachments.push(gl.COLOR_ATTACHMENT0 + a);
      }
      gl.bindTexture(gl.TEXTURE_2D, null);
      gl.drawBuffers(attachments);
      if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) throw new Error('RGBA32UI framebuffer incomplete');
      gl.viewport(0, 0, GRID, rows);
    }
    // Unit 0: the input texture; units 1..: the test texture for each sampler the program uses.
    let unit = 1;
    const uniformCount = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
    for (let i = 0; i < uniformCount; ++i) {
      const info = gl.getActiveUniform(program, i);
      if (info.name === 'doublet_inputs') {
        gl.uniform1i(gl.getUniformLocation(program, info.name), 0);
      } else if ([gl.SAMPLER_2D, gl.SAMPLER_3D, gl.SAMPLER_CUBE].includes(info.type)) {
        made.textures.push(bindTestTexture(gl, data, info.type, unit));
        gl.uniform1i(gl.getUniformLocation(program, info.name), unit++);
      }
    }
    const blockCount = gl.getProgramParameter(program, gl.ACTIVE_UNIFORM_BLOCKS);
    const blocks = [];
    for (let i = 0; i < blockCount; ++i) {
      gl.uniformBlockBinding(program, i, i);
      const buffer = gl.createBuffer();
      made.buffers.push(buffer);
      blocks.push({ name: gl.getActiveUniformBlockName(program, i), buffer,
                    size: gl.getActiveUniformBlockParameter(program, i, gl.UNIFORM_BLOCK_DATA_SIZE) });
    }
    checkError(gl, 'setting up the pass');

    p.jobs.forEach((job, j) => {
      gl.useProgram(program);
      for (const [name, b64] of Object.entries(job.uniforms)) setUniform(gl, program, name, Array.from(typed(Float64Array, b64)));
      for (const block of blocks) {
        const bytes = new Uint8Array(Math.max(block.size, 16));
        if (job.blocks[block.name] !== undefined) bytes.set(bytesOf(job.blocks[block.name]).subarray(0, bytes.length));
        gl.bindBuffer(gl.UNIFORM_BUFFER, block.buffer);
        gl.bufferData(gl.UNIFORM_BUFFER, bytes, gl.DYNAMIC_DRAW);
        gl.bindBufferBase(gl.UNIFORM_BUFFER, blocks.indexOf(block), block.buffer);
      }
      if (texelsPerSample > 0) {
        const words = new Uint32Array(rows * GRID * p.input_words);
        words.set(typed(Uint32Array, job.inputs));
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, inputTexture);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32UI, GRID * texelsPerSample, rows, 0, gl.RGBA_INTEGER, gl.UNSIGNED_INT, words);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      }
      checkError(gl, 'uploading the inputs');
      const out = outputs[j], first = pass.first_slot * 4;
      if (vertex) {
        gl.enable(gl.RASTERIZER_DISCARD);
        gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, feedback);
        gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, captured);
        gl.beginTransformFeedback(gl.POINTS);
        gl.drawArrays(gl.POINTS, 0, p.count);
        gl.endTransformFeedback();
        gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, null);
        gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, null);
        gl.disable(gl.RASTERIZER_DISCARD);
        const got = new Uint32Array(p.count * slots * 4);
        gl.bindBuffer(gl.COPY_READ_BUFFER, captured);
        gl.getBufferSubData(gl.COPY_READ_BUFFER, 0, got);
        gl.bindBuffer(gl.COPY_READ_BUFFER, null);
        for (let s = 0; s < p.count; ++s)
          out.set(got.subarray(s * slots * 4, (s + 1) * slots * 4), s * wordsPerSample + first);
      } else {
        // A sample the stage never writes (discard) reads back as all ones: NaN, as on the other backends.
        for (let a = 0; a < slots; ++a) gl.clearBufferuiv(gl.COLOR, a, new Uint32Array([~0 >>> 0, ~0 >>> 0, ~0 >>> 0, ~0 >>> 0]));
        gl.drawArrays(gl.TRIANGLES, 0, 3);
        const got = new Uint32Array(GRID * rows * 4);
        for (let a = 0; a < slots; ++a) {
          gl.readBuffer(gl.COLOR_ATTACHMENT0 + a);
          gl.readPixels(0, 0, GRID, rows, gl.RGBA_INTEGER, gl.UNSIGNED_INT, got);
          for (let s = 0; s < p.count; ++s) out.set(got.subarray(s * 4, s * 4 + 4), s * wordsPerSample + first + a * 4);
        }
      }
      checkError(gl, 'drawing');
    });
  } finally {
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    made.textures.forEach(t => gl.deleteTexture(t));
    made.buffers.forEach(b => gl.deleteBuffer(b));
    made.framebuffers.forEach(f => gl.deleteFramebuffer(f));
    made.feedbacks.forEach(f => gl.deleteTransformFeedback(f));
    gl.deleteProgram(program);
  }
}

function runProgram(gl, data, p) {
  const outputs = p.jobs.map(() => new Uint32Array(p.count * p.output_words).fill(~0 >>> 0));
  for (const pass of p.passes) runPass(gl, data, p, pass, outputs);
  return outputs.map(o => toBase64(new Uint8Array(o.buffer)));
}

async function main() {
  const data = await (await fetch('jobs.json')).json();
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) throw new Error('this browser has no WebGL2 context');
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const result = { renderer: info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
                   version: gl.getParameter(gl.VERSION), programs: [] };
  gl.bindVertexArray(gl.createVertexArray());
  for (const p of data.programs) {
    try {
      result.programs.push({ jobs: runProgram(gl, data, p) });
    } catch (e) {
      result.programs.push({ error: String(e.message || e) });
      while (gl.getError() !== gl.NO_ERROR) {}  // do not leak an error into the next program
    }
  }
  return result;
}

window.doubletResult = main();
