// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 330 core
// The transcendental extension (docs/transcendentals.md): WGS84 geodetic -> ECEF, Kepler's
// equation by Newton steps, and the other functions on scalars and vectors.
uniform dvec3 lat_lon_height;  // radians, radians, metres
uniform dvec3 eye_ecef;
uniform double mean_anomaly;
uniform double eccentricity;
uniform mat4 view_projection;
out float shade;

dvec3 ecef(dvec3 llh) {
  const double a = 6378137.0lf;
  const double e2 = 6.69437999014e-3lf;
  double s = sin(llh.x);
  double n = a / sqrt(1.0lf - e2 * s * s);
  double r = (n + llh.z) * cos(llh.x);
  return dvec3(r * cos(llh.y), r * sin(llh.y), (n * (1.0lf - e2) + llh.z) * s);
}

double kepler(double m, double e) {
  double E = m;
  for (int i = 0; i < 4; ++i) E -= (E - e * sin(E) - m) / (1.0lf - e * cos(E));
  return E;
}

void main() {
  dvec3 p = ecef(lat_lon_height) - eye_ecef;
  double E = kepler(mean_anomaly, eccentricity);
  double nu = 2.0lf * atan(sqrt(1.0lf + eccentricity) * sin(E / 2.0lf), sqrt(1.0lf - eccentricity) * cos(E / 2.0lf));
  dvec2 v = dvec2(nu, E);
  double t = exp(-v.x) + log(abs(v.y) + 1.0lf) + exp2(v.x) + log2(v.y + 2.0lf) + pow(abs(v.x), 0.75lf)
           + tan(v.x) + asin(v.y * 0.1lf) + acos(v.x * 0.1lf) + atan(v.y) + sinh(v.x) + cosh(v.y) + tanh(v.x);
  dvec2 w = exp(v) + sin(v);
  shade = float(t + w.x + w.y);
  gl_Position = view_projection * vec4(vec3(p), 1.0);
}
