#version 300 es
// Relative-to-eye (RTE) transform.
//
// Far from the origin a float is too coarse for world positions: at 10^7 m
// (planet scale) neighbouring floats are a metre apart, so vertices jitter as
// the camera moves. Keeping the position and the eye in double, subtracting
// them on the GPU and only then narrowing the small eye-relative offset to
// float keeps full precision near the camera. viewProj must not contain the
// camera translation (it is applied by the subtraction).
//
// GLSL ES has no doubles: `doublet lower` turns each dvec3 into a pair of
// vec3 (position_hi/position_lo, eye_hi/eye_lo) and does the subtraction in
// float-float arithmetic; the manifest (--manifest) lists the new names.
in dvec3 position;
uniform dvec3 eye;
uniform mat4 viewProj;
void main(){ gl_Position = viewProj * vec4(vec3(position - eye), 1.0); }
