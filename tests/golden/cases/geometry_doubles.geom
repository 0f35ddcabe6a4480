// targets: es310 es320 glsl330 glsl450
#version 450
// Geometry shaders: per-vertex input arrays of doubles arrive as hi/lo arrays and are joined at
// main's start; double outputs are split before every EmitVertex(), in whichever function it is
// called (src/lower/split_interfaces.cpp). es310 requires GL_EXT_geometry_shader.
layout(triangles) in;
layout(triangle_strip, max_vertices = 6) out;
in dvec3 world[];
in double weight[];
out vec3 v_color;
flat out dvec3 v_offset;
flat out double v_weight;
uniform dvec3 eye;
uniform double spread;

void emit_corner(int k, double scale) {
  dvec3 rel = (world[k] - eye) * scale;
  gl_Position = gl_in[k].gl_Position + vec4(vec3(rel), 0.0);
  v_offset = rel;
  v_weight = weight[k] * scale + double(gl_PrimitiveIDIn);
  v_color = vec3(float(k), float(scale), 0.5);
  EmitVertex();
}

void main() {
  for (int copy = 0; copy < 2; ++copy) {
    double scale = 1.0lf + double(copy) * spread;
    for (int k = 0; k < 3; ++k) emit_corner(k, scale);
    EndPrimitive();
  }
}
