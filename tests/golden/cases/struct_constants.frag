// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// A struct constructor of constants (glslang folds it into one constant) and a
// constant array of structs with double members: each member must stay a value.
struct Orbit { dvec2 z; int n; double r2; };
struct Pair { double a; float b; };
const Pair kPairs[2] = Pair[2](Pair(0.1lf, 1.0), Pair(1.0lf / 3.0lf, 2.0));
uniform dvec2 c;
uniform int pick;
out vec4 color;

void main() {
  Orbit o = Orbit(dvec2(0.25lf, 1e-9lf), 0, 0.0lf);
  o.z = o.z * o.z + c;
  o.r2 = dot(o.z, o.z) + kPairs[pick].a;
  color = vec4(float(o.r2), float(o.z.y), kPairs[pick].b, float(o.n));
}
