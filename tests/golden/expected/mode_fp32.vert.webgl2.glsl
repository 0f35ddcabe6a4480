#version 300 es
precision highp float;
precision highp int;

in vec3 position;
uniform vec3 eye;
uniform mat4 model;
uniform mat4 viewProj;
out float height;

float scaled(float x, int k);

float scaled(float x, int k)
{
  return x * 0.5 + float(k);
}

void main()
{
  vec3 world = (model * vec4(position, 1.0)).xyz;
  vec3 rel = world - eye;
  float h = scaled(length(world), 2);
  height = h - 6378137.0;
  gl_Position = viewProj * vec4(rel, 1.0);
}
