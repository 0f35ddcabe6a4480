// targets: es310 es320 glsl450
#version 450
// Non-square double matrices (dmatCxR, ES 3.00+): products of every shape, outerProduct,
// transpose, resizing constructors, component-wise ops, and a double matrix in a storage block.
layout(local_size_x = 16) in;
layout(std430, binding = 0) buffer Data {
  dmat2x3 weights;
  dvec4 values[];
};
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec4 v = values[i];
  dmat3x2 t = transpose(weights);
  dmat2 square = t * weights;
  dmat3 other = weights * t;
  dmat4x3 outer = outerProduct(v.xyz, v);
  dvec3 column = outer * v + weights * v.zw;
  dvec4 row = v.xyz * outer;
  dmat2x4 wide = dmat2x4(outer) - dmat2x4(1.0lf);
  wide = matrixCompMult(wide, dmat2x4(v, v.wzyx)) * 0.5lf;
  values[i] = row + wide[1] + dvec4(column, determinant(square) + determinant(other));
  weights[1] = column;
}
