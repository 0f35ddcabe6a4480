#version 450
// Planet terrain LOD, control stage: each patch corner arrives in earth-centred metres; the
// invocation for corner 0 computes the patch's centre and its distance to the eye once, per patch
// (patch outputs any invocation may write), and every invocation reads them after barrier() to pick
// the tessellation levels. Each corner's position relative to the patch centre goes on per vertex.
layout(vertices = 3) out;
in dvec3 v_ecef[];
out dvec3 c_offset[];
patch out dvec3 p_center;
patch out double p_distance;
uniform dvec3 u_eye;
uniform double u_lod_distance;

void main() {
  if (gl_InvocationID == 0) {
    p_center = (v_ecef[0] + v_ecef[1] + v_ecef[2]) / 3.0lf;
    p_distance = distance(p_center, u_eye);
  }
  barrier();
  c_offset[gl_InvocationID] = v_ecef[gl_InvocationID] - p_center;
  float level = float(clamp(u_lod_distance / p_distance, 1.0lf, 64.0lf));
  gl_TessLevelOuter[gl_InvocationID] = level;
  if (gl_InvocationID == 0) gl_TessLevelInner[0] = level;
}
