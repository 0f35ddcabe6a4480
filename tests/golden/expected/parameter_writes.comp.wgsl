struct df_dvec4 {
  hi: vec4<f32>,
  lo: vec4<f32>,
}

struct df_double {
  hi: f32,
  lo: f32,
}

struct df_dvec2 {
  hi: vec2<f32>,
  lo: vec2<f32>,
}

struct Data {
  v: array<df_dvec4>,
}

@group(0) @binding(0) var<storage, read_write> df_block_Data: Data;
var<private> scratch: df_double;
struct df_uniforms_t {
  df_guard: f32,  // offset 0
}
@group(0) @binding(1) var<uniform> df_uniforms: df_uniforms_t;

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
  var v_1: df_dvec2 = df_fast_two_sum(s.hi, c);
  var w: vec2<f32> = (t.lo + v_1.lo);
  var z: df_dvec2 = df_fast_two_sum(v_1.hi, w);
  var r: df_dvec2 = df_finish_df_dvec2_vec2(z, s.hi);
  return r;
}

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

fn df_mul(a: df_dvec2, b: df_dvec2) -> df_dvec2 {
  var c: df_dvec2 = df_two_prod(a.hi, b.hi);
  var tl: vec2<f32> = (a.hi * b.lo);
  var th: vec2<f32> = (a.lo * b.hi);
  var cl2: vec2<f32> = (th + tl);
  var cl3: vec2<f32> = (c.lo + cl2);
  var z: df_dvec2 = df_fast_two_sum(c.hi, cl3);
  var r: df_dvec2 = df_finish_df_dvec2_vec2(z, c.hi);
  return r;
}

fn df_mul_pow2(a: df_double, p: f32) -> df_double {
  var h: f32 = (a.hi * p);
  var l: f32 = (a.lo * p);
  var r: df_double = df_finish_df_double_float(df_double(h, l), h);
  return r;
}

fn df_splat_dvec2(s: df_double) -> df_dvec2 {
  return df_dvec2(vec2<f32>(s.hi), vec2<f32>(s.lo));
}

fn df_assign_dvec4_yz(v_1: ptr<function, df_dvec4>, x: df_dvec2) -> df_dvec2 {
  { let df_swz1 = x.hi; (*v_1).hi.y = df_swz1.x; (*v_1).hi.z = df_swz1.y; };
  { let df_swz2 = x.lo; (*v_1).lo.y = df_swz2.x; (*v_1).lo.z = df_swz2.y; };
  return x;
}

fn df_assign_dvec4_zw(v_1: ptr<function, df_dvec4>, x: df_dvec2) -> df_dvec2 {
  { let df_swz3 = x.hi; (*v_1).hi.z = df_swz3.x; (*v_1).hi.w = df_swz3.y; };
  { let df_swz4 = x.lo; (*v_1).lo.z = df_swz4.x; (*v_1).lo.w = df_swz4.y; };
  return x;
}

fn df_assign_dvec4_xy(v_1: ptr<function, df_dvec4>, x: df_dvec2) -> df_dvec2 {
  { let df_swz5 = x.hi; (*v_1).hi.x = df_swz5.x; (*v_1).hi.y = df_swz5.y; };
  { let df_swz6 = x.lo; (*v_1).lo.x = df_swz6.x; (*v_1).lo.y = df_swz6.y; };
  return x;
}

fn halve(x: ptr<function, df_double>) {
  (*x) = df_mul_pow2((*x), 0.5f);
}

fn bend(p: df_dvec4, q: df_double) -> df_dvec2 {
  var p_v: df_dvec4 = p;
  var q_v: df_double = q;
  _ = df_assign_dvec4_yz(&p_v, df_add(df_dvec2(p_v.hi.zy, p_v.lo.zy), df_splat_dvec2(q_v)));
  halve(&q_v);
  return df_mul(df_dvec2(p_v.hi.yz, p_v.lo.yz), df_splat_dvec2(q_v));
}

fn df_main() {
  var i: u32 = df_GlobalInvocationID[0i];
  var a: df_dvec4 = df_block_Data.v[i];
  _ = df_assign_dvec4_zw(&a, bend(a, df_double(a.hi[3i], a.lo[3i])));
  scratch = df_mul_pow2(df_double(a.hi[2i], a.lo[2i]), 2.0f);
  _ = df_assign_dvec4_xy(&a, df_add(df_splat_dvec2(scratch), df_dvec2(a.hi.xy, a.lo.xy)));
  df_block_Data.v[i] = a;
}

var<private> df_GlobalInvocationID: vec3<u32>;

@compute @workgroup_size(64, 1, 1)
fn main(@builtin(global_invocation_id) df_in_global_invocation_id: vec3<u32>) {
  df_GlobalInvocationID = df_in_global_invocation_id;
  df_main();
}
