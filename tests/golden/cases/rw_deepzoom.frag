// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 100
// Real-world style (issue 12): a deep-zoom Mandelbrot fragment shader written for WebGL 1 with
// doubles: loose uniforms, a palette texture, global state initialised from uniforms, a helper
// with an out parameter, a loop with a constant bound and an early break.
precision highp float;
uniform dvec2 center;
uniform double scale;
uniform vec2 resolution;
uniform sampler2D palette;
varying vec2 v_uv;

double pixel_size = scale / double(resolution.y);
int escaped_at = 0;

bool iterate(inout dvec2 z, dvec2 c) {
  z = dvec2(z.x * z.x - z.y * z.y, 2.0lf * z.x * z.y) + c;
  return dot(z, z) > 4.0lf;
}

void main() {
  dvec2 c = center + dvec2(gl_FragCoord.xy - 0.5 * resolution) * pixel_size;
  dvec2 z = dvec2(0.0lf);
  for (int n = 0; n < 256; n++) {
    if (iterate(z, c)) { escaped_at = n; break; }
  }
  gl_FragColor = texture2D(palette, vec2(float(escaped_at) / 256.0, 0.5)) * float(v_uv.x >= 0.0);
}
