// Geometry, camera path and the host-double reference transform of the jitter demo.
#include "demo/jitter_scene.hpp"

#include <cmath>

namespace doublet::demo {
namespace {

using Vec = std::array<double, 3>;

Vec add(Vec a, Vec b, double s = 1) { return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]}; }
Vec scale(Vec a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec cross(Vec a, Vec b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
Vec normalize(Vec a) { return scale(a, 1 / std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])); }

// An orbit angle that puts the satellites where floats are 4 m (x) and 2 m (y) apart.
constexpr double kOrbitAngle = 0.7;
const Vec kCentre = {kGeoRadius * std::cos(kOrbitAngle), kGeoRadius * std::sin(kOrbitAngle), 0.0};
const Vec kRadial = {std::cos(kOrbitAngle), std::sin(kOrbitAngle), 0.0};
const Vec kAlongTrack = {-std::sin(kOrbitAngle), std::cos(kOrbitAngle), 0.0};
const Vec kNorth = {0.0, 0.0, 1.0};

void add_box(JitterGeometry& g, Vec centre, double half, std::array<float, 3> base) {
  const Vec axes[3] = {kAlongTrack, kRadial, kNorth};
  // Each face: its normal axis and sign; two triangles over the other two axes.
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = -1; sign <= 1; sign += 2) {
      const Vec n = scale(axes[axis], sign * half);
      const Vec u = scale(axes[(axis + 1) % 3], half), v = scale(axes[(axis + 2) % 3], half);
      const float shade = 0.55f + 0.15f * static_cast<float>(axis) + (sign > 0 ? 0.15f : 0.0f);
      const double corners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
      for (const auto& c : corners) {
        const Vec p = add(add(add(centre, n), u, c[0]), v, c[1]);
        g.positions.insert(g.positions.end(), p.begin(), p.end());
        for (float b : base) g.colors.push_back(b * shade);
      }
    }
}

}  // namespace

JitterGeometry jitter_geometry() {
  JitterGeometry g;
  add_box(g, add(kCentre, kAlongTrack, -kSatelliteGap / 2), 0.6, {1.0f, 0.78f, 0.25f});  // gold
  add_box(g, add(kCentre, kAlongTrack, kSatelliteGap / 2), 0.6, {0.45f, 0.75f, 1.0f});   // blue
  return g;
}

JitterOrbit jitter_orbit() { return {kCentre, kRadial, kAlongTrack, kNorth}; }

JitterCamera jitter_camera(int i, int frames, double aspect) {
  const double s = frames > 1 ? static_cast<double>(i) / (frames - 1) : 0.0;
  const double distance = 10.0 + 40.0 * s;
  const double azimuth = 0.35 + 0.5 * s, elevation = 0.3;
  const Vec dir = add(add(scale(kRadial, -std::cos(azimuth) * std::cos(elevation)),
                          kAlongTrack, std::sin(azimuth) * std::cos(elevation)),
                      kNorth, std::sin(elevation));
  JitterCamera cam;
  cam.eye = add(kCentre, dir, distance);
  // Look at the pair's centre: rows of the rotation are right, up, -forward.
  const Vec forward = scale(dir, -1.0);
  const Vec right = normalize(cross(forward, kNorth));
  const Vec up = cross(right, forward);
  // Vertical field of view 30°, near 0.5 m, far 500 m.
  const double f = 1 / std::tan(15.0 * M_PI / 180), n = 0.5, fa = 500.0;
  const double a = (fa + n) / (n - fa), b = 2 * fa * n / (n - fa);
  double m[4][4] = {};  // m[column][row]
  for (int c = 0; c < 3; ++c) {
    m[c][0] = f / aspect * right[c];
    m[c][1] = f * up[c];
    m[c][2] = a * -forward[c];
    m[c][3] = forward[c];  // w = -z_view = distance along forward
  }
  m[3][2] = b;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) cam.view_projection[c * 4 + r] = static_cast<float>(m[c][r]);
  return cam;
}

std::vector<double> reference_clip(const JitterGeometry& g, const JitterCamera& cam) {
  std::vector<double> clip;
  clip.reserve(static_cast<size_t>(g.vertex_count()) * 4);
  for (int v = 0; v < g.vertex_count(); ++v) {
    const double rel[4] = {g.positions[v * 3] - cam.eye[0], g.positions[v * 3 + 1] - cam.eye[1],
                           g.positions[v * 3 + 2] - cam.eye[2], 1.0};
    for (int r = 0; r < 4; ++r) {
      double sum = 0;
      for (int c = 0; c < 4; ++c) sum += static_cast<double>(cam.view_projection[c * 4 + r]) * rel[c];
      clip.push_back(sum);
    }
  }
  return clip;
}

}  // namespace doublet::demo
