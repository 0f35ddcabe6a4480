struct df_dvec2 {
  hi: vec2<f32>,
  lo: vec2<f32>,
}

struct df_double {
  hi: f32,
  lo: f32,
}

var<private> a: df_dvec2;
var<private> b: df_dvec2;
struct Result {
  result: vec2<f32>,
}

@group(0) @binding(0) var<storage, read_write> df_block_Result: Result;
struct df_uniforms_t {
  a_hi: vec2<f32>,  // offset 0
  a_lo: vec2<f32>,  // offset 8
  b_hi: vec2<f32>,  // offset 16
  b_lo: vec2<f32>,  // offset 24
  df_guard: f32,  // offset 32
}
@group(0) @binding(1) var<uniform> df_uniforms: df_uniforms_t;

fn df_two_sum(a_1: vec2<f32>, b_1: vec2<f32>) -> df_dvec2 {
  var s: vec2<f32> = ((a_1 + b_1) - df_uniforms.df_guard);
  var bb: vec2<f32> = ((s - a_1) - df_uniforms.df_guard);
  var ab: vec2<f32> = (s - bb);
  var da: vec2<f32> = (a_1 - ab);
  var db: vec2<f32> = (b_1 - bb);
  var e: vec2<f32> = (da + db);
  return df_dvec2(s, e);
}

fn df_fast_two_sum(a_1: vec2<f32>, b_1: vec2<f32>) -> df_dvec2 {
  var s: vec2<f32> = ((a_1 + b_1) - df_uniforms.df_guard);
  var z: vec2<f32> = ((s - a_1) - df_uniforms.df_guard);
  var e: vec2<f32> = (b_1 - z);
  return df_dvec2(s, e);
}

fn df_finish_df_double_float(z: df_double, f: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_finish_df_dvec2_vec2(z: df_dvec2, f: vec2<f32>) -> df_dvec2 {
  var r0: df_double = df_finish_df_double_float(df_double(z.hi[0i], z.lo[0i]), f[0i]);
  var r1: df_double = df_finish_df_double_float(df_double(z.hi[1i], z.lo[1i]), f[1i]);
  return df_dvec2(vec2<f32>(r0.hi, r1.hi), vec2<f32>(r0.lo, r1.lo));
}

fn df_add(a_1: df_dvec2, b_1: df_dvec2) -> df_dvec2 {
  var s: df_dvec2 = df_two_sum(a_1.hi, b_1.hi);
  var t: df_dvec2 = df_two_sum(a_1.lo, b_1.lo);
  var c: vec2<f32> = (s.lo + t.hi);
  var v: df_dvec2 = df_fast_two_sum(s.hi, c);
  var w: vec2<f32> = (t.lo + v.lo);
  var z: df_dvec2 = df_fast_two_sum(v.hi, w);
  var r: df_dvec2 = df_finish_df_dvec2_vec2(z, s.hi);
  return r;
}

fn df_to_float(a_1: df_dvec2) -> vec2<f32> {
  var f: vec2<f32> = ((a_1.hi + a_1.lo) - df_uniforms.df_guard);
  var r: df_dvec2 = df_finish_df_dvec2_vec2(df_dvec2(f, vec2<f32>(0.0f, 0.0f)), a_1.hi);
  return r.hi;
}

fn df_main() {
  a = df_dvec2(df_uniforms.a_hi, df_uniforms.a_lo);
  b = df_dvec2(df_uniforms.b_hi, df_uniforms.b_lo);
  df_block_Result.result = df_to_float(df_add(a, b));
}


@compute @workgroup_size(1, 1, 1)
fn main() {
  df_main();
}
