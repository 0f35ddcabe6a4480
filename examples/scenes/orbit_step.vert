#version 300 es
// One semi-implicit Euler step of a satellite (docs/plan.md): every vertex is a satellite,
// position and velocity in double. A step moves a satellite metres at a radius of thousands of
// kilometres, where float positions are half a metre apart; orbit.scene.json asks for 1e-6 m.
layout(location = 0) in dvec3 position;  // metres, Earth-centred
layout(location = 1) in dvec3 velocity;  // metres per second
uniform double dt;                       // seconds
uniform double mu;                       // gravitational parameter, m^3/s^2
out dvec3 next_position;
out dvec3 next_velocity;

void main() {
  double r2 = dot(position, position);
  double k = mu / (r2 * sqrt(r2)) * dt;
  dvec3 v = velocity - position * k;
  dvec3 p = position + v * dt;
  next_position = p;
  next_velocity = v;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
