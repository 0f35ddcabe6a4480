// The WGS84 example scene (examples/scenes/wgs84_ecef.{vert,comp}, docs/examples-wgs84.md) on real
// drivers: points on the globe, each camera a few metres from its points, the shader lowered in a
// given way, and every result compared with an MPFR (200-bit) evaluation of the geodetic formula
// on the same double inputs. Shared by the driver test (wgs84_test.cpp) and the report tool that
// prints the docs' table (wgs84_report.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace wgs84 {

using Vec3 = std::array<double, 3>;

struct Point {
  double lat, lon, h;  // radians, radians, metres
};

// One camera and the points drawn from it: every component of ECEF(point) - eye within 10 m,
// as wgs84.scene.json promises. `rel` and `up` are the exact (MPFR) results, rounded to double.
struct View {
  Vec3 eye;
  std::vector<Point> points;
  std::vector<Vec3> rel, up;
};

// A camera a few metres from `centre` and `points` points around it.
View make_view(const Point& centre, int points, uint64_t seed);

// `views` cameras anywhere on the globe (the poles, the antimeridian and both height extremes
// among them), `points` points each.
std::vector<View> make_globe_views(int views, int points, uint64_t seed);

// ECEF(p) - eye and the ellipsoid normal at p, evaluated with MPFR at 200 bits, rounded once.
Vec3 reference_rel(const Point& p, const Vec3& eye);
Vec3 reference_up(const Point& p);
// The same formula in long double: to place the samples (not a reference).
Vec3 ecef_long_double(const Point& p);

// examples/scenes/NAME read and lowered with `options` (file_name and include dir set here).
doublet::Result lower_example(const std::string& name, doublet::Options options);
// A plan file made by `doublet plan`, read into options (mode, mode_for). False: `error` says why.
bool apply_plan_file(const std::string& path, doublet::Options* options, std::string* error);

struct Errors {
  std::string error;          // lowering or driver failure; empty when measured
  size_t samples = 0;
  double rel_max = 0;         // max |lowered - exact| over every component of v_rel, metres
  double up_max = 0;          // the same for v_up
  int not_finite = 0;         // results that are NaN or infinite
  std::string worst;          // the input of rel_max, for the failure message
};

// Runs the lowered vertex shader `glsl` in the vertex stage (one draw per view) and compares.
// Inputs and uniforms are filled by name from the stage's reflection: X_hi/X_lo float pairs
// (float-float), X_hi/X_lo uint words (mode exact), or a plain float X (fp32).
Errors measure_vertex(doublet::runner::Backend backend, const std::string& glsl, const std::vector<View>& views);

}  // namespace wgs84
