#version 450
// Counts, with an atomic counter, the samples whose double distance from a reference lies
// within a tolerance, and stores the distances (a typical reduction pre-pass).
layout(local_size_x = 64) in;
layout(binding = 0, offset = 0) uniform atomic_uint within_tolerance;
layout(std430, binding = 0) readonly buffer Points { dvec2 points[]; };
layout(std430, binding = 1) writeonly buffer Distances { double distances[]; };
uniform dvec2 reference;
uniform double tolerance;
void main() {
  uint i = gl_GlobalInvocationID.x;
  double d = distance(points[i], reference);
  distances[i] = d;
  if (d < tolerance) atomicCounterIncrement(within_tolerance);
}
