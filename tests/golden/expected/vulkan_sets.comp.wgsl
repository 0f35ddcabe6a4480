struct df_dvec4 {
  hi: vec4<f32>,
  lo: vec4<f32>,
}

struct df_double {
  hi: f32,
  lo: f32,
}

struct Camera {
  origin: df_dvec4,
  @align(16) @size(16) scale: df_double,
}

@group(1) @binding(0) var<uniform> cam: Camera;
struct Points {
  p: array<df_dvec4>,
}

@group(0) @binding(0) var<storage, read> df_block_Points: Points;
struct Out {
  o: array<df_dvec4>,
}

@group(2) @binding(0) var<storage, read_write> df_block_Out: Out;
struct Extra {
  e: array<df_double>,
}

@group(2) @binding(1) var<storage, read_write> df_block_Extra: Extra;
var<private> bias: df_double;
struct df_uniforms_t {
  bias_hi: f32,  // offset 0
  bias_lo: f32,  // offset 4
  df_guard: f32,  // offset 8
}
@group(0) @binding(1) var<uniform> df_uniforms: df_uniforms_t;

fn df_neg(a: df_dvec4) -> df_dvec4 {
  var h: vec4<f32> = -(a.hi);
  var l: vec4<f32> = -(a.lo);
  return df_dvec4(h, l);
}

fn df_two_sum_vec4_vec4(a: vec4<f32>, b: vec4<f32>) -> df_dvec4 {
  var s: vec4<f32> = ((a + b) - df_uniforms.df_guard);
  var bb: vec4<f32> = ((s - a) - df_uniforms.df_guard);
  var ab: vec4<f32> = (s - bb);
  var da: vec4<f32> = (a - ab);
  var db: vec4<f32> = (b - bb);
  var e_1: vec4<f32> = (da + db);
  return df_dvec4(s, e_1);
}

fn df_fast_two_sum_vec4_vec4(a: vec4<f32>, b: vec4<f32>) -> df_dvec4 {
  var s: vec4<f32> = ((a + b) - df_uniforms.df_guard);
  var z: vec4<f32> = ((s - a) - df_uniforms.df_guard);
  var e_1: vec4<f32> = (b - z);
  return df_dvec4(s, e_1);
}

fn df_finish_df_double_float(z: df_double, f: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_finish_df_dvec4_vec4(z: df_dvec4, f: vec4<f32>) -> df_dvec4 {
  var r0: df_double = df_finish_df_double_float(df_double(z.hi[0i], z.lo[0i]), f[0i]);
  var r1: df_double = df_finish_df_double_float(df_double(z.hi[1i], z.lo[1i]), f[1i]);
  var r2: df_double = df_finish_df_double_float(df_double(z.hi[2i], z.lo[2i]), f[2i]);
  var r3: df_double = df_finish_df_double_float(df_double(z.hi[3i], z.lo[3i]), f[3i]);
  return df_dvec4(vec4<f32>(r0.hi, r1.hi, r2.hi, r3.hi), vec4<f32>(r0.lo, r1.lo, r2.lo, r3.lo));
}

fn df_add(a: df_dvec4, b: df_dvec4) -> df_dvec4 {
  var s: df_dvec4 = df_two_sum_vec4_vec4(a.hi, b.hi);
  var t: df_dvec4 = df_two_sum_vec4_vec4(a.lo, b.lo);
  var c: vec4<f32> = (s.lo + t.hi);
  var v: df_dvec4 = df_fast_two_sum_vec4_vec4(s.hi, c);
  var w: vec4<f32> = (t.lo + v.lo);
  var z: df_dvec4 = df_fast_two_sum_vec4_vec4(v.hi, w);
  var r: df_dvec4 = df_finish_df_dvec4_vec4(z, s.hi);
  return r;
}

fn df_sub(a: df_dvec4, b: df_dvec4) -> df_dvec4 {
  var nb: df_dvec4 = df_neg(b);
  var z: df_dvec4 = df_add(a, nb);
  return z;
}

fn df_split(a: vec4<f32>) -> df_dvec4 {
  var bits: vec4<u32> = bitcast<vec4<u32>>(a);
  var hi: vec4<f32> = bitcast<vec4<f32>>((min((bits + 2048u), (bits | vec4<u32>(2139092992u))) & vec4<u32>(4294963200u)));
  var lo: vec4<f32> = (a - hi);
  return df_dvec4(hi, lo);
}

fn df_mul12_error(sa: df_dvec4, sb: df_dvec4, p_1: vec4<f32>) -> vec4<f32> {
  var hh: vec4<f32> = (sa.hi * sb.hi);
  var hl: vec4<f32> = (sa.hi * sb.lo);
  var lh: vec4<f32> = (sa.lo * sb.hi);
  var ll: vec4<f32> = (sa.lo * sb.lo);
  var t1: vec4<f32> = (hh - p_1);
  var t2: vec4<f32> = (t1 + hl);
  var t3: vec4<f32> = (t2 + lh);
  var e_1: vec4<f32> = (t3 + ll);
  return e_1;
}

fn df_two_prod(a: vec4<f32>, b: vec4<f32>) -> df_dvec4 {
  var p_1: vec4<f32> = ((a * b) - df_uniforms.df_guard);
  var sa: df_dvec4 = df_split(a);
  var sb: df_dvec4 = df_split(b);
  var e_1: vec4<f32> = df_mul12_error(sa, sb, p_1);
  return df_dvec4(p_1, e_1);
}

fn df_mul(a: df_dvec4, b: df_dvec4) -> df_dvec4 {
  var c: df_dvec4 = df_two_prod(a.hi, b.hi);
  var tl: vec4<f32> = (a.hi * b.lo);
  var th: vec4<f32> = (a.lo * b.hi);
  var cl2: vec4<f32> = (th + tl);
  var cl3: vec4<f32> = (c.lo + cl2);
  var z: df_dvec4 = df_fast_two_sum_vec4_vec4(c.hi, cl3);
  var r: df_dvec4 = df_finish_df_dvec4_vec4(z, c.hi);
  return r;
}

fn df_two_sum_float_float(a: f32, b: f32) -> df_double {
  var s: f32 = ((a + b) - df_uniforms.df_guard);
  var bb: f32 = ((s - a) - df_uniforms.df_guard);
  var ab: f32 = (s - bb);
  var da: f32 = (a - ab);
  var db: f32 = (b - bb);
  var e_1: f32 = (da + db);
  return df_double(s, e_1);
}

fn df_fast_two_sum_float_float(a: f32, b: f32) -> df_double {
  var s: f32 = ((a + b) - df_uniforms.df_guard);
  var z: f32 = ((s - a) - df_uniforms.df_guard);
  var e_1: f32 = (b - z);
  return df_double(s, e_1);
}

fn df_add_f(a: df_double, b: f32) -> df_double {
  var s: df_double = df_two_sum_float_float(a.hi, b);
  var v: f32 = (a.lo + s.lo);
  var z: df_double = df_fast_two_sum_float_float(s.hi, v);
  var r: df_double = df_finish_df_double_float(z, s.hi);
  return r;
}

fn df_splat_dvec4(s: df_double) -> df_dvec4 {
  return df_dvec4(vec4<f32>(s.hi), vec4<f32>(s.lo));
}

fn df_main() {
  bias = df_double(df_uniforms.bias_hi, df_uniforms.bias_lo);
  var i: u32 = df_GlobalInvocationID[0i];
  df_block_Out.o[i] = df_add(df_mul(df_sub(df_block_Points.p[i], cam.origin), df_splat_dvec4(cam.scale)), df_splat_dvec4(bias));
  df_block_Extra.e[i] = df_add_f(df_block_Extra.e[i], 1.0f);
}

var<private> df_GlobalInvocationID: vec3<u32>;

@compute @workgroup_size(64, 1, 1)
fn main(@builtin(global_invocation_id) df_in_global_invocation_id: vec3<u32>) {
  df_GlobalInvocationID = df_in_global_invocation_id;
  df_main();
}
