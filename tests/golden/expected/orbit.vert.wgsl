struct df_dvec3 {
  hi: vec3<f32>,
  lo: vec3<f32>,
}

struct df_double {
  hi: f32,
  lo: f32,
}

var<private> position_hi: vec3<f32>;
var<private> position_lo: vec3<f32>;
var<private> eye: df_dvec3;
var<private> color: vec3<f32>;
struct df_uniforms_t {
  eye_hi: vec3<f32>,  // offset 0
  eye_lo: vec3<f32>,  // offset 16
  view_projection: mat4x4<f32>,  // offset 32
  df_guard: f32,  // offset 96
}
@group(0) @binding(0) var<uniform> df_uniforms: df_uniforms_t;

fn df_neg(a: df_dvec3) -> df_dvec3 {
  var h: vec3<f32> = -(a.hi);
  var l: vec3<f32> = -(a.lo);
  return df_dvec3(h, l);
}

fn df_two_sum(a: vec3<f32>, b: vec3<f32>) -> df_dvec3 {
  var s: vec3<f32> = ((a + b) - df_uniforms.df_guard);
  var bb: vec3<f32> = ((s - a) - df_uniforms.df_guard);
  var ab: vec3<f32> = (s - bb);
  var da: vec3<f32> = (a - ab);
  var db: vec3<f32> = (b - bb);
  var e: vec3<f32> = (da + db);
  return df_dvec3(s, e);
}

fn df_fast_two_sum(a: vec3<f32>, b: vec3<f32>) -> df_dvec3 {
  var s: vec3<f32> = ((a + b) - df_uniforms.df_guard);
  var z: vec3<f32> = ((s - a) - df_uniforms.df_guard);
  var e: vec3<f32> = (b - z);
  return df_dvec3(s, e);
}

fn df_finish_df_double_float(z: df_double, f: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_finish_df_dvec3_vec3(z: df_dvec3, f: vec3<f32>) -> df_dvec3 {
  var r0: df_double = df_finish_df_double_float(df_double(z.hi[0i], z.lo[0i]), f[0i]);
  var r1: df_double = df_finish_df_double_float(df_double(z.hi[1i], z.lo[1i]), f[1i]);
  var r2: df_double = df_finish_df_double_float(df_double(z.hi[2i], z.lo[2i]), f[2i]);
  return df_dvec3(vec3<f32>(r0.hi, r1.hi, r2.hi), vec3<f32>(r0.lo, r1.lo, r2.lo));
}

fn df_add(a: df_dvec3, b: df_dvec3) -> df_dvec3 {
  var s: df_dvec3 = df_two_sum(a.hi, b.hi);
  var t: df_dvec3 = df_two_sum(a.lo, b.lo);
  var c: vec3<f32> = (s.lo + t.hi);
  var v: df_dvec3 = df_fast_two_sum(s.hi, c);
  var w: vec3<f32> = (t.lo + v.lo);
  var z: df_dvec3 = df_fast_two_sum(v.hi, w);
  var r: df_dvec3 = df_finish_df_dvec3_vec3(z, s.hi);
  return r;
}

fn df_sub(a: df_dvec3, b: df_dvec3) -> df_dvec3 {
  var nb: df_dvec3 = df_neg(b);
  var z: df_dvec3 = df_add(a, nb);
  return z;
}

fn df_abs(a: df_dvec3) -> df_dvec3 {
  var s: vec3<f32> = (sign(a.hi) - df_uniforms.df_guard);
  var h: vec3<f32> = (abs(a.hi) - df_uniforms.df_guard);
  var l: vec3<f32> = ((a.lo * s) - df_uniforms.df_guard);
  return df_dvec3(h, l);
}

fn df_to_float(a: df_dvec3) -> vec3<f32> {
  var f: vec3<f32> = ((a.hi + a.lo) - df_uniforms.df_guard);
  var r: df_dvec3 = df_finish_df_dvec3_vec3(df_dvec3(f, vec3<f32>(0.0f, 0.0f, 0.0f)), a.hi);
  return r.hi;
}

fn df_main() {
  eye = df_dvec3(df_uniforms.eye_hi, df_uniforms.eye_lo);
  var p: df_dvec3 = df_sub(df_two_sum(position_hi, position_lo), eye);
  color = df_to_float(df_abs(p));
  df_Position = (df_uniforms.view_projection * vec4<f32>(df_to_float(p), 1.0f));
}

var<private> df_Position: vec4<f32>;

struct df_stage_out {
  @builtin(position) gl_Position: vec4<f32>,
  @location(0) color: vec3<f32>,
}

@vertex
fn main(@location(0) df_in_position_hi: vec3<f32>, @location(1) df_in_position_lo: vec3<f32>) -> df_stage_out {
  position_hi = df_in_position_hi;
  position_lo = df_in_position_lo;
  df_main();
  return df_stage_out(df_Position, color);
}
