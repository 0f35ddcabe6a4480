// targets: es300 webgl2
// options: --mode df64-int
#version 450
// Mode df64-int runs its matrix products in loops, one df_dot per row (m * v) or column (v * m, and
// m * n column by column): its integer residuals make every product long, so drivers compile one
// copy instead of four. The operations and their order are df64's (docs/performance.md).
uniform dmat4 u_model;
uniform dmat4 u_view;
uniform dmat3x4 u_normal;
in dvec4 a_position;
flat out dvec4 v_model;
flat out dvec4 v_row;
flat out dvec4 v_view_model;
flat out dvec3 v_normal;
void main() {
  v_model = u_model * a_position;
  v_row = a_position * u_model;
  v_view_model = (u_view * u_model)[2];
  v_normal = a_position * u_normal;
  gl_Position = vec4(u_view * v_model);
}
