fn df_float_frexp(x: f32, exp: ptr<function, i32>) -> f32 {
  let r = frexp(x);
  *exp = r.exp;
  return r.fract;
}

fn df_float_modf(x: f32, whole: ptr<function, f32>) -> f32 {
  let r = modf(x);
  *whole = r.whole;
  return r.fract;
}

struct df_double {
  hi: f32,
  lo: f32,
}

struct B {
  v: array<df_double>,
}

@group(0) @binding(0) var<storage, read_write> df_block_B: B;
struct F {
  whole: array<f32>,
}

@group(0) @binding(1) var<storage, read_write> df_block_F: F;
struct E {
  ex: array<i32>,
}

@group(0) @binding(2) var<storage, read_write> df_block_E: E;
struct R {
  r: array<vec2<f32>>,
}

@group(0) @binding(3) var<storage, read_write> df_block_R: R;
struct df_uniforms_t {
  df_guard: f32,  // offset 0
}
@group(0) @binding(4) var<uniform> df_uniforms: df_uniforms_t;

fn df_finish(z: df_double, f: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_to_float(a: df_double) -> f32 {
  var f: f32 = ((a.hi + a.lo) - df_uniforms.df_guard);
  var r_1: df_double = df_finish(df_double(f, 0.0f), a.hi);
  return r_1.hi;
}

fn df_mul_pow2(a: df_double, p: f32) -> df_double {
  var h: f32 = (a.hi * p);
  var l: f32 = (a.lo * p);
  var r_1: df_double = df_finish(df_double(h, l), h);
  return r_1;
}

fn df_main() {
  var df_arg1: f32;
  var df_arg3: i32;
  var i: u32 = df_GlobalInvocationID[0i];
  var x: f32 = (df_to_float(df_block_B.v[i]) * 7.25f);
  var df_arg2: f32 = df_float_modf(x, &df_arg1);
  df_block_F.whole[i] = df_arg1;
  var fr: f32 = df_arg2;
  var df_arg4: f32 = df_float_frexp((x * 3.0f), &df_arg3);
  df_block_E.ex[i] = df_arg3;
  df_block_R.r[i] = vec2<f32>((fr + df_arg4), df_to_float(df_mul_pow2(df_block_B.v[i], 2.0f)));
}

var<private> df_GlobalInvocationID: vec3<u32>;

@compute @workgroup_size(64, 1, 1)
fn main(@builtin(global_invocation_id) df_in_global_invocation_id: vec3<u32>) {
  df_GlobalInvocationID = df_in_global_invocation_id;
  df_main();
}
