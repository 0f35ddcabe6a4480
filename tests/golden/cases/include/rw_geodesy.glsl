// Shared header of rw_include.vert (engine-style #include): WGS84 constants and a
// geodetic → Earth-centred conversion in double precision, with an include guard.
#ifndef RW_GEODESY_GLSL
#define RW_GEODESY_GLSL
const double kEquatorialRadius = 6378137.0lf;
const double kFlattening = 1.0lf / 298.257223563lf;
const double kEccentricity2 = kFlattening * (2.0lf - kFlattening);

dvec3 geodetic_to_ecef(double lon, double lat, double height) {
  double sin_lat = double(sin(float(lat)));
  double cos_lat = double(cos(float(lat)));
  double n = kEquatorialRadius / sqrt(1.0lf - kEccentricity2 * sin_lat * sin_lat);
  return dvec3((n + height) * cos_lat * double(cos(float(lon))), (n + height) * cos_lat * double(sin(float(lon))),
               (n * (1.0lf - kEccentricity2) + height) * sin_lat);
}
#endif
