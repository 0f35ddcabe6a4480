// targets: glsl330 glsl450
#version 450
// Desktop-only sampler types next to doubles (issue 12): passed through on desktop targets;
// ES targets refuse them at the variable (tests/unit/real_world_test.cpp).
uniform sampler1D ramp;
uniform sampler2DRect screen;
uniform samplerBuffer samples;
uniform double exposure;
in vec2 uv;
out vec4 color;
void main() {
  double e = exposure * 0.5lf;
  color = texture(ramp, uv.x) * texture(screen, uv * 512.0) * texelFetch(samples, 3) * float(e);
}
