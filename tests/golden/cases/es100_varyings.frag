// targets: es100 es300 glsl330 webgl2
#version 100
precision highp float;
// ES 1.00 input: varying, gl_FragColor; a double uniform and a texture lookup.
uniform sampler2D tex;
uniform double zoom;
varying vec2 v_uv;
void main() {
  double u = double(v_uv.x) * zoom;
  gl_FragColor = texture2D(tex, v_uv) * float(u - floor(float(u)));
}
