#version 110
// gl_FragData with constant indices (issue 12): es300+/desktop have no gl_FragData; the lowered
// shader writes df_frag_data_k at location k. Each slot carries a double as (hi, lo), so the low
// word of the arithmetic is compared too.
uniform double a;
uniform double b;
void main() {
  double p = a * b;
  double q = a / b + 1.0lf;
  float p_hi = float(p);
  float q_hi = float(q);
  gl_FragData[0] = vec4(p_hi, float(p - double(p_hi)), 0.0, 1.0);
  gl_FragData[1] = vec4(q_hi, float(q - double(q_hi)), 0.0, 1.0);
}
