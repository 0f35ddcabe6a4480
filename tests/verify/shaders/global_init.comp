#version 310 es
// Global initialisers that read a double uniform (split into _hi/_lo and joined at the top of
// main by the lowering) and feed each other: they must see the uniform's value, not the zero of
// the df_double global before the join (issue 12; before the fix glsl450 printed them at global
// scope and computed 2/log2(1) = inf).
layout(local_size_x = 1) in;
uniform double farPlane;
double scaled = farPlane * 3.0lf + 0.5lf;
double t = scaled / 3.0lf;
float k = 2.0 / log2(float(farPlane) + 1.0);
layout(std430, binding = 0) writeonly buffer Result { vec4 r; };
vec2 pair(double x) { float hi = float(x); return vec2(hi, float(x - double(hi))); }
void main() {
  r = vec4(pair(t), pair(double(k) * farPlane));
}
