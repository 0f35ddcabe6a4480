// targets: es100 es300 es310 glsl330 glsl450 webgl2
#version 110
// gl_FragData with constant indices: ES 1.00 keeps it, ES 3.00+ and core profiles have none, so
// the printer declares one output per slot (df_frag_data_k at location k).
uniform double a;
uniform double b;
void main() {
  double p = a * b;
  gl_FragData[0] = vec4(float(p), 0.0, 0.0, 1.0);
  gl_FragData[1] = vec4(float(a / b), 0.0, 0.0, 1.0);
}
