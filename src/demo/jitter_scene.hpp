// The jitter demo's world, on the host in double: two small satellites 2.75 m apart on a
// geostationary orbit and a camera 10–50 m away moving slowly around them.
#pragma once

#include <array>
#include <vector>

namespace doublet::demo {

inline constexpr double kGeoRadius = 42164137.0;  // metres from the Earth's centre
inline constexpr double kSatelliteGap = 2.75;     // metres between the two boxes' centres

struct JitterGeometry {
  std::vector<double> positions;  // Earth-centred metres, 3 per vertex (triangle list)
  std::vector<float> colors;      // 3 per vertex
  int vertex_count() const { return static_cast<int>(positions.size() / 3); }
};
JitterGeometry jitter_geometry();

// Where the pair sits: its centre (Earth-centred metres) and the orbit's unit axes there.
struct JitterOrbit {
  std::array<double, 3> centre, radial, along_track, north;
};
JitterOrbit jitter_orbit();

struct JitterCamera {
  std::array<double, 3> eye;                // Earth-centred metres
  std::array<float, 16> view_projection;   // column-major; rotation and projection, no translation
};
// Frame `i` of `frames`: the camera's distance grows from 10 to 50 m while it circles the pair.
JitterCamera jitter_camera(int i, int frames, double aspect);

// The reference: the same transform as the shader, all in double (the matrix entries are the floats
// the shader gets). Returns gl_Position, 4 per vertex.
std::vector<double> reference_clip(const JitterGeometry&, const JitterCamera&);

}  // namespace doublet::demo
