#version 450
// A uniform block with doubles, as a viewer declares its camera: filled from the spec in both
// runs (std140 doubles natively, the lowered block's hi/lo places from the manifest).
uniform Camera {
  dmat4 view_projection;
  dvec3 origin;
  double scale;
};
in dvec3 position;
out dvec4 clip;
void main() {
  dvec4 p = view_projection * dvec4(origin + position * scale, 1.0lf);
  clip = p;
  gl_Position = vec4(p);
}
