// The jitter scene in WebGL2 through doublet's web package only: the vertex shader with doubles is
// lowered at build time (the `?doublet` import), its attributes and uniforms are set from the
// manifest with @doublet/host, 48 frames' gl_Position are captured by transform feedback and
// compared with JavaScript's doubles. The result goes to the page and to window.doubletResult.
import jitter from '../shaders/jitter.vert?doublet&target=webgl2';
import { setUniformsFromManifest, splitArray } from '@doublet/host';
import { camera, geometry, referenceClip, wobble } from './scene.js';

const width = 320, height = 240, frames = 48;
const fragmentSource = `#version 300 es
precision highp float;
in vec3 v_color;
out vec4 frag_color;
void main() { frag_color = vec4(v_color, 1.0); }
`;

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
  return shader;
}

function attribute(gl, program, name, data) {
  const location = gl.getAttribLocation(program, name);
  if (location < 0) throw new Error(`no attribute ${name}`);
  gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(data), gl.STATIC_DRAW);
  gl.enableVertexAttribArray(location);
  gl.vertexAttribPointer(location, 3, gl.FLOAT, false, 0, 0);
}

function run() {
  const canvas = document.getElementById('scene');
  const gl = canvas.getContext('webgl2');
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, jitter.code));
  gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, fragmentSource));
  gl.transformFeedbackVaryings(program, ['gl_Position'], gl.SEPARATE_ATTRIBS);
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
  gl.useProgram(program);

  // Attributes by the manifest's names: a split dvec3 is NAME_hi/NAME_lo (or one vec3 in fp32).
  const { positions, colors } = geometry();
  const count = positions.length / 3;
  gl.bindVertexArray(gl.createVertexArray());
  attribute(gl, program, 'color', colors);
  const position = jitter.manifest.variables.find((v) => v.name === 'position');
  if (position.split) {
    const { hi, lo } = splitArray(positions);
    attribute(gl, program, position.lowered_names[0], hi);
    attribute(gl, program, position.lowered_names[1], lo);
  } else {
    attribute(gl, program, position.lowered_names[0], positions);
  }
  const eyeSplit = jitter.manifest.variables.find((v) => v.name === 'eye').split;

  const feedback = gl.createBuffer();
  gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, feedback);
  gl.bufferData(gl.TRANSFORM_FEEDBACK_BUFFER, count * 16, gl.STREAM_READ);
  gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, null);
  const clips = [], references = [];
  gl.enable(gl.DEPTH_TEST);
  for (let f = 0; f < frames; ++f) {
    const cam = camera(f / (frames - 1), width / height);
    if (eyeSplit) {
      for (const u of setUniformsFromManifest(jitter.manifest, { eye: cam.eye }))
        gl[u.setter](gl.getUniformLocation(program, u.name), u.data);
    } else {
      gl.uniform3fv(gl.getUniformLocation(program, 'eye'), cam.eye);
    }
    gl.uniformMatrix4fv(gl.getUniformLocation(program, 'view_projection'), false, cam.viewProjection);
    gl.clearColor(0.02, 0.03, 0.08, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, feedback);
    gl.beginTransformFeedback(gl.TRIANGLES);
    gl.drawArrays(gl.TRIANGLES, 0, count);
    gl.endTransformFeedback();
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, null);
    const clip = new Float32Array(count * 4);
    gl.bindBuffer(gl.COPY_READ_BUFFER, feedback);
    gl.getBufferSubData(gl.COPY_READ_BUFFER, 0, clip);
    gl.bindBuffer(gl.COPY_READ_BUFFER, null);  // bound elsewhere, the next draw could not capture into it
    clips.push(clip);
    references.push(referenceClip(positions, cam));
  }
  const measured = wobble(clips, references, width, height);
  document.getElementById('caption').textContent =
    `${jitter.mode} (${jitter.target}): wobble ${measured.wobble_px.toPrecision(3)} px, largest error ${measured.max_error_px.toPrecision(3)} px`;
  return { mode: jitter.mode, target: jitter.target, frames, vertices: count, ...measured };
}

window.doubletResult = Promise.resolve().then(run);
