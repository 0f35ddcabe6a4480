// straight.comp by hand on luma.gl's WGSL fp64 arithmetic (@luma.gl/shadertools' fp64arithmetic
// module, tools/peers), each double a vec2f (hi, lo): the WebGPU peer of issue 23's speed benchmark
// (tools/browser/speed-suite.mjs --apis webgpu). luma.gl 9.4.2 has no WGSL mat4_vec4_mul_fp64, so
// each row is the four products summed pairwise, ((m0 d0 + m1 d1) + (m2 d2 + m3 d3)), as its GLSL
// matrix helper does. speed-suite.mjs has luma.gl's own WGSL assembler put the module before this
// text (its fp64arithmetic uniforms, ONE and SPLIT, at the binding that assembler picks). Every
// double uniform is a vec4f (hi, lo, -, -) in Params, in the order below, then count: the page
// packs it so.
struct Params {
  eye64: array<vec4f, 3>,   // (hi, lo, -, -) per component
  mvp64: array<vec4f, 16>,  // (hi, lo, -, -) per entry, row after row
  count: u32,               // elements
};
@group(0) @binding(0) var<storage, read> positions: array<vec2f>;  // x y z per element, (hi, lo) each
@group(0) @binding(1) var<storage, read_write> clip: array<vec2f>;  // x y z w per element
@group(0) @binding(2) var<uniform> params: Params;

fn row(r: u32, d: array<vec2f, 4>) -> vec2f {
  let p0 = mul_fp64(params.mvp64[4u * r].xy, d[0]);
  let p1 = mul_fp64(params.mvp64[4u * r + 1u].xy, d[1]);
  let p2 = mul_fp64(params.mvp64[4u * r + 2u].xy, d[2]);
  let p3 = mul_fp64(params.mvp64[4u * r + 3u].xy, d[3]);
  return sum_fp64(sum_fp64(p0, p1), sum_fp64(p2, p3));
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= params.count) {
    return;
  }
  var d: array<vec2f, 4>;
  d[0] = sub_fp64(positions[3u * i], params.eye64[0].xy);
  d[1] = sub_fp64(positions[3u * i + 1u], params.eye64[1].xy);
  d[2] = sub_fp64(positions[3u * i + 2u], params.eye64[2].xy);
  d[3] = vec2f(1.0, 0.0);
  for (var r = 0u; r < 4u; r++) {
    clip[4u * i + r] = row(r, d);
  }
}
