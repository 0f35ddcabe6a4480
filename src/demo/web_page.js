// The page `doublet demo --web DIR` writes (src/demo/web_page.cpp embeds this script, the lowered
// shaders and the scene into one index.html; nothing is fetched, so it runs from file:// too).
// Every number is computed here, in the browser: each mode's shaders run in WebGL2 and are
// compared with the same computation in JavaScript doubles (binary64). The result is also
// published as window.doubletResult (the protocol of tools/browser/run-page.mjs).
'use strict';

const config = JSON.parse(document.getElementById('doublet-config').textContent);

// ---- doubles as the shaders receive them ----------------------------------------------------
// hi = float(x), lo = float(x - hi): doublet::split (include/doublet/split.hpp). The page's
// "drop-lo" sabotage uploads lo = 0, so a float-float shader sees only the float part.
const splitDouble = x => {
  const hi = Math.fround(x);
  return [hi, config.sabotage === 'drop-lo' ? 0 : Math.fround(x - hi)];
};

function compile(gl, type, source, what) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS))
    throw new Error(`${what}: the browser rejected the shader: ${gl.getShaderInfoLog(shader)}`);
  return shader;
}

function link(gl, vertexSource, fragmentSource, what, feedbackVaryings) {
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, vertexSource, what));
  gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, fragmentSource, what));
  if (feedbackVaryings) gl.transformFeedbackVaryings(program, feedbackVaryings, gl.INTERLEAVED_ATTRIBS);
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS))
    throw new Error(`${what}: link failed: ${gl.getProgramInfoLog(program)}`);
  return program;
}

// Sets a shader input that is a double in the original shader: its lowered names come from the
// mode's manifest (`split`: NAME -> [NAME_hi, NAME_lo]); in fp32 it is one float variable.
function setUniform(gl, program, name, values, split) {
  const set = (n, v) => {
    const location = gl.getUniformLocation(program, n);
    if (location === null) return;  // optimised away
    [, gl.uniform1fv, gl.uniform2fv, gl.uniform3fv, gl.uniform4fv][v.length].call(gl, location, v);
  };
  if (!split[name]) return set(name, values.map(Math.fround));
  const pairs = values.map(splitDouble);
  set(split[name][0], pairs.map(p => p[0]));
  set(split[name][1], pairs.map(p => p[1]));
}

function attribute(gl, program, name, size, values) {
  const location = gl.getAttribLocation(program, name);
  if (location < 0) return;
  gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(values), gl.STATIC_DRAW);
  gl.enableVertexAttribArray(location);
  gl.vertexAttribPointer(location, size, gl.FLOAT, false, 0, 0);
}

// ---- the jitter scene: camera path and reference ---------------------------------------------
// The camera of src/demo/jitter_scene.cpp (jitter_camera): its distance grows from 10 to 50 m
// while it circles the two boxes; rotation and projection only, the eye is subtracted in the
// shader. s in [0, 1]. The matrix is rounded to float, as the shader receives it.
function jitterCamera(s, aspect) {
  const J = config.jitter;
  const add = (a, b, k = 1) => a.map((x, i) => x + k * b[i]);
  const scale = (a, k) => a.map(x => x * k);
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const normalize = a => scale(a, 1 / Math.hypot(...a));
  const distance = 10 + 40 * s, azimuth = 0.35 + 0.5 * s, elevation = 0.3;
  const dir = add(add(scale(J.radial, -Math.cos(azimuth) * Math.cos(elevation)), J.along_track,
                      Math.sin(azimuth) * Math.cos(elevation)), J.north, Math.sin(elevation));
  const eye = add(J.centre, dir, distance);
  const forward = scale(dir, -1), right = normalize(cross(forward, J.north)), up = cross(right, forward);
  const f = 1 / Math.tan(15 * Math.PI / 180), near = 0.5, far = 500;
  const a = (far + near) / (near - far), b = 2 * far * near / (near - far);
  const m = new Float32Array(16);  // column-major
  for (let c = 0; c < 3; ++c) {
    m[c * 4 + 0] = f / aspect * right[c];
    m[c * 4 + 1] = f * up[c];
    m[c * 4 + 2] = a * -forward[c];
    m[c * 4 + 3] = forward[c];
  }
  m[14] = b;
  return { eye, viewProjection: m };
}

// gl_Position of every vertex, in doubles, with the float matrix the shader gets.
function referenceClip(camera) {
  const p = config.jitter.positions, m = camera.viewProjection, clip = [];
  for (let v = 0; v * 3 < p.length; ++v) {
    const rel = [p[v * 3] - camera.eye[0], p[v * 3 + 1] - camera.eye[1], p[v * 3 + 2] - camera.eye[2], 1];
    for (let r = 0; r < 4; ++r) {
      let sum = 0;
      for (let c = 0; c < 4; ++c) sum += m[c * 4 + r] * rel[c];
      clip.push(sum);
    }
  }
  return clip;
}

// Wobble as in src/demo/jitter.cpp: per vertex, the screen-space error against the reference;
// the largest change of that error from one frame to the next, in pixels.
function wobble(clipFrames, referenceFrames, width, height) {
  const pixel = (c, i, axis) => (c[i + axis] / c[i + 3] * 0.5 + 0.5) * (axis ? height : width);
  let maxWobble = 0, maxError = 0, previous = null;
  clipFrames.forEach((clip, f) => {
    const error = [];
    for (let i = 0; i < clip.length; i += 4) {
      const dx = pixel(clip, i, 0) - pixel(referenceFrames[f], i, 0);
      const dy = pixel(clip, i, 1) - pixel(referenceFrames[f], i, 1);
      error.push(dx, dy);
      maxError = Math.max(maxError, Math.hypot(dx, dy));
    }
    if (previous)
      for (let k = 0; k < error.length; k += 2)
        maxWobble = Math.max(maxWobble, Math.hypot(error[k] - previous[k], error[k + 1] - previous[k + 1]));
    previous = error;
  });
  return { wobble_px: maxWobble, max_error_px: maxError };
}

class JitterRenderer {
  constructor(gl, mode) {
    const J = config.jitter;
    this.gl = gl;
    this.mode = mode;
    this.count = J.positions.length / 3;
    this.program = link(gl, mode.jitter.vertex, config.jitter_fragment, `${mode.name} jitter`, ['gl_Position']);
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    attribute(gl, this.program, 'color', 3, J.colors);
    const split = mode.jitter.split;
    if (split.position) {
      const pairs = J.positions.map(splitDouble);
      attribute(gl, this.program, split.position[0], 3, pairs.map(p => p[0]));
      attribute(gl, this.program, split.position[1], 3, pairs.map(p => p[1]));
    } else {
      attribute(gl, this.program, 'position', 3, J.positions);
    }
    gl.bindVertexArray(null);
    this.feedback = gl.createBuffer();
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, this.feedback);
    gl.bufferData(gl.TRANSFORM_FEEDBACK_BUFFER, this.count * 16, gl.STREAM_READ);
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, null);
    this.transformFeedback = gl.createTransformFeedback();
  }

  // Draws one frame into the bound framebuffer; returns gl_Position of every vertex when `capture`.
  draw(camera, capture) {
    const gl = this.gl;
    gl.useProgram(this.program);
    setUniform(gl, this.program, 'eye', camera.eye, this.mode.jitter.split);
    gl.uniformMatrix4fv(gl.getUniformLocation(this.program, 'view_projection'), false, camera.viewProjection);
    gl.enable(gl.DEPTH_TEST);
    gl.clearColor(0.02, 0.03, 0.08, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.bindVertexArray(this.vao);
    if (capture) {
      gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, this.transformFeedback);
      gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, this.feedback);
      gl.beginTransformFeedback(gl.TRIANGLES);
    }
    gl.drawArrays(gl.TRIANGLES, 0, this.count);
    gl.bindVertexArray(null);
    if (!capture) return null;
    gl.endTransformFeedback();
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, null);
    gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, null);
    const clip = new Float32Array(this.count * 4);
    gl.bindBuffer(gl.COPY_READ_BUFFER, this.feedback);
    gl.getBufferSubData(gl.COPY_READ_BUFFER, 0, clip);
    gl.bindBuffer(gl.COPY_READ_BUFFER, null);
    return clip;
  }
}

// ---- the deep-zoom Mandelbrot --------------------------------------------------------------
// The fragment shader's iteration count for pixel (x, y) (row 0 at the bottom), in doubles, with
// the same operations in the same order: c = centre + (pixel centre - resolution / 2) * scale.
function referenceIterations(zoom, x, y) {
  const M = config.mandelbrot;
  const cx = M.center[0] + (x + 0.5 - 0.5 * M.width) * zoom;
  const cy = M.center[1] + (y + 0.5 - 0.5 * M.height) * zoom;
  let zx = 0, zy = 0, n = 0;
  while (n < M.max_iterations && zx * zx + zy * zy < 4) {
    const nextX = zx * zx - zy * zy + cx;
    zy = 2 * zx * zy + cy;
    zx = nextX;
    ++n;
  }
  return n;
}

const kFullScreenVertexShader = `#version 300 es
in vec2 corner;
void main() { gl_Position = vec4(corner, 0.0, 1.0); }
`;

class MandelbrotRenderer {
  constructor(gl, mode) {
    const M = config.mandelbrot;
    this.gl = gl;
    this.mode = mode;
    this.program = link(gl, kFullScreenVertexShader, mode.mandelbrot.fragment, `${mode.name} mandelbrot`);
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    attribute(gl, this.program, 'corner', 2, [-1, -1, 3, -1, -1, 3]);
    gl.bindVertexArray(null);
    this.target = gl.createTexture();  // one unsigned integer per pixel: the iteration count
    gl.bindTexture(gl.TEXTURE_2D, this.target);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.R32UI, M.width, M.height);
    this.framebuffer = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.target, 0);
    if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE)
      throw new Error('an R32UI framebuffer is not complete here');
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }

  draw(zoom) {
    const gl = this.gl, M = config.mandelbrot;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.viewport(0, 0, M.width, M.height);
    gl.disable(gl.DEPTH_TEST);
    gl.useProgram(this.program);
    setUniform(gl, this.program, 'center', M.center, this.mode.mandelbrot.split);
    setUniform(gl, this.program, 'scale', [zoom], this.mode.mandelbrot.split);
    gl.uniform2f(gl.getUniformLocation(this.program, 'resolution'), M.width, M.height);
    gl.uniform1i(gl.getUniformLocation(this.program, 'max_iterations'), M.max_iterations);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
  }

  // Iteration counts, row 0 at the bottom.
  read() {
    const gl = this.gl, M = config.mandelbrot;
    const rgba = new Uint32Array(M.width * M.height * 4);
    gl.readPixels(0, 0, M.width, M.height, gl.RGBA_INTEGER, gl.UNSIGNED_INT, rgba);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    const counts = new Uint32Array(M.width * M.height);
    for (let i = 0; i < counts.length; ++i) counts[i] = rgba[i * 4];
    return counts;
  }
}

// The colouring of src/demo/mandelbrot.cpp: black inside, a cosine palette of log2(1 + n) outside.
function paintCounts(canvas, counts) {
  const M = config.mandelbrot;
  const context = canvas.getContext('2d');
  const image = context.createImageData(M.width, M.height);
  for (let y = 0; y < M.height; ++y)
    for (let x = 0; x < M.width; ++x) {
      const n = counts[(M.height - 1 - y) * M.width + x];
      const o = (y * M.width + x) * 4;
      image.data[o + 3] = 255;
      if (n >= M.max_iterations) continue;
      const t = Math.log2(1 + n) * 0.6;
      for (let k = 0; k < 3; ++k) image.data[o + k] = 255 * (0.5 + 0.5 * Math.cos(2 * Math.PI * (t + k * 0.27 + 0.55)));
    }
  context.putImageData(image, 0, 0);
}

// ---- the page --------------------------------------------------------------------------------
const element = (tag, attributes = {}, ...children) => {
  const e = document.createElement(tag);
  Object.assign(e, attributes);
  e.append(...children);
  return e;
};

function panel(container, width, height, title) {
  const canvas = element('canvas', { width, height });
  const caption = element('div', { className: 'caption' });
  container.append(element('figure', {}, canvas, element('figcaption', {}, element('b', {}, title), caption)));
  return { canvas, caption };
}

const pause = () => new Promise(resolve => setTimeout(resolve, 0));  // lets the page repaint

// ms per frame of `draw`, over `frames` frames ended by gl.finish and a one-pixel readPixels; with
// EXT_disjoint_timer_query_webgl2, also the GPU's own time.
async function timeFrames(gl, timer, frames, draw, readOnePixel) {
  let query = null;
  if (timer) {
    query = gl.createQuery();
    gl.beginQuery(timer.TIME_ELAPSED_EXT, query);
  }
  const t0 = performance.now();
  for (let i = 0; i < frames; ++i) draw(i);
  if (query) gl.endQuery(timer.TIME_ELAPSED_EXT);
  gl.finish();
  readOnePixel();
  const wall = (performance.now() - t0) / frames;
  let gpu = null;
  if (query) {
    for (let tries = 0; tries < 200 && !gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE); ++tries)
      await new Promise(resolve => setTimeout(resolve, 10));
    if (gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE) && !gl.getParameter(timer.GPU_DISJOINT_EXT))
      gpu = gl.getQueryParameter(query, gl.QUERY_RESULT) / 1e6 / frames;
  }
  return { wall, gpu };
}

async function run() {
  const J = config.jitter, M = config.mandelbrot;
  const glCanvas = element('canvas', { width: J.width, height: J.height });
  const gl = glCanvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });
  if (!gl) throw new Error('this browser has no WebGL2');
  const debugInfo = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = debugInfo ? gl.getParameter(debugInfo.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  const timer = gl.getExtension('EXT_disjoint_timer_query_webgl2');
  document.getElementById('renderer').textContent = `${renderer} (${gl.getParameter(gl.VERSION)})`;
  const result = {
    renderer, version: gl.getParameter(gl.VERSION), sabotage: config.sabotage || null, loaded_from: location.protocol,
    modes: config.modes.map(m => m.name),
    jitter: { frames: J.frames, width: J.width, height: J.height, modes: {} },
    mandelbrot: { center: M.center, width: M.width, height: M.height, max_iterations: M.max_iterations,
                  reference_stride: M.reference_stride, views: [] },
    timing: { frames: config.timing_frames, timer_query: !!timer, modes: {} },
    panels: [],
  };
  const panels = [];  // [id, canvas]; their places are read once the page is complete
  const notePanel = (id, canvas) => panels.push([id, canvas]);

  // Mandelbrot: one row per zoom, one panel per mode.
  const mandelbrots = config.modes.map(mode => new MandelbrotRenderer(gl, mode));
  for (const zoom of M.zooms) {
    const row = element('div', { className: 'row' });
    document.getElementById('mandelbrot').append(element('h3', {}, `${zoom.toExponential(0)} per pixel`), row);
    const reference = [];
    for (let y = 0; y < M.height; y += M.reference_stride)
      for (let x = 0; x < M.width; x += M.reference_stride) reference.push([x, y, referenceIterations(zoom, x, y)]);
    const view = { zoom, checked_pixels: reference.length,
                   reference_distinct_counts: new Set(reference.map(r => r[2])).size, modes: {} };
    for (const [i, mode] of config.modes.entries()) {
      const { canvas, caption } = panel(row, M.width, M.height, mode.label);
      mandelbrots[i].draw(zoom);
      const counts = mandelbrots[i].read();
      paintCounts(canvas, counts);
      const equal = reference.filter(([x, y, n]) => counts[y * M.width + x] === n).length;
      view.modes[mode.name] = { match_fraction: equal / reference.length };
      caption.textContent = `${(100 * equal / reference.length).toFixed(2)} % of ${reference.length} checked pixels ` +
                            'have the JS-double iteration count';
      notePanel(`mandelbrot-${zoom.toExponential(0)}-${mode.name}`, canvas);
      await pause();
    }
    result.mandelbrot.views.push(view);
  }

  // Jitter: every mode draws the same frames; gl_Position is captured with transform feedback.
  const jitters = config.modes.map(mode => new JitterRenderer(gl, mode));
  const aspect = J.width / J.height;
  const cameras = Array.from({ length: J.frames }, (_, i) => jitterCamera(i / (J.frames - 1), aspect));
  const references = cameras.map(referenceClip);
  const jitterPanels = [];
  for (const [i, mode] of config.modes.entries()) {
    const { canvas, caption } = panel(document.getElementById('jitter-row'), J.width, J.height, mode.label);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, J.width, J.height);
    const clips = cameras.map(camera => jitters[i].draw(camera, true));
    const measured = wobble(clips, references, J.width, J.height);
    result.jitter.modes[mode.name] = measured;
    caption.textContent = `wobble ${measured.wobble_px.toPrecision(3)} px, largest error ` +
                          `${measured.max_error_px.toPrecision(3)} px (${J.frames} frames vs JS double)`;
    canvas.getContext('2d').drawImage(glCanvas, 0, 0);
    jitterPanels.push(canvas);
    notePanel(`jitter-${mode.name}`, canvas);
  }

  // Timing: the first zoom's Mandelbrot and a jitter frame, per mode.
  const table = document.getElementById('timing');
  for (const [i, mode] of config.modes.entries()) {
    await pause();
    const readOne = () => gl.readPixels(0, 0, 1, 1, gl.RGBA_INTEGER, gl.UNSIGNED_INT, new Uint32Array(4));
    const mandelbrot = await timeFrames(gl, timer, config.timing_frames, () => mandelbrots[i].draw(M.zooms[0]), () => {
      gl.bindFramebuffer(gl.FRAMEBUFFER, mandelbrots[i].framebuffer);
      readOne();
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    });
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, J.width, J.height);
    const jitter = await timeFrames(gl, timer, config.timing_frames,
                                    f => jitters[i].draw(cameras[f % cameras.length], false),
                                    () => gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4)));
    result.timing.modes[mode.name] = { mandelbrot_ms: mandelbrot.wall, mandelbrot_gpu_ms: mandelbrot.gpu,
                                       jitter_ms: jitter.wall, jitter_gpu_ms: jitter.gpu };
    const cell = (wall, gpu) => wall.toFixed(2) + (gpu === null ? '' : ` (GPU ${gpu.toFixed(2)})`);
    table.append(element('tr', {}, element('td', {}, mode.name), element('td', {}, cell(mandelbrot.wall, mandelbrot.gpu)),
                         element('td', {}, cell(jitter.wall, jitter.gpu))));
  }
  document.getElementById('timing-note').textContent =
      `${renderer}: ${config.timing_frames} frames per cell, ended by gl.finish() and a one-pixel readPixels; ` +
      (timer ? 'GPU time from EXT_disjoint_timer_query_webgl2.' : 'EXT_disjoint_timer_query_webgl2 is not available here.');

  // The jitter panels keep moving once the numbers are in: the camera sweeps 10 -> 50 m and back.
  const start = performance.now();
  const animate = now => {
    const phase = ((now - start) / 8000) % 2, s = phase < 1 ? phase : 2 - phase;
    const camera = jitterCamera(s, aspect);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, J.width, J.height);
    jitters.forEach((jitter, i) => {
      jitter.draw(camera, false);
      jitterPanels[i].getContext('2d').drawImage(glCanvas, 0, 0);
    });
    requestAnimationFrame(animate);
  };
  requestAnimationFrame(animate);
  document.getElementById('status').textContent = 'done';
  // Where each panel is on the page (CSS pixels from the top left), so a screenshot can be checked.
  for (const [id, canvas] of panels) {
    const r = canvas.getBoundingClientRect();
    result.panels.push({ id, x: Math.round(r.left + scrollX), y: Math.round(r.top + scrollY),
                         width: canvas.width, height: canvas.height });
  }
  return result;
}

window.doubletResult = run().catch(error => {
  document.getElementById('status').textContent = `failed: ${error.message}`;
  throw error;
});
