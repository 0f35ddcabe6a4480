// loop.comp by hand on luma.gl's WGSL fp64 arithmetic (@luma.gl/shadertools' fp64arithmetic module,
// tools/peers), each double a vec2f (hi, lo): the WebGPU peer of issue 23's speed benchmark
// (tools/browser/speed-suite.mjs --apis webgpu). Same operations in the same order as loop.comp and
// loop.luma.frag; 0.5 * dt and -mu are exact on a (hi, lo) pair. speed-suite.mjs has luma.gl's own
// WGSL assembler put the module before this text (its fp64arithmetic uniforms, ONE and SPLIT, at
// the binding that assembler picks). Every double uniform is a vec4f (hi, lo, -, -) in Params, in
// the order below, then count: the page packs it so.
struct Params {
  mu64: vec4f,  // (hi, lo, -, -)
  dt64: vec4f,  // (hi, lo, -, -)
  count: u32,   // elements
};
@group(0) @binding(0) var<storage, read> states: array<vec2f>;  // px py vx vy per element, (hi, lo) each
@group(0) @binding(1) var<storage, read_write> positions: array<vec2f>;  // px py per element
@group(0) @binding(2) var<uniform> params: Params;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
  let i = id.x;
  if (i >= params.count) {
    return;
  }
  let mu64 = params.mu64.xy;
  let dt64 = params.dt64.xy;
  var px = states[4u * i];
  var py = states[4u * i + 1u];
  var vx = states[4u * i + 2u];
  var vy = states[4u * i + 3u];
  for (var k = 0; k < 32; k++) {
    var r2 = sum_fp64(mul_fp64(px, px), mul_fp64(py, py));
    var r = sqrt_fp64(r2);
    var f = div_fp64(-mu64, mul_fp64(r2, r));
    var h = mul_fp64(dt64 * 0.5, f);
    vx = sum_fp64(vx, mul_fp64(h, px));
    vy = sum_fp64(vy, mul_fp64(h, py));
    px = sum_fp64(px, mul_fp64(dt64, vx));
    py = sum_fp64(py, mul_fp64(dt64, vy));
    r2 = sum_fp64(mul_fp64(px, px), mul_fp64(py, py));
    r = sqrt_fp64(r2);
    f = div_fp64(-mu64, mul_fp64(r2, r));
    h = mul_fp64(dt64 * 0.5, f);
    vx = sum_fp64(vx, mul_fp64(h, px));
    vy = sum_fp64(vy, mul_fp64(h, py));
  }
  positions[2u * i] = px;
  positions[2u * i + 1u] = py;
}
