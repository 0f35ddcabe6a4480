// targets: es310 glsl450
// options: --mode exact
#version 450
// Mode exact's double matrices across the interface: a loose dmat4 / dmat3[2] uniform becomes one
// uvec4 array of the column-major doubles' words (loaded into M_value at main's start); block
// members keep their std140/std430 bytes as ex_dmatCxR_words (column words at the 16/32-byte column
// stride); a column or element is read and written alone, a whole matrix through ex_load/ex_words.
layout(local_size_x = 64) in;
uniform dmat4 u_model;
uniform dmat3 r[2];
layout(std140, binding = 0) uniform Mats { float s; dmat3 a; dmat2x3 b; dmat2 c; double k; };
layout(std430, binding = 1) buffer Io { float f; dmat4 m; dmat3x2 n[2]; dvec4 v[]; } io;
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec4 x = io.v[i];
  io.v[i] = u_model * x + dvec4(r[i & 1u] * x.xyz, c[1][i & 1u] * k);
  if (i == 0u) {
    io.m = u_model;
    io.m[2] = io.m[1] + dvec4(a[0], b[1][2]);
    io.m[3][1] = io.m[0][3] * k;
    io.n[1] = c * io.n[0];
    io.n[0][2].y += a[2][2];
  }
}
