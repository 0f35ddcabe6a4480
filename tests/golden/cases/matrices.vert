// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// Square double matrices: uniforms split into hi/lo mat uniforms, matrix x vector, vector x
// matrix, matrix x matrix, matrix +- scalar, component-wise ops, indexing m[i] and m[i][j]
// (constant and dynamic, read and write), transpose, determinant, inverse, matrixCompMult,
// constructors and conversions, double matrix function parameters and returns.
uniform dmat4 model;
uniform dmat3 normal_basis;
uniform dmat2 warp[2];
uniform int column;
in dvec4 position;
in vec3 normal;
out vec4 shade;
dmat3 scaled(dmat3 m, double s) { return m * s; }
void main() {
  dmat4 mvp = model * transpose(model) + 0.5lf;
  dvec4 p = mvp * position;
  p += position * mvp;
  dmat3 n = inverse(normal_basis) * determinant(normal_basis);
  n = scaled(n, 2.0lf) - dmat3(1.0lf);
  n[1] = dvec3(normal);
  n[2][column] += 3.0lf;
  mvp[column] = p;
  dmat2 w = matrixCompMult(warp[0], warp[1]) / 4.0lf;
  w = -w + dmat2(inverse(warp[1])) * warp[0];
  dvec3 r = n * dvec3(normal) + dvec3(w[0], determinant(w));
  bool same = model == mvp;
  mat4 demoted = mat4(mvp);
  shade = vec4(vec3(r), same ? 1.0 : 0.0) + demoted[column];
  gl_Position = vec4(dmat4(mat3(demoted)) * p + mvp[2] + dvec4(n[column], w[1][column - 2 * (column / 2)]));
}
