#version 450
// Astronomy renderer: each star (a point, heliocentric position in metres) becomes a short trail of
// line segments along its velocity, drawn relative to the eye. Positions near 1e11 m with a
// millimetre-scale trail step: float cannot resolve the step, double can. An engine header for the
// relative-to-eye helper, an EmitVertex loop in a helper function, a uniform with a default value.
#include "engine_common.glsl"
layout(points) in;
layout(line_strip, max_vertices = 4) out;
in dvec3 v_star_position[];
in dvec3 v_star_velocity[];
in float v_magnitude[];
uniform dvec3 u_eye;
uniform double u_trail_seconds = 0.5lf;
flat out dvec3 g_relative;
out vec2 g_depth_hi_lo;
out float g_fade;

void emit_trail_point(dvec3 position, float fade) {
  g_relative = rte(position, u_eye);
  g_depth_hi_lo = hi_lo(length(g_relative));
  g_fade = fade;
  gl_Position = vec4(vec3(g_relative * 1e-11lf), 1.0);
  EmitVertex();
}

void main() {
  const int steps = 4;
  for (int k = 0; k < steps; ++k) {
    double t = double(k) / double(steps - 1) * u_trail_seconds;
    emit_trail_point(v_star_position[0] - v_star_velocity[0] * t, v_magnitude[0] * float(steps - k) / float(steps));
  }
  EndPrimitive();
}
