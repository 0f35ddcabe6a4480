// targets: es300 es310 es320 glsl450 webgl2
#version 450
// A ternary choosing a double (a df_double struct once lowered) read from a uniform block: glslang
// 12 compiled it to an OpSelect of two different struct types, invalid SPIR-V (spirv-val), so the
// selection goes through a temporary on every target (src/lower/select_structs.cpp). Run on
// lavapipe against native fp64 (tests/golden CMake). Found by the differential tester.
layout(std140) uniform Params {
  double limit;
  dvec2 offset;
};
in dvec2 position;
flat out dvec2 moved;
void main() {
  double x = position.x > limit ? limit : position.x;
  dvec2 shift = position.y < 0.0lf ? offset : dvec2(x, 1.0lf);
  moved = shift + position;
  gl_Position = vec4(vec2(moved), 0.0, 1.0);
}
