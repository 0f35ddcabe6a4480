struct df_dvec2 {
  hi: vec2<f32>,
  lo: vec2<f32>,
}

struct df_double {
  hi: f32,
  lo: f32,
}

struct Offsets {
  offsets: array<df_dvec2>,
}

@group(0) @binding(0) var<storage, read> df_block_Offsets: Offsets;
var<private> origin: df_dvec2;
struct df_uniforms_t {
  origin_hi: vec2<f32>,  // offset 0
  origin_lo: vec2<f32>,  // offset 8
  df_guard: f32,  // offset 16
}
@group(0) @binding(1) var<uniform> df_uniforms: df_uniforms_t;

fn df_neg(a: df_dvec2) -> df_dvec2 {
  var h: vec2<f32> = -(a.hi);
  var l: vec2<f32> = -(a.lo);
  return df_dvec2(h, l);
}

fn df_two_sum(a: vec2<f32>, b: vec2<f32>) -> df_dvec2 {
  var s: vec2<f32> = ((a + b) - df_uniforms.df_guard);
  var bb: vec2<f32> = ((s - a) - df_uniforms.df_guard);
  var ab: vec2<f32> = (s - bb);
  var da: vec2<f32> = (a - ab);
  var db: vec2<f32> = (b - bb);
  var e: vec2<f32> = (da + db);
  return df_dvec2(s, e);
}

fn df_fast_two_sum(a: vec2<f32>, b: vec2<f32>) -> df_dvec2 {
  var s: vec2<f32> = ((a + b) - df_uniforms.df_guard);
  var z: vec2<f32> = ((s - a) - df_uniforms.df_guard);
  var e: vec2<f32> = (b - z);
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

fn df_add(a: df_dvec2, b: df_dvec2) -> df_dvec2 {
  var s: df_dvec2 = df_two_sum(a.hi, b.hi);
  var t: df_dvec2 = df_two_sum(a.lo, b.lo);
  var c: vec2<f32> = (s.lo + t.hi);
  var v: df_dvec2 = df_fast_two_sum(s.hi, c);
  var w: vec2<f32> = (t.lo + v.lo);
  var z: df_dvec2 = df_fast_two_sum(v.hi, w);
  var r: df_dvec2 = df_finish_df_dvec2_vec2(z, s.hi);
  return r;
}

fn df_sub(a: df_dvec2, b: df_dvec2) -> df_dvec2 {
  var nb: df_dvec2 = df_neg(b);
  var z: df_dvec2 = df_add(a, nb);
  return z;
}

fn df_to_float(a: df_dvec2) -> vec2<f32> {
  var f: vec2<f32> = ((a.hi + a.lo) - df_uniforms.df_guard);
  var r: df_dvec2 = df_finish_df_dvec2_vec2(df_dvec2(f, vec2<f32>(0.0f, 0.0f)), a.hi);
  return r.hi;
}

fn df_main() {
  origin = df_dvec2(df_uniforms.origin_hi, df_uniforms.origin_lo);
  var p: df_dvec2 = df_sub(df_block_Offsets.offsets[df_InstanceID], origin);
  var corner: f32 = f32((df_VertexID & 1i));
  df_Position = vec4<f32>((df_to_float(p) + corner), 0.0f, 1.0f);
}

var<private> df_VertexID: i32;
var<private> df_InstanceID: i32;
var<private> df_Position: vec4<f32>;

struct df_stage_out {
  @builtin(position) gl_Position: vec4<f32>,
}

@vertex
fn main(@builtin(vertex_index) df_in_vertex_index: u32, @builtin(instance_index) df_in_instance_index: u32) -> df_stage_out {
  df_VertexID = i32(df_in_vertex_index);
  df_InstanceID = i32(df_in_instance_index);
  df_main();
  return df_stage_out(df_Position);
}
