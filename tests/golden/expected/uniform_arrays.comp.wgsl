struct df_double {
  hi: f32,
  lo: f32,
}

struct df_dvec2 {
  hi: vec2<f32>,
  lo: vec2<f32>,
}

var<private> d: array<df_double, 3>;
var<private> w: array<df_dvec2, 2>;
struct Data {
  x: array<df_dvec2>,
}

@group(0) @binding(0) var<storage, read_write> df_block_Data: Data;
struct Results {
  r: array<df_dvec2>,
}

@group(0) @binding(1) var<storage, read_write> df_block_Results: Results;
struct df_uniforms_t {
  @align(16) d_hi: array<vec4<f32>, 3>,  // offset 0
  @align(16) d_lo: array<vec4<f32>, 3>,  // offset 48
  @align(16) w_hi: array<vec4<f32>, 2>,  // offset 96
  @align(16) w_lo: array<vec4<f32>, 2>,  // offset 128
  @align(16) f: array<vec4<f32>, 2>,  // offset 160
  df_guard: f32,  // offset 192
}
@group(0) @binding(2) var<uniform> df_uniforms: df_uniforms_t;

fn df_split(a: vec2<f32>) -> df_dvec2 {
  var bits: vec2<u32> = bitcast<vec2<u32>>(a);
  var hi: vec2<f32> = bitcast<vec2<f32>>((min((bits + 2048u), (bits | vec2<u32>(2139092992u))) & vec2<u32>(4294963200u)));
  var lo: vec2<f32> = (a - hi);
  return df_dvec2(hi, lo);
}

fn df_mul12_error(sa: df_dvec2, sb: df_dvec2, p: vec2<f32>) -> vec2<f32> {
  var hh: vec2<f32> = (sa.hi * sb.hi);
  var hl: vec2<f32> = (sa.hi * sb.lo);
  var lh: vec2<f32> = (sa.lo * sb.hi);
  var ll: vec2<f32> = (sa.lo * sb.lo);
  var t1: vec2<f32> = (hh - p);
  var t2: vec2<f32> = (t1 + hl);
  var t3: vec2<f32> = (t2 + lh);
  var e: vec2<f32> = (t3 + ll);
  return e;
}

fn df_two_prod(a: vec2<f32>, b: vec2<f32>) -> df_dvec2 {
  var p: vec2<f32> = ((a * b) - df_uniforms.df_guard);
  var sa: df_dvec2 = df_split(a);
  var sb: df_dvec2 = df_split(b);
  var e: vec2<f32> = df_mul12_error(sa, sb, p);
  return df_dvec2(p, e);
}

fn df_fast_two_sum(a: vec2<f32>, b: vec2<f32>) -> df_dvec2 {
  var s: vec2<f32> = ((a + b) - df_uniforms.df_guard);
  var z: vec2<f32> = ((s - a) - df_uniforms.df_guard);
  var e: vec2<f32> = (b - z);
  return df_dvec2(s, e);
}

fn df_finish_df_double_float(z: df_double, f_1: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f_1, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_finish_df_dvec2_vec2(z: df_dvec2, f_1: vec2<f32>) -> df_dvec2 {
  var r0: df_double = df_finish_df_double_float(df_double(z.hi[0i], z.lo[0i]), f_1[0i]);
  var r1: df_double = df_finish_df_double_float(df_double(z.hi[1i], z.lo[1i]), f_1[1i]);
  return df_dvec2(vec2<f32>(r0.hi, r1.hi), vec2<f32>(r0.lo, r1.lo));
}

fn df_mul(a: df_dvec2, b: df_dvec2) -> df_dvec2 {
  var c: df_dvec2 = df_two_prod(a.hi, b.hi);
  var tl: vec2<f32> = (a.hi * b.lo);
  var th: vec2<f32> = (a.lo * b.hi);
  var cl2: vec2<f32> = (th + tl);
  var cl3: vec2<f32> = (c.lo + cl2);
  var z: df_dvec2 = df_fast_two_sum(c.hi, cl3);
  var r_1: df_dvec2 = df_finish_df_dvec2_vec2(z, c.hi);
  return r_1;
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

fn df_add(a: df_dvec2, b: df_dvec2) -> df_dvec2 {
  var s: df_dvec2 = df_two_sum(a.hi, b.hi);
  var t: df_dvec2 = df_two_sum(a.lo, b.lo);
  var c: vec2<f32> = (s.lo + t.hi);
  var v: df_dvec2 = df_fast_two_sum(s.hi, c);
  var w_1: vec2<f32> = (t.lo + v.lo);
  var z: df_dvec2 = df_fast_two_sum(v.hi, w_1);
  var r_1: df_dvec2 = df_finish_df_dvec2_vec2(z, s.hi);
  return r_1;
}

fn df_mul_f2(a: df_dvec2, b: vec2<f32>) -> df_dvec2 {
  var c: df_dvec2 = df_two_prod(a.hi, b);
  var cl2: vec2<f32> = (a.lo * b);
  var cl3: vec2<f32> = (c.lo + cl2);
  var z: df_dvec2 = df_fast_two_sum(c.hi, cl3);
  var r_1: df_dvec2 = df_finish_df_dvec2_vec2(z, c.hi);
  return r_1;
}

fn df_splat_dvec2(s: df_double) -> df_dvec2 {
  return df_dvec2(vec2<f32>(s.hi), vec2<f32>(s.lo));
}

fn df_main() {
  d[0i] = df_double(df_uniforms.d_hi[0i].x, df_uniforms.d_lo[0i].x);
  d[1i] = df_double(df_uniforms.d_hi[1i].x, df_uniforms.d_lo[1i].x);
  d[2i] = df_double(df_uniforms.d_hi[2i].x, df_uniforms.d_lo[2i].x);
  w[0i] = df_dvec2(df_uniforms.w_hi[0i].xy, df_uniforms.w_lo[0i].xy);
  w[1i] = df_dvec2(df_uniforms.w_hi[1i].xy, df_uniforms.w_lo[1i].xy);
  var i: u32 = df_GlobalInvocationID[0i];
  df_block_Results.r[i] = df_add(df_add(df_mul(df_block_Data.x[i], df_splat_dvec2(d[(i % 3u)])), df_mul_f2(w[(i % 2u)], vec2<f32>(df_uniforms.f[1i].x))), df_splat_dvec2(d[0i]));
}

var<private> df_GlobalInvocationID: vec3<u32>;

@compute @workgroup_size(16, 1, 1)
fn main(@builtin(global_invocation_id) df_in_global_invocation_id: vec3<u32>) {
  df_GlobalInvocationID = df_in_global_invocation_id;
  df_main();
}
