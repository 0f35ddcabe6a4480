// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 330 core
// Real-world style (issue 12): satellites on Kepler orbits, as a space-visualisation app writes it.
// A struct uniform with doubles, a Newton solver with inout parameters, global constants and
// state, a smooth float output and a flat double one.
struct Orbit {
  double semi_major_axis;
  double eccentricity;
  double mean_motion;
  double epoch;
};
uniform Orbit orbit;
uniform double time_seconds;
uniform dvec3 camera_position;
uniform mat4 view_projection;
in float phase_offset;
out float brightness;

const double kTwoPi = 6.283185307179586lf;
const int kIterations = 6;
double elapsed = time_seconds - orbit.epoch;

void solve_kepler(double mean_anomaly, double e, inout double eccentric_anomaly) {
  for (int k = 0; k < kIterations; ++k) {
    double f = eccentric_anomaly - e * double(sin(float(eccentric_anomaly))) - mean_anomaly;
    eccentric_anomaly -= f / (1.0lf - e * double(cos(float(eccentric_anomaly))));
  }
}

void main() {
  double m = mod(orbit.mean_motion * elapsed + double(phase_offset), kTwoPi);
  double ea = m;
  solve_kepler(m, orbit.eccentricity, ea);
  double a = orbit.semi_major_axis;
  dvec3 position = dvec3(a * (double(cos(float(ea))) - orbit.eccentricity),
                         a * sqrt(1.0lf - orbit.eccentricity * orbit.eccentricity) * double(sin(float(ea))), 0.0lf);
  dvec3 relative = position - camera_position;
  brightness = 1.0 / (1.0 + float(length(relative)) * 1e-6);
  gl_Position = view_projection * vec4(vec3(relative), 1.0);
}
