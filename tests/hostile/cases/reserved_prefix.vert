#version 300 es
uniform double df_secret;
void main() { gl_Position = vec4(float(df_secret)); }
