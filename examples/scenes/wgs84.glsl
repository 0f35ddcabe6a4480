// WGS84 geodetic coordinates -> Earth-centred, Earth-fixed (ECEF) metres (docs/examples-wgs84.md).
// Ellipsoid of NIMA TR8350.2: a = 6378137 m, f = 1/298.257223563, e^2 = f (2 - f).
//   N = a / sqrt(1 - e^2 sin^2 lat)           (prime vertical radius of curvature)
//   X = (N + h) cos lat cos lon,  Y = (N + h) cos lat sin lon,  Z = (N (1 - e^2) + h) sin lat
// sin and cos of doubles are doublet's transcendental extension (docs/transcendentals.md).

// angles: geodetic latitude and longitude, radians; h: ellipsoidal height, metres.
dvec3 geodetic_to_ecef(dvec2 angles, double h) {
  const double a = 6378137.0lf;
  const double e2 = 6.69437999014131699e-3lf;
  double s = sin(angles.x);
  double c = cos(angles.x);
  double n = a / sqrt(1.0lf - e2 * s * s);
  return dvec3((n + h) * c * cos(angles.y), (n + h) * c * sin(angles.y), (n * (1.0lf - e2) + h) * s);
}

// The ellipsoid's outward normal at (lat, lon): for lighting, where a few tenths of a degree do.
vec3 up_vector(dvec2 angles) {
  double c = cos(angles.x);
  return vec3(dvec3(c * cos(angles.y), c * sin(angles.y), sin(angles.x)));
}
