#include "wgs84_harness.hpp"

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "doublet/split.hpp"
#include "plan/planner.hpp"

namespace wgs84 {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRelation = 10;  // wgs84.scene.json: |ECEF(point) - eye| <= 10 m per axis

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// a and e^2 = f (2 - f), f = 1/298.257223563 (NIMA TR8350.2), to 200 bits.
struct Ellipsoid {
  mpfr_t a, e2;
  Ellipsoid() {
    mpfr_inits2(200, a, e2, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_ui(a, 6378137, MPFR_RNDN);
    mpfr_t f;
    mpfr_init2(f, 200);
    mpfr_set_str(f, "298.257223563", 10, MPFR_RNDN);
    mpfr_ui_div(f, 1, f, MPFR_RNDN);
    mpfr_ui_sub(e2, 2, f, MPFR_RNDN);
    mpfr_mul(e2, e2, f, MPFR_RNDN);
    mpfr_clear(f);
  }
  ~Ellipsoid() { mpfr_clears(a, e2, static_cast<mpfr_ptr>(nullptr)); }
};

// Fills x, y, z with ECEF(p) (200 bits).
void ecef_mpfr(const Point& p, mpfr_t x, mpfr_t y, mpfr_t z) {
  static const Ellipsoid wgs;
  mpfr_t s, c, cl, sl, n, t;
  mpfr_inits2(200, s, c, cl, sl, n, t, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(t, p.lat, MPFR_RNDN);
  mpfr_sin_cos(s, c, t, MPFR_RNDN);
  mpfr_set_d(t, p.lon, MPFR_RNDN);
  mpfr_sin_cos(sl, cl, t, MPFR_RNDN);
  mpfr_sqr(n, s, MPFR_RNDN);  // N = a / sqrt(1 - e2 s^2)
  mpfr_mul(n, n, wgs.e2, MPFR_RNDN);
  mpfr_ui_sub(n, 1, n, MPFR_RNDN);
  mpfr_rec_sqrt(n, n, MPFR_RNDN);
  mpfr_mul(n, n, wgs.a, MPFR_RNDN);
  mpfr_add_d(t, n, p.h, MPFR_RNDN);  // (N + h) cos lat
  mpfr_mul(t, t, c, MPFR_RNDN);
  mpfr_mul(x, t, cl, MPFR_RNDN);
  mpfr_mul(y, t, sl, MPFR_RNDN);
  mpfr_ui_sub(t, 1, wgs.e2, MPFR_RNDN);  // (N (1 - e2) + h) sin lat
  mpfr_mul(t, t, n, MPFR_RNDN);
  mpfr_add_d(t, t, p.h, MPFR_RNDN);
  mpfr_mul(z, t, s, MPFR_RNDN);
  mpfr_clears(s, c, cl, sl, n, t, static_cast<mpfr_ptr>(nullptr));
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1p-53);
}

// The value a lowered input/uniform `lowered` (of scalar kind `scalar`) takes for the original
// variable `name` with value x, or false when `lowered` is not one of its parts.
bool part_value(const std::string& lowered, char scalar, const std::string& name, double x, double* out) {
  if (lowered == name) {
    *out = x;  // fp32: the runner rounds it to float
    return true;
  }
  const bool hi = lowered == name + "_hi", lo = lowered == name + "_lo";
  if (!hi && !lo) return false;
  if (scalar == 'u') {
    const doublet::ExactWords w = doublet::exact_words(x);
    *out = hi ? w.hi : w.lo;
  } else {
    const doublet::FloatPair f = doublet::split(x);
    *out = hi ? f.hi : f.lo;
  }
  return true;
}

}  // namespace

Vec3 ecef_long_double(const Point& p) {
  const long double a = 6378137.0L, f = 1 / 298.257223563L, e2 = f * (2 - f);
  const long double s = std::sin(static_cast<long double>(p.lat)), c = std::cos(static_cast<long double>(p.lat));
  const long double n = a / std::sqrt(1 - e2 * s * s);
  return {static_cast<double>((n + p.h) * c * std::cos(static_cast<long double>(p.lon))),
          static_cast<double>((n + p.h) * c * std::sin(static_cast<long double>(p.lon))),
          static_cast<double>((n * (1 - e2) + p.h) * s)};
}

Vec3 reference_rel(const Point& p, const Vec3& eye) {
  mpfr_t v[3];
  for (mpfr_t& x : v) mpfr_init2(x, 200);
  ecef_mpfr(p, v[0], v[1], v[2]);
  Vec3 r;
  for (int i = 0; i < 3; ++i) {
    mpfr_sub_d(v[i], v[i], eye[static_cast<size_t>(i)], MPFR_RNDN);
    r[static_cast<size_t>(i)] = mpfr_get_d(v[i], MPFR_RNDN);
    mpfr_clear(v[i]);
  }
  return r;
}

Vec3 reference_up(const Point& p) {
  mpfr_t t, s, c, sl, cl;
  mpfr_inits2(200, t, s, c, sl, cl, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(t, p.lat, MPFR_RNDN);
  mpfr_sin_cos(s, c, t, MPFR_RNDN);
  mpfr_set_d(t, p.lon, MPFR_RNDN);
  mpfr_sin_cos(sl, cl, t, MPFR_RNDN);
  mpfr_mul(cl, cl, c, MPFR_RNDN);
  mpfr_mul(sl, sl, c, MPFR_RNDN);
  const Vec3 r{mpfr_get_d(cl, MPFR_RNDN), mpfr_get_d(sl, MPFR_RNDN), mpfr_get_d(s, MPFR_RNDN)};
  mpfr_clears(t, s, c, sl, cl, static_cast<mpfr_ptr>(nullptr));
  return r;
}

namespace {

View view_around(const Point& c, int points, std::mt19937_64& rng) {
  View v;
  const Vec3 centre = ecef_long_double(c);
  for (size_t i = 0; i < 3; ++i) v.eye[i] = centre[i] + uniform(rng, -5, 5);
  // Points a few metres around the centre (in angle: metres / radius, more in longitude where
  // the parallels shrink), kept when every axis is within the relation's 10 m of the eye.
  const double dlat = 6 / 6.4e6, dlon = 6 / (6.4e6 * std::max(std::cos(c.lat), 1e-3));
  while (static_cast<int>(v.points.size()) < points) {
    Point p{std::clamp(c.lat + uniform(rng, -dlat, dlat), -kPi / 2, kPi / 2),
            std::clamp(c.lon + uniform(rng, -dlon, dlon), -kPi, kPi),
            std::clamp(c.h + uniform(rng, -6, 6), -500.0, 9000.0)};
    const Vec3 e = ecef_long_double(p);
    bool near = true;
    for (size_t i = 0; i < 3; ++i) near &= std::fabs(e[i] - v.eye[i]) <= kRelation - 0.01;
    if (!near) continue;
    v.points.push_back(p);
    v.rel.push_back(reference_rel(p, v.eye));
    v.up.push_back(reference_up(p));
  }
  return v;
}

}  // namespace

View make_view(const Point& centre, int points, uint64_t seed) {
  std::mt19937_64 rng(seed);
  return view_around(centre, points, rng);
}

std::vector<View> make_globe_views(int views, int points, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<View> out;
  for (int k = 0; k < views; ++k) {
    // Centres: the first few at the edges of the scene's ranges, the rest uniform over it.
    Point c{uniform(rng, -kPi / 2, kPi / 2), uniform(rng, -kPi, kPi), uniform(rng, -500, 9000)};
    switch (k) {
      case 0: c = {kPi / 2, 0.3, 9000}; break;    // north pole, highest
      case 1: c = {-kPi / 2, -2.0, -500}; break;  // south pole, lowest
      case 2: c = {0.0, kPi, 0}; break;           // equator on the antimeridian
      case 3: c = {0.7, -kPi, 4000}; break;
      case 4: c = {1e-9, 1e-9, 0}; break;         // where cos is 1 and sin tiny
      default: break;
    }
    out.push_back(view_around(c, points, rng));
  }
  return out;
}

doublet::Result lower_example(const std::string& name, doublet::Options options) {
  const std::string path = std::string(DOUBLET_SCENES) + "/" + name;
  options.file_name = path;
  options.stage = name.ends_with(".comp") ? doublet::Stage::Compute : doublet::Stage::Vertex;
  options.include_dirs.push_back(DOUBLET_SCENES);
  return doublet::lower(read_text(path), options);
}

bool apply_plan_file(const std::string& path, doublet::Options* options, std::string* error) {
  doublet::Diagnostic d;
  if (doublet::plan::load_plan(read_text(path), path, options, &d)) return true;
  *error = doublet::format_diagnostic(d);
  return false;
}

Errors measure_vertex(doublet::runner::Backend backend, const std::string& glsl, const std::vector<View>& views) {
  namespace r = doublet::runner;
  Errors out;
  r::GraphicsInterface iface;
  if (!r::reflect_graphics(r::GraphicsStage::Vertex, glsl, &iface, &out.error)) return out;
  std::vector<r::GraphicsJob> jobs;
  for (const View& v : views) {
    r::GraphicsJob job;
    job.stage = r::GraphicsStage::Vertex;
    job.glsl = glsl;
    job.count = static_cast<uint32_t>(v.points.size());
    for (const r::StageVariable& in : iface.inputs) {
      std::vector<double>& values = job.inputs[in.name];
      for (const Point& p : v.points) {
        double x = 0;
        if (part_value(in.name, in.scalar, "lat_lon", p.lat, &x)) {
          values.push_back(x);
          part_value(in.name, in.scalar, "lat_lon", p.lon, &x);
          values.push_back(x);
        } else if (part_value(in.name, in.scalar, "height", p.h, &x)) {
          values.push_back(x);
        }
      }
      if (values.size() != v.points.size() * static_cast<size_t>(in.components)) {
        out.error = "unexpected input '" + in.name + "' in the lowered shader";
        return out;
      }
    }
    for (const auto& u : iface.uniforms) {
      if (u.name == "view_projection") job.uniforms[u.name] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
      for (size_t i = 0; i < 3; ++i) {
        double x = 0;
        if (part_value(u.name, u.scalar, "eye", v.eye[i], &x)) job.uniforms[u.name].push_back(x);
      }
    }
    jobs.push_back(std::move(job));
  }
  const std::vector<r::GraphicsResult> results = r::run_graphics_batch(backend, jobs);
  for (size_t k = 0; k < views.size(); ++k) {
    if (k >= results.size() || !results[k].ok) {
      out.error = results.empty() ? "no result" : results.back().error;
      return out;
    }
    const auto& rel = results[k].outputs.at("v_rel");
    const auto& up = results[k].outputs.at("v_up");
    for (size_t i = 0; i < views[k].points.size(); ++i) {
      ++out.samples;
      for (size_t c = 0; c < 3; ++c) {
        const double got = rel[i * 3 + c], want = views[k].rel[i][c];
        if (!std::isfinite(got) || !std::isfinite(up[i * 3 + c])) {
          ++out.not_finite;
          continue;
        }
        const double e = std::fabs(got - want);
        if (e > out.rel_max) {
          out.rel_max = e;
          const Point& p = views[k].points[i];
          char buf[256];
          std::snprintf(buf, sizeof buf, "lat=%.17g lon=%.17g h=%.17g component %zu: got %.9g, exact %.9g", p.lat, p.lon,
                        p.h, c, got, want);
          out.worst = buf;
        }
        out.up_max = std::max(out.up_max, std::fabs(up[i * 3 + c] - views[k].up[i][c]));
      }
    }
  }
  return out;
}

}  // namespace wgs84
