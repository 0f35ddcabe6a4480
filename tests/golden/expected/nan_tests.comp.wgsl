fn df_select_df_double(f: df_double, t: df_double, c: bool) -> df_double {
  if c {
    return t;
  }
  return f;
}

fn df_float_isinf(x: f32) -> bool {
  let m = bitcast<u32>(x) & u32(0x7fffffffu);
  return m == u32(0x7f800000u);
}

fn df_float_isnan(x: f32) -> bool {
  let m = bitcast<u32>(x) & u32(0x7fffffffu);
  return m > u32(0x7f800000u);
}

struct df_double {
  hi: f32,
  lo: f32,
}

struct Data {
  x: array<df_double, 64>,
  f: array<f32>,
}

@group(0) @binding(0) var<storage, read_write> df_block_Data: Data;
struct df_uniforms_t {
  df_guard: f32,  // offset 0
}
@group(0) @binding(1) var<uniform> df_uniforms: df_uniforms_t;

fn df_isnan(a: df_double) -> bool {
  return df_float_isnan(a.hi);
}

fn df_isinf(a: df_double) -> bool {
  return df_float_isinf(a.hi);
}

fn df_from_bool(b: bool) -> df_double {
  var f_1: f32 = (f32(b) - df_uniforms.df_guard);
  return df_double(f_1, 0.0f);
}

fn df_two_sum(a: f32, b: f32) -> df_double {
  var s: f32 = ((a + b) - df_uniforms.df_guard);
  var bb: f32 = ((s - a) - df_uniforms.df_guard);
  var ab: f32 = (s - bb);
  var da: f32 = (a - ab);
  var db: f32 = (b - bb);
  var e: f32 = (da + db);
  return df_double(s, e);
}

fn df_fast_two_sum(a: f32, b: f32) -> df_double {
  var s: f32 = ((a + b) - df_uniforms.df_guard);
  var z: f32 = ((s - a) - df_uniforms.df_guard);
  var e: f32 = (b - z);
  return df_double(s, e);
}

fn df_finish(z: df_double, f_1: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f_1, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_add(a: df_double, b: df_double) -> df_double {
  var s: df_double = df_two_sum(a.hi, b.hi);
  var t: df_double = df_two_sum(a.lo, b.lo);
  var c: f32 = (s.lo + t.hi);
  var v: df_double = df_fast_two_sum(s.hi, c);
  var w: f32 = (t.lo + v.lo);
  var z: df_double = df_fast_two_sum(v.hi, w);
  var r: df_double = df_finish(z, s.hi);
  return r;
}

fn df_main() {
  var i: u32 = df_GlobalInvocationID[0i];
  var odd: bool = (df_isnan(df_block_Data.x[i]) || df_isinf(df_block_Data.x[i]));
  var single: bool = (df_float_isnan(df_block_Data.f[i]) || df_float_isinf(df_block_Data.f[i]));
  df_block_Data.x[i] = df_select_df_double(df_add(df_block_Data.x[i], df_from_bool(single)), df_double((0.0f + df_uniforms.df_guard), (0.0f + df_uniforms.df_guard)), odd);
}

var<private> df_GlobalInvocationID: vec3<u32>;

@compute @workgroup_size(64, 1, 1)
fn main(@builtin(global_invocation_id) df_in_global_invocation_id: vec3<u32>) {
  df_GlobalInvocationID = df_in_global_invocation_id;
  df_main();
}
